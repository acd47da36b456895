// Helpers of both specimen benchmark programs (symcr_bench_specimen and the schema-change
// program built from a patched autopilot): the generated schema, checkpoint header fields,
// scratch files, failures.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_COMMON_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_COMMON_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "symcr/generated.hpp"

namespace benchmark {
class State;
namespace internal {
class Benchmark;
}
}  // namespace benchmark

namespace specimen_bench {

// The schema symcr-gen generated for this build's `copter` (symcr_program_schema()).
const symcr::Schema& program_schema();

// Header fields of a single-file checkpoint (docs/format.md §1).
std::uint32_t schema_size(const std::vector<std::uint8_t>& record);
std::uint32_t payload_size(const std::vector<std::uint8_t>& record);
// The values alone, about: the payload less its two u32 counts of heap objects and references
// (docs/format.md §3). `copter`'s few pointers (its flight mode, the mission's callbacks) are
// references, counted here as values.
std::uint32_t value_bytes(const std::vector<std::uint8_t>& record);
// A file name under $TMPDIR (else /tmp), unique to this process.
std::string scratch_path(const char* name);

// Prints "specimen benchmark: what: message" and exits with 1 (setup that must not fail).
[[noreturn]] void die(const char* what, const std::string& message);

// Marks the benchmark as failed with "what: message".
void fail(benchmark::State& state, const char* what, const char* message);

// Every row is registered with ->Apply(measured_iterations): with SYMCR_BENCH_ITERATIONS=N in
// the environment the row runs exactly N iterations instead of running for a time, so that
// benchmarks/run can count instructions per operation under callgrind as the difference of
// two runs (N and a larger N), which cancels the setup and the first, cold operation.
void measured_iterations(benchmark::internal::Benchmark* row);

}  // namespace specimen_bench

#endif  // SYMCR_BENCHMARKS_SPECIMEN_COMMON_HPP
