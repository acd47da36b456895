// symcr_bench_specimen: the specimen's critical state, every row side by side in one run
// (symcr_rows.cpp, compare.cpp). Before the benchmarks run, the copter flies to its in-flight
// state (flight.hpp).
//
//   symcr_bench_specimen [Google Benchmark flags]       (files go to $TMPDIR, else /tmp)
//   symcr_bench_specimen --write-fixture DIR
//       writes the in-flight state as this (V0) build checkpoints it, for the schema-change
//       program built from a patched autopilot (schema_change.cpp): DIR/specimen-v0.ckpt
//       (single file), DIR/specimen-v0.store (a store holding one checkpoint) and
//       DIR/specimen-v0.txt (the number of mission commands, which the restore must bring back)
//   symcr_bench_specimen --cold-restore N STORE
//       the first restore in a fresh process, N times (cold_restore.hpp)
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "Copter.hpp"
#include "cold_restore.hpp"
#include "state.hpp"
#include "symcr/symcr.hpp"

namespace {

int write_fixture(const std::string& dir) {
  using namespace specimen_bench;
  reset_to_flight_state();
  const std::string single = dir + "/specimen-v0.ckpt", store_path = dir + "/specimen-v0.store";
  symcr::Status status = symcr::checkpoint(program_schema(), single.c_str());
  if (!status.ok()) die("checkpoint", status.message());
  ::unlink(store_path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  symcr::Store store;
  status = symcr::Store::open(store_path.c_str(), program_schema(), options, store);
  if (status.ok()) status = store.save();
  if (!status.ok()) die("store", status.message());
  store.close();
  const std::string expect = dir + "/specimen-v0.txt";
  std::FILE* f = std::fopen(expect.c_str(), "w");
  if (f == nullptr || std::fprintf(f, "%d\n", copter.mission.num_commands()) < 0 ||
      std::fclose(f) != 0) {
    die("write", expect);
  }
  std::printf("%s\n", flight_description().c_str());
  return 0;
}

// After a cold restore: the in-flight state's marks (flying a mission in AUTO, armed).
bool restored_in_flight() {
  return copter.armed() && copter.get_mode() == Mode::AUTO && copter.mission.num_commands() > 0;
}

}  // namespace

int main(int argc, char** argv) {
  const int cold = specimen_bench::run_cold_restore_mode(argc, argv, restored_in_flight);
  if (cold >= 0) return cold;
  if (argc == 3 && std::strcmp(argv[1], "--write-fixture") == 0) return write_fixture(argv[2]);
  benchmark::AddCustomContext("specimen_flight", specimen_bench::flight_description());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
