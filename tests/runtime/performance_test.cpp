// The save and restore paths allocate nothing in a steady state, and the save's speed
// (printed; the timed targets live in benchmarks/): a ~300-byte state, and a 10^6-node cyclic
// pointer graph.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <time.h>

#include "encode.hpp"
#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "plan.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"

namespace {
bool counting = false;
std::size_t allocations = 0;
}  // namespace

// Counts allocations made while `counting` is set (this test binary only).
void* operator new(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  std::abort();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace engine_tests {
namespace {

// CPU time of this thread: the machine is shared, so wall time would measure the neighbours.
struct Clock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<Clock, duration>;
  static time_point now() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return time_point(duration(std::int64_t{now.tv_sec} * 1000000000 + now.tv_nsec));
  }
};

std::vector<g::Node> build_graph(std::size_t count) {
  std::vector<g::Node> nodes(count);
  for (std::size_t i = 0; i < count; ++i) {
    nodes[i].value = static_cast<std::int64_t>(i);
    nodes[i].next = &nodes[(i + 1) % count];           // one big cycle
    nodes[i].jump = &nodes[(i * 7919 + 13) % count];   // and shared targets
  }
  return nodes;
}

TEST(EnginePerformance, SavePathAllocatesNothingAfterTheFirstCall) {
  std::vector<std::uint8_t> out;
  // A state with containers, strings, a shared_ptr and heap pointers.
  std::vector<g::Node> nodes = build_graph(64);
  g::graph.first = nodes.data();
  b0::bag.vec = {1, 2, 3};
  b0::bag.map = {{"a", 1}};
  b0::bag.str = std::string(100, 'x');
  b0::bag.up.reset(new b0::Item{1, 2});
  // World C: heap nodes, a cycle, interior and outside pointers, a shared_ptr.
  static std::int32_t outside_value = 3;
  c0::world = c0::World();
  c0::Node* node = new c0::Node{1, nullptr, nullptr};
  node->next = node;
  c0::world.head = node;
  c0::world.into_node = &node->value;
  c0::world.outside = &outside_value;
  c0::world.target_ptr = &c0::world.nav.target[1];
  c0::world.navs.resize(3);
  c0::world.pick = &c0::world.navs[2];
  c0::world.s1 = std::make_shared<c0::Leaf>();
  c0::world.s2 = c0::world.s1;
  for (const symcr::Schema* schema :
       {&g::schema(), &b0::schema(), &p::schema(), &e0::schema(), &c0::schema()}) {
    ASSERT_TRUE(symcr::detail::encode_payload(*schema, out).ok());
    ASSERT_TRUE(symcr::detail::encode_payload(*schema, out).ok());
    allocations = 0;
    counting = true;
    const symcr::Status status = symcr::detail::encode_payload(*schema, out);
    counting = false;
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(allocations, 0u) << schema->roots[0].name;
  }
  g::graph.first = nullptr;
  c0::world = c0::World();
  delete node;
}

TEST(EnginePerformance, RestorePathAllocatesNothingAfterTheFirstCalls) {
  // Pointers into the state's own root and a container: the general decoder (not the copy-only
  // payload path), with no heap object to create. Its tables are the thread's kept ones.
  c0::world = c0::World();
  c0::world.target_ptr = &c0::world.nav.target[2];
  c0::world.lon_ptr = &c0::world.nav.lon;
  c0::world.navs.resize(3);
  c0::world.pick = &c0::world.navs[1];
  const Saved saved = save(c0::schema());
  auto restore = [&saved] {
    return symcr::detail::restore_payload(c0::schema(), saved.hash, saved.payload.data(),
                                          saved.payload.size(), c0::schema(), {});
  };
  ASSERT_TRUE(restore().ok());
  ASSERT_TRUE(restore().ok());
  c0::world.pick = nullptr;
  allocations = 0;
  counting = true;
  const symcr::Report report = restore();
  counting = false;
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(c0::world.pick, &c0::world.navs[1]);  // restored, not skipped
  c0::world = c0::World();
}

TEST(EnginePerformance, PlansAreCachedPerWriterAndReader) {
  const auto& blob = symcr::detail::schema_blob(a0::schema());
  symcr::Status status;
  const auto first = symcr::detail::plan_for(a0::schema(), blob.hash, a1::schema(), status);
  const auto second = symcr::detail::plan_for(a0::schema(), blob.hash, a1::schema(), status);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first.get(), second.get());
  const auto other = symcr::detail::plan_for(a0::schema(), blob.hash, a0::schema(), status);
  EXPECT_NE(first.get(), other.get());
}

TEST(EnginePerformance, SmallStateEncodesFast) {
  std::vector<std::uint8_t> out;
  for (int i = 0; i < 10; ++i) p::state.pids[i].limit = static_cast<std::int16_t>(i);
  ASSERT_TRUE(symcr::detail::encode_payload(p::schema(), out).ok());
  constexpr int kRounds = 100000;
  const auto start = Clock::now();
  for (int i = 0; i < kRounds; ++i) symcr::detail::encode_payload(p::schema(), out);
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kRounds;
  std::printf("[ perf ] encode %zu-byte state (%zu bytes of payload): %.0f ns\n",
              sizeof(p::State), out.size(), ns);
  const Saved saved = save(p::schema());
  const auto restore_start = Clock::now();
  constexpr int kRestores = 10000;
  for (int i = 0; i < kRestores; ++i) {
    symcr::detail::restore_payload(p::schema(), saved.hash, saved.payload.data(),
                                   saved.payload.size(), p::schema(), {});
  }
  const double restore_ns =
      std::chrono::duration<double, std::nano>(Clock::now() - restore_start).count() / kRestores;
  std::printf("[ perf ] restore it (same build, cached plan): %.0f ns\n", restore_ns);
  EXPECT_LT(ns, 50000.0);  // generous: sanitizer builds run here too
}

TEST(EnginePerformance, MillionNodeCyclicGraph) {
#if defined(__SANITIZE_ADDRESS__)
  constexpr std::size_t kNodes = 100000;  // sanitizers are ~10x slower; the logic is the same
#else
  constexpr std::size_t kNodes = 1000000;
#endif
  std::vector<g::Node> nodes = build_graph(kNodes);
  g::graph.first = &nodes[0];
  g::graph.count = static_cast<std::int32_t>(kNodes);
  // The nodes live in one vector, but the schema only knows pointers: each is a heap object.
  std::vector<std::uint8_t> out;
  auto start = Clock::now();
  symcr::Status status = symcr::detail::encode_payload(g::schema(), out);
  const double first_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  ASSERT_TRUE(status.ok()) << status.message();
  start = Clock::now();
  status = symcr::detail::encode_payload(g::schema(), out);
  const double second_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::printf("[ perf ] encode %zu-node graph: %.0f ms first, %.0f ms steady (%zu bytes)\n",
              kNodes, first_ms, second_ms, out.size());

  const auto& blob = symcr::detail::schema_blob(g::schema());
  g::graph.first = nullptr;
  start = Clock::now();
  const symcr::Report report = symcr::detail::restore_payload(
      g::schema(), blob.hash, out.data(), out.size(), g::schema(), {});
  const double restore_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::printf("[ perf ] restore %zu-node graph: %.0f ms\n", kNodes, restore_ms);
  ASSERT_TRUE(report.ok()) << report.status().message();
  // Walk the restored cycle and check values and sharing.
  g::Node* node = g::graph.first;
  ASSERT_NE(node, nullptr);
  std::vector<g::Node*> restored(kNodes);
  for (std::size_t i = 0; i < kNodes; ++i) {
    ASSERT_EQ(node->value, static_cast<std::int64_t>(i));
    restored[i] = node;
    node = node->next;
  }
  EXPECT_EQ(node, g::graph.first);
  for (std::size_t i = 0; i < kNodes; i += 997) {
    EXPECT_EQ(restored[i]->jump, restored[(i * 7919 + 13) % kNodes]);
  }
  for (g::Node* n : restored) delete n;
  g::graph.first = nullptr;
  EXPECT_LT(second_ms, 20000.0);
}

}  // namespace
}  // namespace engine_tests
