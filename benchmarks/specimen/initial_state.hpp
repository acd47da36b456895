// Puts `copter` back into its initial state: constructed anew, since its constant and reference
// members rule out assignment. Inline, as each benchmark program is built from its own version
// of the autopilot.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_INITIAL_STATE_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_INITIAL_STATE_HPP

#include <new>

#include "Copter.hpp"

namespace specimen_bench {

inline void reset_copter() {
  copter.~Copter();
  new (&copter) Copter();
}

}  // namespace specimen_bench

#endif  // SYMCR_BENCHMARKS_SPECIMEN_INITIAL_STATE_HPP
