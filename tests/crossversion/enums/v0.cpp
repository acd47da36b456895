// v0: enums with their original numbering.
#include "check.hpp"

enum class Mode : unsigned char { Idle, Auto, Land, Acro };
enum Phase { TAKEOFF, CRUISE, DESCENT };

struct Flight {
  Mode mode;
  Phase phase;
  Mode vanished;
};

SYMCR_CHECKPOINT Flight flight;

int main(int argc, char** argv) {
  flight = {Mode::Land, CRUISE, Mode::Acro};
  return xv::save(argc, argv);
}
