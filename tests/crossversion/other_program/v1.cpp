// v1 of other_program: the copter, a different program, refuses the rover's checkpoint and
// keeps its own state; told to accept it, it restores it.
#include <cstring>

#include "check.hpp"

struct State {
  int mode;
  double speed;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state.mode = 1;
  state.speed = 0;
  const symcr::Report refused = xv::restore(argc, argv);
  XV_CHECK(!refused.ok());
  XV_CHECK(refused.status().error() == symcr::Error::Incompatible);
  XV_CHECK(std::strstr(refused.status().message(), "another program") != nullptr);
  XV_CHECK(state.mode == 1 && state.speed == 0);

  symcr::RestoreOptions options;
  options.accept_other_program = true;
  const symcr::Report accepted = symcr::restore(argv[1], options);
  XV_CHECK(accepted.ok());
  XV_CHECK(state.mode == 7 && state.speed == 2.5);
  return xv::verdict();
}
