// v1 of unnamed_enums: every enumerator renumbered; values come back by name.
#include "check.hpp"

typedef enum { LINK_BAD = 10, LINK_OK = 11, LINK_NONE = 12 } link_status_t;
typedef enum { MODE_RUN = 20, MODE_IDLE = 21 } run_mode_t;

struct State {
  link_status_t link;
  run_mode_t mode;
  enum { GEAR_DOWN = 30, GEAR_UP = 31 } gear;
  enum { LIGHT_ON = 40, LIGHT_OFF = 41 } light;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(state.link == LINK_BAD);
  XV_CHECK(state.mode == MODE_RUN);
  XV_CHECK(state.gear == State::GEAR_DOWN);
  XV_CHECK(state.light == State::LIGHT_ON);
  return xv::verdict();
}
