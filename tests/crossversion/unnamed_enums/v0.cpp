// v0: the C header idiom `typedef enum {...} name_t;`, twice in one translation unit, and an
// enum with no name at all. Each gets a name of its own (the typedef's, or its first
// enumerator's), so none collide.
#include "check.hpp"

typedef enum { LINK_NONE = 0, LINK_OK = 1, LINK_BAD = 2 } link_status_t;
typedef enum { MODE_IDLE = 0, MODE_RUN = 1 } run_mode_t;

struct State {
  link_status_t link;
  run_mode_t mode;
  enum { GEAR_UP, GEAR_DOWN } gear;
  enum { LIGHT_OFF, LIGHT_ON } light;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state.link = LINK_BAD;
  state.mode = MODE_RUN;
  state.gear = State::GEAR_DOWN;
  state.light = State::LIGHT_ON;
  return xv::save(argc, argv);
}
