// With internal_b.cpp: two different types with internal linkage and the same name.
#include <symcr/symcr.hpp>

namespace {
struct State {
  int a;
};
SYMCR_CHECKPOINT State state_a;
}  // namespace
