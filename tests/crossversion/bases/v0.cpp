// v0: a class hierarchy.
#include "check.hpp"

struct Vehicle {
  int id;
};
struct Logger {
  int level;
};
struct Tracker {
  int fixes;
};
struct Copter : Vehicle, Tracker {
  int motors;
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  copter.id = 7;
  copter.fixes = 11;
  copter.motors = 4;
  return xv::save(argc, argv);
}
