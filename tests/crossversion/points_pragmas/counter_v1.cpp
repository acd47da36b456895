#include "counter_v1.hpp"

#include <cstdio>

Counter counter;

void Counter::resume() {
  // Runs after the restore at this function's entry.
  std::printf("resumed: ticks=%d total=%lld average=%.3f\n", ticks, static_cast<long long>(total),
              average);
}
