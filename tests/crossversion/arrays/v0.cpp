// v0: fixed arrays, one- and two-dimensional.
#include "check.hpp"

struct Tables {
  int grows[3];
  int shrinks[5];
  short grid[2][3];
  char name[8];
};

SYMCR_CHECKPOINT Tables tables;

int main(int argc, char** argv) {
  tables = {{1, 2, 3}, {10, 20, 30, 40, 50}, {{1, 2, 3}, {4, 5, 6}}, "copter"};
  return xv::save(argc, argv);
}
