// How checkpoint and restore cost grows with the state (benchmarks/README.md: within 2x of memcpy for
// large POD arrays; a 10^6-node pointer graph with cycles checkpointed and restored in <= 1 s
// each). Schemas are hand-written in the form symcr-gen emits
// (tests/runtime/handwritten_schemas.hpp):
//
//   - POD: a root that is a fixed array of doubles (float64[N]) and a root that is a
//     std::vector<double>, 1 KB .. 256 MB, beside memcpy of the same bytes and beside one read
//     of them followed by memcpy (a check-first restore's floor). Throughput is
//     bytes_per_second (payload bytes per iteration).
//   - Pointer graphs: N heap nodes {int64 value; Node* next; Node* jump}: `next` closes one big
//     cycle, `jump` shares targets; 10^3 .. 10^6 nodes. Restore rebuilds every node into an
//     empty root (a fresh process's situation); the rebuilt nodes are freed outside the timing.
//   - A std::map<int64, double> of 10^5 entries, beside copying the map.
//
// Checkpoints go to memory (checkpoint_to_buffer / restore_from_buffer: the same bytes as a
// single-file checkpoint), so the numbers are the engine's, not the disk's.
//
//   symcr_bench_scale [google benchmark flags]
//   symcr_bench_scale --memory <nodes>    one JSON line: peak RSS added by one checkpoint and
//                                         one restore of a graph, in a fresh process (memo
//                                         tables, scratch and output; the engine exposes no
//                                         counters of its own)
#include <time.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "schema_tables.hpp"
#include "scratch.hpp"
#include "symcr/generated.hpp"
#include "symcr/ops.hpp"
#include "symcr/symcr.hpp"

namespace {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

void fail(benchmark::State& state, const char* what, const symcr::Status& status) {
  const std::string text = std::string(what) + ": " + status.message();
  state.SkipWithError(text.c_str());
}

// ---- POD arrays --------------------------------------------------------------------------------
// One schema per size, built at run time (the generator would emit a constant table for the
// program's one size). Worlds live until exit: the runtime caches per Schema object.
struct PodWorld {
  std::string array_name;
  std::vector<double> storage;  // the fixed array's memory (a root variable in a real program)
  std::vector<double> vector;   // the std::vector<double> root
  TypeInfo array_types[2];
  symcr::RootInfo array_root;
  symcr::Schema array_schema;
  TypeInfo vector_types[2];
  symcr::RootInfo vector_root;
  symcr::Schema vector_schema;
};

PodWorld& pod_world(std::size_t bytes) {
  static std::map<std::size_t, PodWorld*> worlds;
  PodWorld*& world = worlds[bytes];
  if (world) return *world;
  world = new PodWorld();  // never freed: see above
  const std::size_t count = bytes / sizeof(double);
  world->array_name = "float64[" + std::to_string(count) + "]";
  world->storage.resize(count);
  world->vector.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    world->storage[i] = world->vector[i] = static_cast<double>(i) * 0.5;
  }
  world->array_types[0] = scalar("float64", Kind::Float, 8);
  world->array_types[1] = array(world->array_name.c_str(), 0, count,
                                static_cast<std::uint32_t>(bytes), alignof(double));
  world->array_root = {"samples", 1, world->storage.data(), 0, nullptr};
  world->array_schema = {world->array_types, 2, &world->array_root, 1, nullptr};
  world->vector_types[0] = scalar("float64", Kind::Float, 8);
  world->vector_types[1] =
      holder("std::vector<float64>", Kind::Container, sizeof(std::vector<double>),
             alignof(std::vector<double>), 0, &symcr::ops::container<std::vector<double>>::table);
  world->vector_root = {"samples", 1, &world->vector, 0, nullptr};
  world->vector_schema = {world->vector_types, 2, &world->vector_root, 1, nullptr};
  return *world;
}

// 1 KB .. 256 MB: x16 steps, then 256 MB. With SYMCR_BENCH_ITERATIONS=N in the environment
// each runs exactly N times, so that counters of the whole process (`perf stat`) taken at two
// values of N give the cost of one operation, setup cancelled.
void pod_sizes(benchmark::internal::Benchmark* b) {
  for (std::int64_t bytes = 1 << 10; bytes <= (std::int64_t{1} << 26); bytes *= 16) b->Arg(bytes);
  b->Arg(std::int64_t{1} << 28);
  const char* fixed = std::getenv("SYMCR_BENCH_ITERATIONS");
  if (fixed == nullptr || *fixed == '\0') return;
  char* end = nullptr;
  const long long iterations = std::strtoll(fixed, &end, 10);
  if (*end != '\0' || iterations <= 0) {
    std::fprintf(stderr, "SYMCR_BENCH_ITERATIONS: not a positive number: %s\n", fixed);
    std::exit(2);
  }
  b->Iterations(static_cast<benchmark::IterationCount>(iterations));
}

void BM_PodMemcpy(benchmark::State& state) {
  const std::size_t bytes = static_cast<std::size_t>(state.range(0));
  PodWorld& world = pod_world(bytes);
  std::vector<std::uint8_t> out(bytes);
  for (auto _ : state) {
    std::memcpy(out.data(), world.storage.data(), bytes);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_PodMemcpy)->Apply(pod_sizes);

// The least a restore that checks before it writes can do: read every byte of the source once
// (a word sum, bounded by memory bandwidth like a CRC as fast as memory), then memcpy. A record
// larger than the cache is read twice; memcpy reads it once.
void BM_PodReadThenMemcpy(benchmark::State& state) {
  const std::size_t bytes = static_cast<std::size_t>(state.range(0));
  PodWorld& world = pod_world(bytes);
  std::vector<std::uint8_t> out(bytes);
  const auto* words = reinterpret_cast<const std::uint64_t*>(world.storage.data());
  const std::size_t count = bytes / sizeof(std::uint64_t);
  for (auto _ : state) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < count; ++i) sum ^= words[i];
    benchmark::DoNotOptimize(sum);
    std::memcpy(out.data(), world.storage.data(), bytes);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_PodReadThenMemcpy)->Apply(pod_sizes);

void pod_checkpoint(benchmark::State& state, bool vector) {
  const std::size_t bytes = static_cast<std::size_t>(state.range(0));
  PodWorld& world = pod_world(bytes);
  const symcr::Schema& schema = vector ? world.vector_schema : world.array_schema;
  std::vector<std::uint8_t> out;
  // Steady state of periodic checkpoints: the buffer has its capacity (and memcpy's destination
  // is allocated and touched too).
  const symcr::Status first = symcr::checkpoint_to_buffer(schema, out);
  if (!first.ok()) return fail(state, "checkpoint_to_buffer", first);
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint_to_buffer(schema, out);
    if (!status.ok()) return fail(state, "checkpoint_to_buffer", status);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
  state.counters["checkpoint_bytes"] = static_cast<double>(out.size());
}

void pod_restore(benchmark::State& state, bool vector) {
  const std::size_t bytes = static_cast<std::size_t>(state.range(0));
  PodWorld& world = pod_world(bytes);
  const symcr::Schema& schema = vector ? world.vector_schema : world.array_schema;
  std::vector<std::uint8_t> in;
  const symcr::Status saved = symcr::checkpoint_to_buffer(schema, in);
  if (!saved.ok()) return fail(state, "checkpoint_to_buffer", saved);
  for (auto _ : state) {
    const symcr::Report report = symcr::restore_from_buffer(schema, in.data(), in.size());
    if (!report.ok()) return fail(state, "restore_from_buffer", report.status());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

void BM_PodArrayCheckpoint(benchmark::State& state) { pod_checkpoint(state, false); }
void BM_PodArrayRestore(benchmark::State& state) { pod_restore(state, false); }
void BM_PodVectorCheckpoint(benchmark::State& state) { pod_checkpoint(state, true); }
void BM_PodVectorRestore(benchmark::State& state) { pod_restore(state, true); }
BENCHMARK(BM_PodArrayCheckpoint)->Apply(pod_sizes);
BENCHMARK(BM_PodArrayRestore)->Apply(pod_sizes);
BENCHMARK(BM_PodVectorCheckpoint)->Apply(pod_sizes);
BENCHMARK(BM_PodVectorRestore)->Apply(pod_sizes);

// ---- pointer graphs ----------------------------------------------------------------------------
struct Node {
  std::int64_t value;
  Node* next;
  Node* jump;
};
struct Graph {
  Node* first;
  std::uint64_t count;
};
Graph graph;

const symcr::Schema& graph_schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(Node, value)),
                                          field("next", 2, offsetof(Node, next)),
                                          field("jump", 2, offsetof(Node, jump))};
  static const FieldInfo graph_fields[] = {field("first", 2, offsetof(Graph, first)),
                                           field("count", 3, offsetof(Graph, count))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      record("Node", sizeof(Node), alignof(Node), node_fields, 3,
             &symcr::ops::lifecycle<Node>::table),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      scalar("uint64", Kind::UInt, 8),
      record("Graph", sizeof(Graph), alignof(Graph), graph_fields, 2),
  };
  static const symcr::RootInfo roots[] = {{"graph", 4, &graph, 0, nullptr}};
  static const symcr::Schema schema{types, 5, roots, 1, nullptr};
  return schema;
}

// N separately allocated nodes (as a program's heap graph is): one cycle through `next`,
// `jump` to a pseudo-random shared target.
std::vector<Node*> build_graph(std::size_t count) {
  std::vector<Node*> nodes(count);
  for (std::size_t i = 0; i < count; ++i) nodes[i] = new Node{static_cast<std::int64_t>(i), nullptr, nullptr};
  for (std::size_t i = 0; i < count; ++i) {
    nodes[i]->next = nodes[(i + 1) % count];
    nodes[i]->jump = nodes[(i * 7919 + 13) % count];
  }
  return nodes;
}

void free_nodes(std::vector<Node*>& nodes) {
  for (Node* node : nodes) delete node;
  nodes.clear();
}

// The nodes a restore rebuilt: every node is on the `next` cycle from `first`.
std::size_t free_cycle(Node* first) {
  if (!first) return 0;
  std::vector<Node*> nodes;
  Node* node = first;
  do {
    nodes.push_back(node);
    node = node->next;
  } while (node && node != first && nodes.size() < (std::size_t{1} << 26));
  const std::size_t count = nodes.size();
  free_nodes(nodes);
  return count;
}

void graph_sizes(benchmark::internal::Benchmark* b) {
  for (std::int64_t nodes = 1000; nodes <= 1000000; nodes *= 10) b->Arg(nodes);
  b->Unit(benchmark::kMillisecond);
}

void BM_GraphCheckpoint(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  std::vector<Node*> nodes = build_graph(count);
  graph = Graph{nodes[0], count};
  std::vector<std::uint8_t> out;
  const symcr::Status first = symcr::checkpoint_to_buffer(graph_schema(), out);  // steady state
  if (!first.ok()) return fail(state, "checkpoint_to_buffer", first);
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint_to_buffer(graph_schema(), out);
    if (!status.ok()) {
      fail(state, "checkpoint_to_buffer", status);
      break;
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["checkpoint_bytes"] = static_cast<double>(out.size());
  state.counters["bytes_per_node"] = static_cast<double>(out.size()) / static_cast<double>(count);
  state.counters["scratch_bytes"] =
      static_cast<double>(symcr::detail::thread_scratch_bytes().checkpoint);
  graph = Graph{nullptr, 0};
  free_nodes(nodes);
}
BENCHMARK(BM_GraphCheckpoint)->Apply(graph_sizes);

void BM_GraphRestore(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  std::vector<std::uint8_t> in;
  {
    std::vector<Node*> nodes = build_graph(count);
    graph = Graph{nodes[0], count};
    const symcr::Status status = symcr::checkpoint_to_buffer(graph_schema(), in);
    free_nodes(nodes);
    if (!status.ok()) return fail(state, "checkpoint_to_buffer", status);
  }
  std::size_t rebuilt = 0;
  for (auto _ : state) {
    graph = Graph{nullptr, 0};  // restore into an empty root: every node is rebuilt
    const symcr::Report report = symcr::restore_from_buffer(graph_schema(), in.data(), in.size());
    state.PauseTiming();
    rebuilt = free_cycle(graph.first);
    graph = Graph{nullptr, 0};
    state.ResumeTiming();
    if (!report.ok()) return fail(state, "restore_from_buffer", report.status());
  }
  if (rebuilt != count) {
    state.SkipWithError("restore did not rebuild the whole cycle");
  }
  state.counters["checkpoint_bytes"] = static_cast<double>(in.size());
  state.counters["scratch_bytes"] =
      static_cast<double>(symcr::detail::thread_scratch_bytes().restore);
}
BENCHMARK(BM_GraphRestore)->Apply(graph_sizes);

// ---- std::map ----------------------------------------------------------------------------------
using Map = std::map<std::int64_t, double>;
using MapPair = std::pair<std::int64_t, double>;  // what the generator describes (ops::element_t)
Map table;

const symcr::Schema& map_schema() {
  static const FieldInfo pair_fields[] = {
      field("first", 0, symcr::ops::offset_of(&MapPair::first)),
      field("second", 1, symcr::ops::offset_of(&MapPair::second))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      scalar("float64", Kind::Float, 8),
      record("std::pair<int64,float64>", sizeof(MapPair), alignof(MapPair), pair_fields, 2,
             &symcr::ops::lifecycle<MapPair>::table),
      holder("std::map<int64,float64>", Kind::Container, sizeof(Map), alignof(Map), 2,
             &symcr::ops::container<Map>::table, symcr::ContainerKind::Map),
  };
  static const symcr::RootInfo roots[] = {{"table", 3, &table, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

void fill_map(std::size_t count) {
  table.clear();
  for (std::size_t i = 0; i < count; ++i) {
    table.emplace(static_cast<std::int64_t>(i * 2654435761u % 1000003u) * 1000 +
                      static_cast<std::int64_t>(i),
                  static_cast<double>(i) * 0.25);
  }
}

void BM_MapCopy(benchmark::State& state) {
  fill_map(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    Map copy = table;
    benchmark::DoNotOptimize(copy);
  }
  table.clear();
}
BENCHMARK(BM_MapCopy)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_MapCheckpoint(benchmark::State& state) {
  fill_map(static_cast<std::size_t>(state.range(0)));
  std::vector<std::uint8_t> out;
  for (auto _ : state) {
    const symcr::Status status = symcr::checkpoint_to_buffer(map_schema(), out);
    if (!status.ok()) return fail(state, "checkpoint_to_buffer", status);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["checkpoint_bytes"] = static_cast<double>(out.size());
  table.clear();
}
BENCHMARK(BM_MapCheckpoint)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_MapRestore(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  fill_map(count);
  std::vector<std::uint8_t> in;
  const symcr::Status status = symcr::checkpoint_to_buffer(map_schema(), in);
  if (!status.ok()) return fail(state, "checkpoint_to_buffer", status);
  for (auto _ : state) {
    state.PauseTiming();
    table.clear();  // restore into an empty map, as at start-up
    state.ResumeTiming();
    const symcr::Report report = symcr::restore_from_buffer(map_schema(), in.data(), in.size());
    if (!report.ok()) return fail(state, "restore_from_buffer", report.status());
  }
  if (table.size() != count) state.SkipWithError("wrong number of entries restored");
  table.clear();
}
BENCHMARK(BM_MapRestore)->Arg(100000)->Unit(benchmark::kMillisecond);

// ---- --memory <nodes> ----------------------------------------------------------------------------
long status_kb(const char* key) {
  FILE* file = std::fopen("/proc/self/status", "r");
  if (!file) return -1;
  char line[256];
  long value = -1;
  const std::size_t length = std::strlen(key);
  while (std::fgets(line, sizeof line, file)) {
    if (std::strncmp(line, key, length) == 0 && line[length] == ':') {
      value = std::strtol(line + length + 1, nullptr, 10);
      break;
    }
  }
  std::fclose(file);
  return value;
}

// Resets VmHWM to the current RSS (Linux >= 4.0); false when not permitted.
bool reset_peak() {
  FILE* file = std::fopen("/proc/self/clear_refs", "w");
  if (!file) return false;
  const bool ok = std::fputs("5", file) >= 0;
  return std::fclose(file) == 0 && ok;
}

struct Times {
  double wall_ms, cpu_ms;
};
Times now() {
  timespec wall{}, cpu{};
  clock_gettime(CLOCK_MONOTONIC, &wall);
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
  return {static_cast<double>(wall.tv_sec) * 1e3 + static_cast<double>(wall.tv_nsec) / 1e6,
          static_cast<double>(cpu.tv_sec) * 1e3 + static_cast<double>(cpu.tv_nsec) / 1e6};
}

int memory_main(std::size_t count) {
  std::vector<Node*> nodes = build_graph(count);
  graph = Graph{nodes[0], count};
  std::vector<std::uint8_t> out;
  const bool reset = reset_peak();
  const long before = status_kb("VmRSS");
  const Times t0 = now();
  const symcr::Status status = symcr::checkpoint_to_buffer(graph_schema(), out);
  const Times t1 = now();
  const long checkpoint_peak = status_kb("VmHWM");
  if (!status.ok()) {
    std::fprintf(stderr, "checkpoint: %s\n", status.message());
    return 1;
  }
  graph = Graph{nullptr, 0};
  free_nodes(nodes);
  std::vector<Node*>().swap(nodes);
  reset_peak();
  const long restore_before = status_kb("VmRSS");
  const Times t2 = now();
  const symcr::Report report = symcr::restore_from_buffer(graph_schema(), out.data(), out.size());
  const Times t3 = now();
  const long restore_peak = status_kb("VmHWM");
  const long restore_after = status_kb("VmRSS");
  if (!report.ok()) {
    std::fprintf(stderr, "restore: %s\n", report.status().message());
    return 1;
  }
  const std::size_t rebuilt = free_cycle(graph.first);
  std::printf(
      "{\"nodes\": %zu, \"peak_reset\": %s, \"checkpoint_bytes\": %zu, "
      "\"checkpoint_peak_delta_kb\": %ld, \"restore_peak_delta_kb\": %ld, "
      "\"restore_retained_kb\": %ld, \"rebuilt\": %zu, \"first_checkpoint_wall_ms\": %.3f, "
      "\"first_checkpoint_cpu_ms\": %.3f, \"first_restore_wall_ms\": %.3f, "
      "\"first_restore_cpu_ms\": %.3f}\n",
      count, reset ? "true" : "false", out.size(), checkpoint_peak - before,
      restore_peak - restore_before, restore_after - restore_before, rebuilt,
      t1.wall_ms - t0.wall_ms, t1.cpu_ms - t0.cpu_ms, t3.wall_ms - t2.wall_ms,
      t3.cpu_ms - t2.cpu_ms);
  return rebuilt == count ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--memory") == 0) {
    return memory_main(static_cast<std::size_t>(std::strtoull(argv[2], nullptr, 10)));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
