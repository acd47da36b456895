// Program point directives that cannot be honoured; each line is one test's error.
#include "points_header.hpp"
int value;
#pragma symcr checkpoint(value)
#pragma symcr store("points.store")
#pragma symcr checkpoint_at(Missing::loop, exit)
#pragma symcr checkpoint_at(declared_only, exit)
#pragma symcr restore_at(inline_in_header, entry)
#pragma symcr checkpoint_at(tick, middle)
#pragma symcr checkpoint_at(tick, exit, every 0)
#pragma symcr restore_at(tick, exit, on_failure=retry)
#pragma symcr store("other.store")
template <typename T> T twice(T x) { return x + x; }
#pragma symcr checkpoint_at(twice, exit)
void tick() { value += twice(1); }
#pragma symcr store("points.store", fallback_depth=0, confirm_after=5)
#pragma symcr store("points.store", slots=2, confirm_after=5)
#pragma symcr store("points.store", fallback_depth=-1)
