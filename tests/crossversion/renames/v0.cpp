// v0: names before the renames of v1.
#include "check.hpp"

struct Settings {
  int gain;
  int limit;
};

SYMCR_CHECKPOINT Settings tuning;

int main(int argc, char** argv) {
  tuning = {12, 300};
  return xv::save(argc, argv);
}
