// Pointer graphs and container nesting of any depth never overflow the stack:
//   - a 10^6-node linked list through raw pointers saves and restores (heap objects are
//     serialised breadth-first, so a pointer hop is never a recursion);
//   - a container chain nested 10^5 deep is refused at save, cleanly, at the format's nesting
//     limit (docs/format.md §3: 1000), and one within the limit round-trips;
//   - a crafted payload nesting 10^6 levels is refused by restore and by the reader-less
//     decoder (symcr inspect), with the live state untouched;
//   - at the deepest nesting the format allows, save, restore and the decoder fit in a 1 MiB
//     thread stack (optimised, uninstrumented builds), as an embedded task's might be.
// The 10^6-node *cyclic* graph with sharing is EnginePerformance.MillionNodeCyclicGraph.
#include <pthread.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "engine.hpp"
#include "little_endian.hpp"
#include "reliability_schemas.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

void free_list(ListNode* node) {
  while (node) {
    ListNode* next = node->next;
    delete node;
    node = next;
  }
}

TEST(DeepGraph, MillionNodeLinkedListThroughRawPointersRoundTrips) {
  constexpr std::int64_t kNodes = 1000000;
  ListNode* head = nullptr;
  for (std::int64_t i = kNodes - 1; i >= 0; --i) head = new ListNode{i * 3, head};
  list.head = head;
  list.length = kNodes;
  std::vector<std::uint8_t> buffer;
  const symcr::Status saved = symcr::checkpoint_to_buffer(list_schema(), buffer);
  ASSERT_TRUE(saved.ok()) << saved.message();

  list.head = nullptr;
  list.length = 0;
  const symcr::Report report = symcr::restore_from_buffer(list_schema(), buffer.data(), buffer.size());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(list.length, kNodes);
  std::int64_t count = 0;
  for (const ListNode* node = list.head; node; node = node->next, ++count) {
    ASSERT_EQ(node->value, count * 3);
  }
  EXPECT_EQ(count, kNodes);
  free_list(list.head);
  free_list(head);
  list = List{};
}

TEST(DeepGraph, ContainerChainWithinTheNestingLimitRoundTrips) {
  build_chain(chain, 900);
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(chain_schema(), buffer).ok());
  dismantle_chain(chain);
  const symcr::Report report = symcr::restore_from_buffer(chain_schema(), buffer.data(), buffer.size());
  ASSERT_TRUE(report.ok()) << report.to_text();
  const Chain* at = &chain;
  std::size_t depth = 0;
  while (!at->inner.empty()) {
    ASSERT_EQ(at->value, static_cast<std::int32_t>(depth));
    at = &at->inner[0];
    ++depth;
  }
  EXPECT_EQ(depth, 900u);
  dismantle_chain(chain);
}

// Sanitizers and -O0 make frames several times larger: the bound is for optimised builds.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || !defined(__OPTIMIZE__)
constexpr std::size_t kSmallStack = std::size_t{64} << 20;
#else
constexpr std::size_t kSmallStack = std::size_t{1} << 20;
#endif

struct DeepestChainRun {
  std::size_t depth = 0;           // the deepest chain that saved
  std::vector<std::uint8_t> buffer;
  bool restored = false;
  std::size_t restored_depth = 0;
  bool decoded = false;
};

void* save_and_restore_deepest_chain(void* argument) {
  auto& run = *static_cast<DeepestChainRun*>(argument);
  for (std::size_t depth = 1001; depth > 990 && run.depth == 0; --depth) {
    build_chain(chain, depth);
    if (symcr::checkpoint_to_buffer(chain_schema(), run.buffer).ok()) run.depth = depth;
    dismantle_chain(chain);
  }
  if (run.depth == 0) return nullptr;
  const symcr::Report report =
      symcr::restore_from_buffer(chain_schema(), run.buffer.data(), run.buffer.size());
  run.restored = report.ok();
  for (const Chain* at = &chain; !at->inner.empty(); at = &at->inner[0]) ++run.restored_depth;
  dismantle_chain(chain);
  struct LeafCounter : symcr::detail::ValueVisitor {
    void leaf(const char*, const symcr::TypeInfo&, const std::uint8_t*, std::size_t,
              const char*) override {
      ++leaves;
    }
    std::size_t leaves = 0;
  } visitor;
  std::vector<std::uint8_t> payload(run.buffer.begin() + 56 + symcr::detail::le::load32(run.buffer.data() + 40),
                                    run.buffer.end());
  run.decoded = symcr::detail::visit_payload(chain_schema(), payload.data(), payload.size(),
                                             visitor).ok() &&
                visitor.leaves == run.depth + 1;  // one value per level
  return nullptr;
}

TEST(DeepGraph, DeepestAllowedNestingFitsInASmallThreadStack) {
  pthread_attr_t attributes;
  ASSERT_EQ(pthread_attr_init(&attributes), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attributes, kSmallStack), 0);
  DeepestChainRun run;
  pthread_t thread;
  ASSERT_EQ(pthread_create(&thread, &attributes, save_and_restore_deepest_chain, &run), 0);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  pthread_attr_destroy(&attributes);
  ASSERT_GE(run.depth, 999u) << "no chain near the nesting limit (1000) saved";
  EXPECT_TRUE(run.restored);
  EXPECT_EQ(run.restored_depth, run.depth);
  EXPECT_TRUE(run.decoded);
}

TEST(DeepGraph, ContainerChainHundredThousandDeepIsRefusedAtSaveWithoutRecursing) {
  build_chain(chain, 100000);
  std::vector<std::uint8_t> buffer;
  const symcr::Status saved = symcr::checkpoint_to_buffer(chain_schema(), buffer);
  EXPECT_FALSE(saved.ok());
  EXPECT_NE(std::strstr(saved.message(), "1000"), nullptr) << saved.message();
  dismantle_chain(chain);
}

// A payload for chain_schema() nesting `depth` levels: value, count 1, value, count 1, ...
std::vector<std::uint8_t> nested_payload(std::size_t depth) {
  std::vector<std::uint8_t> payload(depth * 8 + 8 + 8);
  std::uint8_t* p = payload.data();
  for (std::size_t level = 0; level < depth; ++level, p += 8) {
    symcr::detail::le::store32(p, static_cast<std::uint32_t>(level));
    symcr::detail::le::store32(p + 4, 1);
  }
  symcr::detail::le::store32(p, 7);      // the innermost value
  symcr::detail::le::store32(p + 4, 0);  // with no elements
  symcr::detail::le::store32(p + 8, 0);  // heap count
  symcr::detail::le::store32(p + 12, 0);  // reference count
  return payload;
}

struct CountingVisitor : symcr::detail::ValueVisitor {
  std::size_t leaves = 0;
  void leaf(const char*, const symcr::TypeInfo&, const std::uint8_t*, std::size_t,
            const char*) override {
    ++leaves;
  }
};

TEST(DeepGraph, CraftedMillionLevelNestingIsRefusedByRestoreAndByTheDecoder) {
  const symcr::detail::SchemaBlob& blob = symcr::detail::schema_blob(chain_schema());
  symcr::detail::ParsedSchema writer;
  ASSERT_TRUE(symcr::detail::parse_schema(blob.data, blob.size, writer).ok());

  // Sanity: a shallow crafted payload is accepted, so the deep one fails for its depth.
  std::vector<std::uint8_t> shallow = nested_payload(10);
  chain = Chain{};
  symcr::Report report = symcr::detail::restore_payload(writer.schema(), blob.hash, shallow.data(),
                                                        shallow.size(), chain_schema(), {});
  ASSERT_TRUE(report.ok()) << report.to_text();
  dismantle_chain(chain);

  const std::vector<std::uint8_t> deep = nested_payload(1000000);
  chain.value = 55;
  report = symcr::detail::restore_payload(writer.schema(), blob.hash, deep.data(), deep.size(),
                                          chain_schema(), {});
  EXPECT_EQ(report.status().error(), symcr::Error::Corrupt) << report.to_text();
  EXPECT_EQ(chain.value, 55);
  EXPECT_TRUE(chain.inner.empty());

  CountingVisitor visitor;
  const symcr::Status visited =
      symcr::detail::visit_payload(writer.schema(), deep.data(), deep.size(), visitor);
  EXPECT_FALSE(visited.ok());
  chain = Chain{};
}

}  // namespace
}  // namespace reliability
