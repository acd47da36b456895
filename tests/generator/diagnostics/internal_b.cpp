#include <symcr/symcr.hpp>

namespace {
struct State {
  double b;
};
SYMCR_CHECKPOINT State state_b;
}  // namespace
