// v1: heading became a struct and home an int: both incompatible (struct <-> int).
#include "check.hpp"

struct Heading {
  int degrees;
};

struct State {
  Heading heading{-1};
  int home = -2;
  int kept;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state = State{};
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(state.heading.degrees == -1);
  XV_CHECK(state.home == -2);
  XV_CHECK(state.kept == 12);
  XV_CHECK(xv::decided(report, "state.heading", symcr::Decision::Rejected));
  XV_CHECK(xv::decided(report, "state.home", symcr::Decision::Rejected));
  return xv::verdict();
}
