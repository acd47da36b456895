// v0: a field that is an integer, and one that is a struct.
#include "check.hpp"

struct Position {
  int x;
  int y;
};

struct State {
  int heading;
  Position home;
  int kept;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state = {90, {3, 4}, 12};
  return xv::save(argc, argv);
}
