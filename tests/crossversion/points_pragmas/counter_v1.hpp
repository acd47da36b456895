// v1: `total` became 64-bit and `ticks` moved; the points are written with the macros of
// <symcr/points.h> (they are pragmas for symcr-gen and nothing for the compiler). The restore
// happens at the entry of Counter::resume and stops the program if it fails.
#ifndef POINTS_PRAGMAS_COUNTER_V1_HPP
#define POINTS_PRAGMAS_COUNTER_V1_HPP

#include <cstdint>

#include <symcr/points.h>

struct Counter {
  double average = -1;
  std::int64_t total = -1;
  std::int32_t ticks = -1;
  void resume();  // defined in counter_v1.cpp
};

extern Counter counter;

#pragma symcr checkpoint(counter)
SYMCR_STORE("points_pragmas.store", slots=2, durability=fdatasync)
SYMCR_RESTORE_AT(Counter::resume, entry, on_failure=stop)

#endif
