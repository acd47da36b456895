// v0: a shallow root holding its mode objects as members, of which it selects one; the current
// and previous mode pointers may point at any of them (an unselected member, an element of an
// unselected array member). The pointers are saved as references by path; the unselected
// members' values are not saved. The current-mode pointer is declared never to own a heap
// object (the macro form), so no mode class is described as a heap object's class.
#include <cstring>
#include <vector>

#include "check.hpp"

struct Mode {
  virtual ~Mode() {}
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};
struct ModeRTL : Mode {
  int number() const override { return 6; }
  int stage = 0;
};
struct ModeLand : Mode {
  int number() const override { return 9; }
};

struct Vehicle {
  int ticks = 0;
  ModeAuto mode_auto SYMCR_INCLUDE;
  ModeLoiter mode_loiter;
  ModeRTL rtl_modes[2];
  ModeLand mode_land;
  Mode* flightmode SYMCR_INCLUDE SYMCR_NOT_OWNER = &mode_auto;
  Mode* previous SYMCR_INCLUDE SYMCR_NOT_OWNER = nullptr;
  Mode* last_failsafe SYMCR_INCLUDE SYMCR_NOT_OWNER = nullptr;
};

SYMCR_CHECKPOINT_SHALLOW Vehicle vehicle;

int main(int argc, char** argv) {
  vehicle.ticks = 42;
  vehicle.mode_auto.next_waypoint = 4;
  vehicle.mode_loiter.radius_m = 7.5f;  // not selected: not saved
  vehicle.rtl_modes[1].stage = 2;       // likewise
  vehicle.previous = &vehicle.rtl_modes[1];
  vehicle.last_failsafe = &vehicle.mode_land;

  // A never-owning pointer at a heap object: saving refuses it, naming the member.
  ModeLoiter* loose = new ModeLoiter;
  vehicle.flightmode = loose;
  std::vector<std::uint8_t> bytes;
  const symcr::Status refused = symcr::checkpoint_to_buffer(*symcr_program_schema(), bytes);
  XV_CHECK(refused.error() == symcr::Error::Unsupported);
  XV_CHECK(std::strstr(refused.message(), "vehicle.flightmode") != nullptr);
  XV_CHECK(std::strstr(refused.message(), "never to own a heap object") != nullptr);
  delete loose;

  vehicle.flightmode = &vehicle.mode_loiter;
  if (xv::failures() != 0) return xv::verdict();
  return xv::save(argc, argv);
}
