// v1: the same state annotated with macros (plus one pragma), Log::lines renamed to count.
#include <functional>

#include "check.hpp"

namespace {
struct Counter {
  int hits;
};
SYMCR_CHECKPOINT Counter counter;
}  // namespace

struct Driver {
  int handle;
};

class Copter {
 public:
  struct Mission {
    int index;
  };
  int mode = 0;
  double alt[3] = {};
  Driver driver{};
  SYMCR_INCLUDE Mission mission{};
  std::function<void()> callback;
  static void set_boots(int value) { boots = value; }
  static int get_boots() { return boots; }

 private:
  SYMCR_CHECKPOINT static int boots;
};
int Copter::boots = 0;

SYMCR_CHECKPOINT_SHALLOW Copter copter;

struct Log {
  int count SYMCR_RENAMED_FROM("lines");
  int junk SYMCR_SKIP;
};
Log log_state;
#pragma symcr checkpoint(log_state)

int next_id() {
  SYMCR_CHECKPOINT static int id = 0;
  return ++id;
}

int main(int argc, char** argv) {
  log_state.junk = -7;
  copter.driver.handle = -1;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(counter.hits == 17);
  XV_CHECK(copter.mode == 3);
  XV_CHECK(copter.alt[1] == 120.5);
  XV_CHECK(copter.driver.handle == -1);  // not part of the shallow root
  XV_CHECK(copter.mission.index == 4);
  XV_CHECK(Copter::get_boots() == 6);
  XV_CHECK(log_state.count == 250);
  XV_CHECK(log_state.junk == -7);
  XV_CHECK(next_id() == 3);
  return xv::verdict();
}
