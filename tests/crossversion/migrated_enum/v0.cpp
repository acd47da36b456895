// v0: a navigator in mode Return, with a mode history. v1 replaces Return by Rtl and its hook
// maps the removed enumerator onto the new one.
#include <vector>

#include "check.hpp"

enum class Mode { Manual, Auto, Return };

struct Leg {
  Mode mode;
  int seconds;
};

struct Navigator {
  Mode mode;
  int waypoint;
  Leg last;                 // Leg has no hook: its values go to Navigator's
  std::vector<Mode> history;
  Leg spare;                // v1: an int (its seconds), a kind change
};

SYMCR_CHECKPOINT Navigator nav;

int main(int argc, char** argv) {
  nav = Navigator{Mode::Return, 4, Leg{Mode::Return, 30}, {Mode::Auto, Mode::Return},
                 Leg{Mode::Manual, 12}};
  return xv::save(argc, argv);
}
