#include "shared_v0.hpp"

SYMCR_CHECKPOINT Fleet fleet;

int main(int argc, char** argv) {
  fleet.route = {{1, 2}, {3, 4}};
  fleet.scratch = 5;
  fill_log();
  return xv::save(argc, argv);
}
