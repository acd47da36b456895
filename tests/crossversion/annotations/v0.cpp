// v0: annotated only with pragmas and the sidecar file (annotations/v0.symcr); no macros.
#include <functional>

#include "check.hpp"

namespace {
struct Counter {
  int hits;
};
Counter counter;  // a root by the sidecar file; internal linkage
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
  Driver driver{};                 // not selected by the shallow root
  Mission mission{};               // selected by include()
  std::function<void()> callback;  // never reached: the root is shallow
  static void set_boots(int value) { boots = value; }

 private:
  static int boots;  // a private static member root
};
int Copter::boots = 0;

#pragma symcr checkpoint(copter, shallow)
#pragma symcr include(Copter::mission)
Copter copter;

struct Log {
  int lines;
  int junk;
};
#pragma symcr skip(Log::junk)
Log log_state;

int next_id() {
  static int id = 0;  // a function-local static root by the sidecar file
  return ++id;
}

int main(int argc, char** argv) {
  counter.hits = 17;
  copter.mode = 3;
  copter.alt[1] = 120.5;
  copter.driver.handle = 99;
  copter.mission.index = 4;
  Copter::set_boots(6);
  log_state = {250, 1};
  next_id();
  next_id();
  return xv::save(argc, argv);
}
