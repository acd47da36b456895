// v0: a vehicle class with what a new build re-creates by itself: const members, a reference
// bound in the constructor, callbacks (function and member-function pointers). None of it
// needs an annotation, and none of it is saved.
#include <cstdint>

#include "check.hpp"

int ticks_v0 = 0;
void arm_handler_v0() {}

struct Copter {
  Copter() : ticks(ticks_v0) {}
  const std::uint8_t num_flight_modes = 6;
  const int limits[2] = {1, 2};
  int mode = 0;
  int& ticks;
  void (*on_arm)() = &arm_handler_v0;
  void (Copter::*on_update)() = &Copter::update;
  std::uint16_t startup_delay_ms = 1000;  // const in v1
  void update() {}
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  copter.mode = 5;
  copter.startup_delay_ms = 1500;
  return xv::save(argc, argv);
}
