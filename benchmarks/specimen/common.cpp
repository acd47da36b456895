#include "common.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <benchmark/benchmark.h>

#include "symcr/symcr.hpp"

namespace specimen_bench {

void die(const char* what, const std::string& message) {
  std::fprintf(stderr, "specimen benchmark: %s: %s\n", what, message.c_str());
  std::exit(1);
}

const symcr::Schema& program_schema() {
  const symcr::Schema* schema = symcr_program_schema ? symcr_program_schema() : nullptr;
  if (schema == nullptr) die("schema", "this program has no generated schema (symcr-gen)");
  return *schema;
}

std::uint32_t schema_size(const std::vector<std::uint8_t>& record) {
  std::uint32_t size = 0;
  if (record.size() >= 48) std::memcpy(&size, record.data() + 40, sizeof size);  // LE host
  return size;
}

std::uint32_t payload_size(const std::vector<std::uint8_t>& record) {
  std::uint32_t size = 0;
  if (record.size() >= 48) std::memcpy(&size, record.data() + 44, sizeof size);
  return size;
}

std::uint32_t value_bytes(const std::vector<std::uint8_t>& record) {
  const std::uint32_t payload = payload_size(record);
  return payload >= 8 ? payload - 8 : 0;
}

std::string scratch_path(const char* name) {
  const char* base = std::getenv("TMPDIR");
  return std::string(base && *base ? base : "/tmp") + "/symcr-bench-specimen-" +
         std::to_string(::getpid()) + "-" + name;
}

void fail(benchmark::State& state, const char* what, const char* message) {
  const std::string text = std::string(what) + ": " + message;
  state.SkipWithError(text.c_str());
}

void measured_iterations(benchmark::internal::Benchmark* row) {
  const char* fixed = std::getenv("SYMCR_BENCH_ITERATIONS");
  if (fixed == nullptr || *fixed == '\0') return;
  char* end = nullptr;
  const long long iterations = std::strtoll(fixed, &end, 10);
  if (*end != '\0' || iterations <= 0) die("SYMCR_BENCH_ITERATIONS", fixed);
  row->Iterations(static_cast<benchmark::IterationCount>(iterations));
}

}  // namespace specimen_bench
