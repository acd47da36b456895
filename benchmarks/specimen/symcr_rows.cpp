// The specimen's critical state (`SYMCR_CHECKPOINT Copter copter;`, the schema symcr-gen
// generated for it) through symcr's file layer and in memory, beside the floor: memcpy of the
// root object's bytes and one raw pwrite of as many bytes as the values take. The same rows
// as runtime_latency.cpp has for the stand-in state. Every benchmark reports "bytes" = bytes
// written (or read) per checkpoint.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "Copter.hpp"
#include "initial_state.hpp"
#include "state.hpp"
#include "symcr/symcr.hpp"

namespace specimen_bench {
namespace {

// ---- the floor -------------------------------------------------------------------------------
// The root object's bytes, padding and skipped fields included: what the specimen's raw-image
// method saves.
void BM_Memcpy(benchmark::State& state) {
  reset_to_flight_state();
  alignas(Copter) static std::uint8_t buffer[sizeof(Copter)];
  for (auto _ : state) {
    std::memcpy(buffer, &copter, sizeof copter);
    benchmark::DoNotOptimize(buffer);
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(sizeof buffer);
}
BENCHMARK(BM_Memcpy)->Apply(measured_iterations);

// One positioned write of as many bytes as the values symcr saves (no header, schema or counts).
void BM_RawPwrite(benchmark::State& state) {
  const std::string path = scratch_path("raw");
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return fail(state, "open", std::strerror(errno));
  const std::vector<std::uint8_t> bytes(value_bytes(flight_checkpoint()), 0x5a);
  for (auto _ : state) {
    if (::pwrite(fd, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size())) {
      fail(state, "pwrite", std::strerror(errno));
      break;
    }
  }
  state.counters["bytes"] = static_cast<double>(bytes.size());
  ::close(fd);
  ::unlink(path.c_str());
}
BENCHMARK(BM_RawPwrite)->Apply(measured_iterations);

// ---- symcr: in memory (the bytes of a single-file checkpoint, schema inline) ------------------
void BM_CheckpointToBuffer(benchmark::State& state) {
  reset_to_flight_state();
  std::vector<std::uint8_t> buffer;
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint_to_buffer(program_schema(), buffer);
    if (!status.ok()) {
      fail(state, "checkpoint_to_buffer", status.message());
      break;
    }
    benchmark::DoNotOptimize(buffer.data());
  }
  state.counters["bytes"] = static_cast<double>(buffer.size());
  state.counters["payload_bytes"] = static_cast<double>(payload_size(buffer));
  state.counters["schema_bytes"] = static_cast<double>(schema_size(buffer));
}
BENCHMARK(BM_CheckpointToBuffer)->Apply(measured_iterations);

void BM_RestoreFromBuffer(benchmark::State& state) {
  reset_to_flight_state();
  const std::vector<std::uint8_t>& buffer = flight_checkpoint();
  reset_copter();  // the restores must bring every value back
  for (auto _ : state) {
    const symcr::Report report =
        symcr::restore_from_buffer(program_schema(), buffer.data(), buffer.size());
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
  }
  if (!matches_flight_state()) fail(state, "restore_from_buffer", "the restored state differs");
  state.counters["bytes"] = static_cast<double>(buffer.size());
}
BENCHMARK(BM_RestoreFromBuffer)->Apply(measured_iterations);

// ---- symcr: the checkpoint store --------------------------------------------------------------
// Authenticated checkpoints for the rows that ask for them: every save signs its record and
// every restore verifies it (HMAC-SHA-256 with a 32-byte key).
class BenchmarkKeys {
 public:
  explicit BenchmarkKeys(bool authenticated) : on_(authenticated) {
    static const std::uint8_t key[32] = {0x5e, 0xc2, 0x37, 0x91};
    const symcr::CheckpointKey bench_key{1, key, sizeof key};
    if (on_) (void)symcr::set_checkpoint_keys(&bench_key, 1);
  }
  ~BenchmarkKeys() {
    if (on_) (void)symcr::set_checkpoint_keys(nullptr, 0);
  }
  BenchmarkKeys(const BenchmarkKeys&) = delete;
  BenchmarkKeys& operator=(const BenchmarkKeys&) = delete;

 private:
  bool on_;
};

void BM_StoreSave(benchmark::State& state, symcr::Durability durability, bool authenticated) {
  reset_to_flight_state();  // before the keys: its checkpoint is not authenticated
  const BenchmarkKeys keys(authenticated);
  const std::string path = scratch_path("store");
  ::unlink(path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  options.durability = durability;
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path.c_str(), program_schema(), options, store);
  if (!status.ok()) return fail(state, "open", status.message());
  for (auto _ : state) {
    status = store.save();
    if (!status.ok()) {
      fail(state, "save", status.message());
      break;
    }
  }
  state.counters["bytes"] = static_cast<double>(store_record_bytes());
  store.close();
  ::unlink(path.c_str());
}
BENCHMARK_CAPTURE(BM_StoreSave, page_cache, symcr::Durability::PageCache, false)->Apply(measured_iterations);
BENCHMARK_CAPTURE(BM_StoreSave, fdatasync, symcr::Durability::Fdatasync, false)->Iterations(200)->Apply(measured_iterations);
BENCHMARK_CAPTURE(BM_StoreSave, page_cache_authenticated, symcr::Durability::PageCache, true)->Apply(measured_iterations);

void store_restore_latest(benchmark::State& state, bool authenticated) {
  reset_to_flight_state();  // before the keys: its checkpoint is not authenticated
  const BenchmarkKeys keys(authenticated);
  const std::string path = scratch_path("store-restore");
  ::unlink(path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path.c_str(), program_schema(), options, store);
  if (!status.ok()) return fail(state, "open", status.message());
  for (std::uint32_t slot = 0; slot < options.slots; ++slot) {  // every slot valid
    status = store.save();
    if (!status.ok()) return fail(state, "save", status.message());
  }
  reset_copter();
  for (auto _ : state) {
    const symcr::Report report = store.restore_latest();
    if (!report.ok() || report.sequence() != options.slots) {
      fail(state, "restore_latest", report.status().message());
      break;
    }
  }
  if (!matches_flight_state()) fail(state, "restore_latest", "the restored state differs");
  state.counters["bytes"] = static_cast<double>(store_record_bytes());
  store.close();
  ::unlink(path.c_str());
}
void BM_StoreRestoreLatest(benchmark::State& state) { store_restore_latest(state, false); }
BENCHMARK(BM_StoreRestoreLatest)->Apply(measured_iterations);
void BM_StoreRestoreLatestAuthenticated(benchmark::State& state) {
  store_restore_latest(state, true);
}
BENCHMARK(BM_StoreRestoreLatestAuthenticated)->Apply(measured_iterations);

// ---- symcr: single-file checkpoints (exclusive temp file + rename) ---------------------------
void BM_CheckpointFile(benchmark::State& state) {
  reset_to_flight_state();
  const std::string path = scratch_path("single.ckpt");
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint(program_schema(), path.c_str());
    if (!status.ok()) {
      fail(state, "checkpoint", status.message());
      break;
    }
  }
  state.counters["bytes"] = static_cast<double>(flight_checkpoint().size());
  ::unlink(path.c_str());
}
BENCHMARK(BM_CheckpointFile)->Apply(measured_iterations);

void BM_RestoreFile(benchmark::State& state) {
  reset_to_flight_state();
  const std::string path = scratch_path("restore.ckpt");
  const symcr::Status saved = symcr::checkpoint(program_schema(), path.c_str());
  if (!saved.ok()) return fail(state, "checkpoint", saved.message());
  reset_copter();
  for (auto _ : state) {
    const symcr::Report report = symcr::restore(program_schema(), path.c_str());
    if (!report.ok()) {
      fail(state, "restore", report.status().message());
      break;
    }
  }
  if (!matches_flight_state()) fail(state, "restore", "the restored state differs");
  state.counters["bytes"] = static_cast<double>(flight_checkpoint().size());
  ::unlink(path.c_str());
}
BENCHMARK(BM_RestoreFile)->Apply(measured_iterations);

}  // namespace
}  // namespace specimen_bench
