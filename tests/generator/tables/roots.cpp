// The roots of the tables test, with the linkages the generator must handle.
#include "roots.hpp"

SYMCR_CHECKPOINT fleet::Everything everything;

namespace {
struct Hidden {
  int x;
};
SYMCR_CHECKPOINT Hidden hidden_root{42};
}  // namespace

namespace fleet {
SYMCR_CHECKPOINT int fleet_counter = 0;
}

int Registry::count = 0;

const void* hidden_root_address() { return &hidden_root; }

int* local_static_address() {
  SYMCR_CHECKPOINT static int calls = 0;
  ++calls;
  return &calls;
}
