// v0: the original layout.
#include "check.hpp"

struct Config {
  int a;
  double removed;
  float b;
  char tag;
  int old_name;
};

SYMCR_CHECKPOINT Config config;

int main(int argc, char** argv) {
  config = {1, 2.5, 3.5f, 'x', 42};
  return xv::save(argc, argv);
}
