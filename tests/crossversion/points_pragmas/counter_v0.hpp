// v0's counter and its checkpoint annotations, as pragmas in the header that both sources
// include: the state, the store and the point (Counter::tick's exit), each seen by two
// translation units and counted once.
#ifndef POINTS_PRAGMAS_COUNTER_V0_HPP
#define POINTS_PRAGMAS_COUNTER_V0_HPP

#include <cstdint>

struct Counter {
  std::int32_t ticks = 0;
  std::int32_t total = 0;
  double average = 0;
  void tick(std::int32_t value);  // defined in counter_v0.cpp
};

extern Counter counter;

#pragma symcr checkpoint(counter)
#pragma symcr store("points_pragmas.store", slots=2, durability=fdatasync)
#pragma symcr checkpoint_at(Counter::tick, exit)

#endif
