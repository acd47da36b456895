// v0 of other_program: another program (a rover, named so by its build) whose root happens to
// have the same name and shape as the copter's.
#include "check.hpp"

struct State {
  int mode;
  double speed;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state.mode = 7;
  state.speed = 2.5;
  return xv::save(argc, argv);
}
