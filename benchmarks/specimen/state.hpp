// What the specimen benchmarks share: the in-flight state of `copter` (flown once per process,
// flight.hpp), the checkpoint of it that resets the state before each benchmark, and the sizes
// every benchmark reports against.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_STATE_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_STATE_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common.hpp"

namespace specimen_bench {

// Flies to the in-flight state on the first call (aborting the program if the flight fails),
// and on every call puts `copter` back into that state. Every benchmark starts with it.
void reset_to_flight_state();

// What was flown, for the report: "<mission file>: <s> s simulated, heading for item <n> of
// <m> commands".
const std::string& flight_description();

// True when `copter` holds the in-flight state again (its checkpoint payload is the same):
// how the cereal / Boost loads and the restores show they restored everything.
bool matches_flight_state();

// The single-file checkpoint bytes of the in-flight state (inline schema).
const std::vector<std::uint8_t>& flight_checkpoint();

// Bytes of one store slot record: the single-file record less its inline schema (the store
// shares the schema between its slots).
std::size_t store_record_bytes();

}  // namespace specimen_bench

#endif  // SYMCR_BENCHMARKS_SPECIMEN_STATE_HPP
