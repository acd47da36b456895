#include <cstdio>

#include "counter_v0.hpp"

int main() {
  const int values[] = {4, 8, -3, 15};
  for (int value : values) counter.tick(value);
  std::printf("v0: %d ticks\n", counter.ticks);
  return 0;
}
