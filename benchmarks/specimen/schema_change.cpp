// Restore across a schema change, with the specimen's real builds: the checkpoint the V0 build
// wrote in flight (symcr_bench_specimen --write-fixture, run at build time) restored into this
// program, built from a patched autopilot (V3 by default: `prev_control_mode` renamed
// `prev_flight_mode`, `_baro_offset` float -> double, AP_Mission's and AP_AHRS's fields reordered;
// specimen/README.md), with the resolution plan cached and not cached, and from the store the
// V0 build wrote. A separate program because one process holds one build of `copter`;
// benchmarks/run reports its rows beside symcr_bench_specimen's.
//
//   symcr_bench_specimen_<version> [--fixture DIR] [Google Benchmark flags]
//   symcr_bench_specimen_<version> --cold-restore N STORE   (cold_restore.hpp)
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "Copter.hpp"
#include "cold_restore.hpp"
#include "common.hpp"
#include "initial_state.hpp"
#include "symcr/symcr.hpp"

#ifndef SPECIMEN_BENCH_FIXTURE_DIR
#error "SPECIMEN_BENCH_FIXTURE_DIR (where the V0 checkpoints are) must be defined by the build"
#endif

namespace specimen_bench {
namespace {

std::string& fixture_dir() {
  static std::string dir = SPECIMEN_BENCH_FIXTURE_DIR;
  return dir;
}

std::vector<std::uint8_t> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die("read", path + " (run symcr_bench_specimen --write-fixture DIR first)");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::vector<std::uint8_t>& v0_checkpoint() {
  static const std::vector<std::uint8_t> bytes = read_file(fixture_dir() + "/specimen-v0.ckpt");
  return bytes;
}

int v0_mission_commands() {
  static const int count = [] {
    const std::vector<std::uint8_t> text = read_file(fixture_dir() + "/specimen-v0.txt");
    return std::atoi(std::string(text.begin(), text.end()).c_str());
  }();
  return count;
}

// What the V0 -> V3 restore must bring back (so a broken resolution cannot pass for a fast
// one): the vehicle armed, flying its mission in AUTO, with every command of it.
bool restored() {
  return copter.armed() && copter.get_mode() == Mode::AUTO &&
         copter.mission.num_commands() == v0_mission_commands() && v0_mission_commands() > 0;
}

void reset() { reset_copter(); }

void report_counters(benchmark::State& state, const symcr::Report& report, std::size_t bytes) {
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["report_entries"] = static_cast<double>(report.entries().size());
  state.counters["converted"] = static_cast<double>(report.count(symcr::Decision::Converted));
}

// The resolution plan of (V0 schema, this build's schema) is built once and cached. Single-file
// form: the inline V0 schema is parsed on every restore, the plan is not rebuilt.
void BM_SchemaChangeRestoreCached(benchmark::State& state) {
  const std::vector<std::uint8_t>& bytes = v0_checkpoint();
  reset();
  symcr::Report report;
  for (auto _ : state) {
    report = symcr::restore_from_buffer(program_schema(), bytes.data(), bytes.size());
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
  }
  if (!restored()) fail(state, "V0 -> patched", "wrong values restored");
  report_counters(state, report, bytes.size());
}
BENCHMARK(BM_SchemaChangeRestoreCached)->Apply(measured_iterations);

// Not cached: the runtime keeps a few plans keyed by the reader Schema object, so restoring in
// turn into more distinct (identical) reader Schema objects than it keeps makes every restore
// build its plan from scratch: what the first restore after a patch costs.
void BM_SchemaChangeRestoreUncached(benchmark::State& state) {
  const std::vector<std::uint8_t>& bytes = v0_checkpoint();
  constexpr std::size_t kReaders = 32;  // well above the plan cache's capacity
  std::vector<symcr::Schema> readers(kReaders, program_schema());
  for (const symcr::Schema& reader : readers) {  // warm everything but the plans
    symcr::restore_from_buffer(reader, bytes.data(), bytes.size());
  }
  reset();
  std::size_t next = 0;
  symcr::Report report;
  for (auto _ : state) {
    report = symcr::restore_from_buffer(readers[next], bytes.data(), bytes.size());
    next = (next + 1) % kReaders;
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
  }
  if (!restored()) fail(state, "V0 -> patched", "wrong values restored");
  report_counters(state, report, bytes.size());
}
BENCHMARK(BM_SchemaChangeRestoreUncached)->Apply(measured_iterations);

// The store the V0 build wrote, opened by this build: restore_latest with the store's parsed
// schema and the cached plan (the periodic-checkpoint deployment after a patch). Works on a
// copy: opening a store may prepare it for this build's saves.
void BM_SchemaChangeStoreRestoreLatest(benchmark::State& state) {
  const std::vector<std::uint8_t> image = read_file(fixture_dir() + "/specimen-v0.store");
  const std::string path = scratch_path("store-v0");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(image.data()),
              static_cast<std::streamsize>(image.size()));
    if (!out) return fail(state, "write", path.c_str());
  }
  symcr::StoreOptions options;
  options.slot_size = 4096;
  symcr::Store store;
  const symcr::Status status = symcr::Store::open(path.c_str(), program_schema(), options, store);
  if (!status.ok()) return fail(state, "open", status.message());
  reset();
  symcr::Report report;
  for (auto _ : state) {
    report = store.restore_latest();
    if (!report.ok()) {
      fail(state, "restore_latest", report.status().message());
      break;
    }
  }
  if (!restored()) fail(state, "V0 -> patched", "wrong values restored");
  const std::vector<std::uint8_t>& single = v0_checkpoint();
  report_counters(state, report, single.size() - schema_size(single));
  store.close();
  ::unlink(path.c_str());
}
BENCHMARK(BM_SchemaChangeStoreRestoreLatest)->Apply(measured_iterations);

}  // namespace
}  // namespace specimen_bench

int main(int argc, char** argv) {
  const int cold = specimen_bench::run_cold_restore_mode(argc, argv, specimen_bench::restored);
  if (cold >= 0) return cold;
  if (argc >= 3 && std::strcmp(argv[1], "--fixture") == 0) {
    specimen_bench::fixture_dir() = argv[2];
    argv[2] = argv[0];
    argv += 2;
    argc -= 2;
  }
  benchmark::AddCustomContext("specimen_fixture", specimen_bench::fixture_dir());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
