// v0: a first program's state. v1 makes an int of `speed` (12.5 does not fit), drops the
// enumerator Sport (the value checkpointed) and renames `heading` to `yaw` without annotating it.
#include "check.hpp"

enum class Mode { Manual, Auto, Sport };

struct Vehicle {
  int id;
  double speed;
  Mode mode;
  float heading;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  vehicle = Vehicle{7, 12.5, Mode::Sport, 90.0f};
  return xv::save(argc, argv);
}
