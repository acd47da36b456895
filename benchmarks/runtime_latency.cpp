// Checkpoint and restore latency of the runtime's file layer (benchmarks/README.md: store save
// <= 5 us, restore <= 20 us) for a specimen-sized state (critical_state.hpp): about 300 bytes
// in about 100 fields of nested structs, arrays (one two-dimensional) and enums, described by a
// hand-written schema in the shape symcr-gen emits. Beside them, the floor: memcpy and one raw
// pwrite of the same bytes. Every benchmark reports "bytes" = bytes written per checkpoint.
// Linked into one program with critical_compare.cpp (cereal, Boost, schema change), so that
// all of them are measured side by side in one run.
//
//   symcr_bench_latency [--benchmark_filter=Store]     (files go to $TMPDIR, else /tmp)
#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "critical_state.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace {

using namespace critical;  // the state and its schema: critical_state.hpp

// Bytes of one store slot record: a single-file record minus its inline schema (the size at
// header offset 40, docs/format.md §1), as the store shares the schema between slots.
double store_record_bytes() {
  std::vector<std::uint8_t> buffer;
  if (!symcr::checkpoint_to_buffer(schema, buffer).ok()) return 0;
  std::uint32_t schema_size = 0;
  std::memcpy(&schema_size, buffer.data() + 40, sizeof schema_size);  // little-endian host
  return static_cast<double>(buffer.size() - schema_size);
}

void fail(benchmark::State& state, const char* what, const char* message) {
  const std::string text = std::string(what) + ": " + message;
  state.SkipWithError(text.c_str());
}

// ---- the floor -------------------------------------------------------------------------------
void BM_Memcpy(benchmark::State& state) {
  fill_state(1);
  std::uint8_t buffer[sizeof(Copter) + sizeof(Ahrs) + sizeof(Mission) + sizeof(Telemetry)];
  for (auto _ : state) {
    std::uint8_t* p = buffer;
    std::memcpy(p, &copter, sizeof copter);
    p += sizeof copter;
    std::memcpy(p, &ahrs, sizeof ahrs);
    p += sizeof ahrs;
    std::memcpy(p, &mission, sizeof mission);
    p += sizeof mission;
    std::memcpy(p, &telemetry, sizeof telemetry);
    benchmark::DoNotOptimize(buffer);
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(sizeof buffer);
}
BENCHMARK(BM_Memcpy);

void BM_RawPwrite(benchmark::State& state) {
  const std::string path = scratch_path("raw");
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  std::uint8_t bytes[kValueBytes] = {};
  for (auto _ : state) {
    if (::pwrite(fd, bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes)) {
      fail(state, "pwrite", std::strerror(errno));
      break;
    }
  }
  state.counters["bytes"] = static_cast<double>(sizeof bytes);
  ::close(fd);
  ::unlink(path.c_str());
}
BENCHMARK(BM_RawPwrite);

// ---- symcr -----------------------------------------------------------------------------------
void BM_CheckpointToBuffer(benchmark::State& state) {
  fill_state(1);
  std::vector<std::uint8_t> buffer;
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint_to_buffer(schema, buffer);
    if (!status.ok()) {
      fail(state, "checkpoint_to_buffer", status.message());
      break;
    }
    benchmark::DoNotOptimize(buffer.data());
  }
  state.counters["bytes"] = static_cast<double>(buffer.size());
}
BENCHMARK(BM_CheckpointToBuffer);

void BM_RestoreFromBuffer(benchmark::State& state) {
  fill_state(1);
  std::vector<std::uint8_t> buffer;
  symcr::checkpoint_to_buffer(schema, buffer);
  for (auto _ : state) {
    const symcr::Report report = symcr::restore_from_buffer(schema, buffer.data(), buffer.size());
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
  }
  state.counters["bytes"] = static_cast<double>(buffer.size());
}
BENCHMARK(BM_RestoreFromBuffer);

void BM_StoreSave(benchmark::State& state, symcr::Durability durability) {
  const std::string path = scratch_path("store");
  ::unlink(path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  options.durability = durability;
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path.c_str(), schema, options, store);
  if (!status.ok()) return fail(state, "open", status.message());
  std::uint32_t tick = 0;
  for (auto _ : state) {
    copter.ticks = ++tick;
    status = store.save();
    if (!status.ok()) {
      fail(state, "save", status.message());
      break;
    }
  }
  state.counters["bytes"] = store_record_bytes();
  store.close();
  ::unlink(path.c_str());
}
BENCHMARK_CAPTURE(BM_StoreSave, page_cache, symcr::Durability::PageCache);
BENCHMARK_CAPTURE(BM_StoreSave, fdatasync, symcr::Durability::Fdatasync)->Iterations(200);

// With `fallback_depth`, each iteration is a start's restore and its confirm(): the crash-loop
// fallback's two journal writes (a restore that is already recorded writes nothing).
void store_restore_latest(benchmark::State& state, std::uint32_t fallback_depth) {
  const std::string path = scratch_path("store-restore");
  ::unlink(path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  options.fallback_depth = fallback_depth;
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path.c_str(), schema, options, store);
  if (!status.ok()) return fail(state, "open", status.message());
  for (std::uint32_t tick = 1; tick <= options.slots; ++tick) {  // every slot valid
    fill_state(tick);
    status = store.save();
    if (!status.ok()) return fail(state, "save", status.message());
  }
  for (auto _ : state) {
    const symcr::Report report = store.restore_latest();
    if (!report.ok() || report.sequence() != options.slots) {
      fail(state, "restore_latest", report.status().message());
      break;
    }
    if (fallback_depth != 0) {
      status = store.confirm();
      if (!status.ok()) {
        fail(state, "confirm", status.message());
        break;
      }
    }
  }
  state.counters["bytes"] = store_record_bytes();
  store.close();
  ::unlink(path.c_str());
}

void BM_StoreRestoreLatest(benchmark::State& state) { store_restore_latest(state, 0); }
BENCHMARK(BM_StoreRestoreLatest);

void BM_StoreRestoreLatestAndConfirmWithFallback(benchmark::State& state) {
  store_restore_latest(state, 2);
}
BENCHMARK(BM_StoreRestoreLatestAndConfirmWithFallback);

// ---- authenticated stores (docs/threat-model.md) ------------------------------------------------
// Each iteration is a save and a restore_latest() (which verifies every slot's MAC): without
// keys; with keys and a counter in memory (what a hardware counter costs symcr: the MACs); and
// with keys and the default freshness counter, a file written after every save.
class MemoryCounter : public symcr::FreshnessCounter {
 public:
  symcr::Status read(std::uint64_t& value) override {
    value = value_;
    return symcr::Status();
  }
  symcr::Status advance(std::uint64_t value) override {
    if (value > value_) value_ = value;
    return symcr::Status();
  }

 private:
  std::uint64_t value_ = 0;
};

enum class Freshness { NoKeys, KeysMemoryCounter, KeysFileCounter };

void BM_StoreSaveAndRestore(benchmark::State& state, Freshness freshness) {
  const std::string path = scratch_path("store-auth");
  ::unlink(path.c_str());
  ::unlink((path + ".fresh").c_str());
  static const std::uint8_t key[32] = {7};
  const symcr::CheckpointKey keys{1, key, sizeof key};
  (void)symcr::set_checkpoint_keys(&keys, freshness == Freshness::NoKeys ? 0 : 1);
  MemoryCounter counter;
  symcr::StoreOptions options;
  options.slot_size = 4096;
  if (freshness == Freshness::KeysMemoryCounter) options.freshness_counter = &counter;
  {
    symcr::Store store;
    symcr::Status status = symcr::Store::open(path.c_str(), schema, options, store);
    if (!status.ok()) return fail(state, "open", status.message());
    std::uint32_t tick = 0;
    for (auto _ : state) {
      fill_state(++tick);
      status = store.save();
      const symcr::Report report = store.restore_latest();
      if (!status.ok() || !report.ok()) {
        fail(state, "save and restore", status.ok() ? report.status().message() : status.message());
        break;
      }
    }
  }
  state.counters["bytes"] = store_record_bytes();
  (void)symcr::set_checkpoint_keys(nullptr, 0);
  ::unlink(path.c_str());
  ::unlink((path + ".fresh").c_str());
}
BENCHMARK_CAPTURE(BM_StoreSaveAndRestore, no_keys, Freshness::NoKeys);
BENCHMARK_CAPTURE(BM_StoreSaveAndRestore, keys_memory_counter, Freshness::KeysMemoryCounter);
BENCHMARK_CAPTURE(BM_StoreSaveAndRestore, keys_freshness_file, Freshness::KeysFileCounter);

void BM_CheckpointFile(benchmark::State& state) {
  const std::string path = scratch_path("single.ckpt");
  fill_state(1);
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint(schema, path.c_str());
    if (!status.ok()) {
      fail(state, "checkpoint", status.message());
      break;
    }
  }
  std::vector<std::uint8_t> buffer;
  symcr::checkpoint_to_buffer(schema, buffer);
  state.counters["bytes"] = static_cast<double>(buffer.size());
  ::unlink(path.c_str());
}
BENCHMARK(BM_CheckpointFile);

void BM_RestoreFile(benchmark::State& state) {
  const std::string path = scratch_path("restore.ckpt");
  fill_state(1);
  const symcr::Status saved = symcr::checkpoint(schema, path.c_str());
  if (!saved.ok()) return fail(state, "checkpoint", saved.message());
  for (auto _ : state) {
    const symcr::Report report = symcr::restore(schema, path.c_str());
    if (!report.ok()) {
      fail(state, "restore", report.status().message());
      break;
    }
  }
  ::unlink(path.c_str());
}
BENCHMARK(BM_RestoreFile);

}  // namespace

