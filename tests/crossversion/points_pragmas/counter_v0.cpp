#include "counter_v0.hpp"

Counter counter;

void Counter::tick(std::int32_t value) {
  ++ticks;
  total += value;
  if (value < 0) return;  // every return path reaches the exit point
  average = static_cast<double>(total) / ticks;
}
