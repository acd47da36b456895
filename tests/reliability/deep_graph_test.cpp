// Pointer graphs and container nesting of any depth never overflow the stack:
//   - a 10^6-node linked list through raw pointers saves and restores (heap objects are
//     serialised breadth-first, so a pointer hop is never a recursion);
//   - a container chain nested 10^5 deep is refused at save, cleanly, at the format's nesting
//     limit (docs/format.md §3), and one within the limit round-trips;
//   - a crafted payload nesting 10^6 levels is refused by restore and by the reader-less
//     decoder (symcr inspect), with the live state untouched;
//   - at the deepest nesting the format allows, save, restore and the decoder fit in a 1 MiB
//     thread stack (optimised, uninstrumented builds), as an embedded task's might be;
//   - struct nesting and container nesting share the one limit: a crafted file nesting 250
//     structs inside each of many containers is refused within that stack, and a schema whose
//     types nest by value past the limit, or contain themselves by value, is refused.
// The 10^6-node *cyclic* graph with sharing is EnginePerformance.MillionNodeCyclicGraph.
#include <gtest/gtest.h>
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "parsed_schema.hpp"
#include "payload_grammar.hpp"
#include "reliability_schemas.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"
#include "visit.hpp"

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
  std::vector<std::uint8_t> payload(
      run.buffer.begin() + 56 + symcr::format::load32(run.buffer.data() + 40), run.buffer.end());
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
  EXPECT_NE(std::strstr(saved.message(), "nesting limit"), nullptr) << saved.message();
  dismantle_chain(chain);
}

// A payload for chain_schema() nesting `depth` levels: value, count 1, value, count 1, ...
std::vector<std::uint8_t> nested_payload(std::size_t depth) {
  std::vector<std::uint8_t> payload(depth * 8 + 8 + 8);
  std::uint8_t* p = payload.data();
  for (std::size_t level = 0; level < depth; ++level, p += 8) {
    symcr::format::store32(p, static_cast<std::uint32_t>(level));
    symcr::format::store32(p + 4, 1);
  }
  symcr::format::store32(p, 7);       // the innermost value
  symcr::format::store32(p + 4, 0);   // with no elements
  symcr::format::store32(p + 8, 0);   // heap count
  symcr::format::store32(p + 12, 0);  // reference count
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


// A writer schema as a hostile file carries it: State{S1 f}, S1{S2 f}, ..., S<depth-1>{
// std::vector<State> v}, serialised from tables and parsed back. Each State holds `depth` levels
// by value, and each vector element one more.
struct StructChainInContainers {
  explicit StructChainInContainers(std::uint32_t depth) {
    names.reserve(depth);
    for (std::uint32_t i = 0; i < depth; ++i) {
      names.push_back(i == 0 ? "State" : "S" + std::to_string(i));
    }
    for (std::uint32_t i = 0; i < depth; ++i) {
      fields.push_back(i + 1 < depth ? field("f", i + 1, 0) : field("v", depth, 0));
    }
    for (std::uint32_t i = 0; i < depth; ++i) {
      types.push_back(record(names[i].c_str(), 24, 8, &fields[i], 1));
    }
    types.push_back(holder("std::vector<State>", Kind::Container, 24, 8, 0, nullptr));
    root = symcr::RootInfo{"state", 0, nullptr, 0, nullptr};
    const symcr::Schema tables{types.data(), static_cast<std::uint32_t>(types.size()), &root, 1,
                               nullptr};
    std::vector<std::uint8_t> bytes;
    symcr::detail::serialise_schema(tables, bytes);
    parsed = symcr::detail::parse_schema(bytes.data(), bytes.size(), writer);
  }
  // The root's payload: `levels` vectors of one element each, the innermost empty.
  static std::vector<std::uint8_t> payload(std::size_t levels) {
    std::vector<std::uint8_t> bytes(4 * levels + 12, 0);
    for (std::size_t i = 0; i < levels; ++i) symcr::format::store32(bytes.data() + 4 * i, 1);
    return bytes;  // then the empty vector, no heap objects, no references
  }
  std::vector<std::string> names;
  std::vector<FieldInfo> fields;
  std::vector<TypeInfo> types;
  symcr::RootInfo root{};
  symcr::detail::ParsedSchema writer;
  symcr::Status parsed;
};

// The reader: a program whose root is also named `state` (its types need not match).
struct Reader {
  std::int64_t counter;
};
Reader reader_state;
const symcr::Schema& reader_schema() {
  static const FieldInfo fields[] = {field("counter", 0, offsetof(Reader, counter))};
  static const TypeInfo types[] = {scalar("int64", Kind::Int, 8),
                                   record("State", sizeof(Reader), alignof(Reader), fields, 1)};
  static const symcr::RootInfo roots[] = {{"state", 1, &reader_state, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  return schema;
}

bool refused_for_nesting(const symcr::Status& status) {
  return status.error() == symcr::Error::Corrupt &&
         std::strstr(status.message(), "nesting limit") != nullptr;
}

struct NestedRefusal {
  const StructChainInContainers* chain;
  const std::vector<std::uint8_t>* payload;
  bool restore_refused = false;
  bool state_untouched = false;
  bool decoder_refused = false;
};

void* restore_and_decode(void* argument) {
  auto& run = *static_cast<NestedRefusal*>(argument);
  reader_state.counter = 42;
  const symcr::Report report = symcr::detail::restore_payload(
      run.chain->writer.schema(), run.chain->writer.hash(), run.payload->data(),
      run.payload->size(), reader_schema(), {});
  run.restore_refused = refused_for_nesting(report.status());
  run.state_untouched = reader_state.counter == 42;
  CountingVisitor visitor;
  run.decoder_refused = refused_for_nesting(symcr::detail::visit_payload(
      run.chain->writer.schema(), run.payload->data(), run.payload->size(), visitor));
  return nullptr;
}

TEST(DeepGraph, StructNestingTimesContainerNestingIsRefusedWithinASmallStack) {
  const StructChainInContainers chain(250);
  ASSERT_TRUE(chain.parsed.ok()) << chain.parsed.message();
  // 250 levels for the root, 251 for each element: 7 vectors deep is within the limit.
  CountingVisitor within;
  const std::vector<std::uint8_t> shallow = StructChainInContainers::payload(7);
  EXPECT_TRUE(symcr::detail::visit_payload(chain.writer.schema(), shallow.data(), shallow.size(),
                                           within)
                  .ok());
  const std::vector<std::uint8_t> past = StructChainInContainers::payload(8);
  EXPECT_TRUE(refused_for_nesting(
      symcr::detail::visit_payload(chain.writer.schema(), past.data(), past.size(), within)));

  // 1000 vectors deep: 250,000 levels of recursion unless refused. In a child process, so that
  // a stack overflow fails this test only.
  const std::vector<std::uint8_t> deep = StructChainInContainers::payload(1000);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    pthread_attr_setstacksize(&attributes, kSmallStack);
    NestedRefusal run{&chain, &deep};
    pthread_t thread;
    if (pthread_create(&thread, &attributes, restore_and_decode, &run) != 0) ::_exit(3);
    pthread_join(thread, nullptr);
    ::_exit(run.restore_refused && run.state_untouched && run.decoder_refused ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status)) << "the child died of signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "not refused for its nesting, or the state changed";
}

TEST(DeepGraph, SchemaNestingByValuePastTheLimitIsRefusedInAnyTypeOrder) {
  // Type i holds type i - 1: visited from type 0 up, every type is met after its field's.
  constexpr std::uint32_t kTypes = symcr::detail::kMaxValueNesting + 10;
  std::vector<std::string> names;
  for (std::uint32_t i = 0; i < kTypes; ++i) names.push_back("T" + std::to_string(i));
  std::vector<FieldInfo> fields;
  for (std::uint32_t i = 0; i < kTypes; ++i) fields.push_back(field("inner", i - 1, 0));
  std::vector<TypeInfo> types;
  types.push_back(scalar(names[0].c_str(), Kind::Int, 4));
  for (std::uint32_t i = 1; i < kTypes; ++i) {
    types.push_back(record(names[i].c_str(), 4, 4, &fields[i], 1));
  }
  const symcr::RootInfo root{"deep", kTypes - 1, nullptr, 0, nullptr};
  const symcr::Schema tables{types.data(), kTypes, &root, 1, nullptr};
  std::vector<std::uint8_t> bytes;
  symcr::detail::serialise_schema(tables, bytes);
  symcr::detail::ParsedSchema parsed;
  const symcr::Status status = symcr::detail::parse_schema(bytes.data(), bytes.size(), parsed);
  EXPECT_TRUE(refused_for_nesting(status)) << status.message();

  // Within the limit the same chain parses.
  const symcr::Schema shorter{types.data(), 1000, &root, 0, nullptr};
  bytes.clear();  // serialise_schema appends
  symcr::detail::serialise_schema(shorter, bytes);
  EXPECT_TRUE(symcr::detail::parse_schema(bytes.data(), bytes.size(), parsed).ok());

  // A type holding itself by value (through another) can have no value at all.
  fields[1] = field("inner", 2, 0);
  fields[2] = field("inner", 1, 0);
  const symcr::Schema cycle{types.data(), 3, &root, 0, nullptr};
  bytes.clear();
  symcr::detail::serialise_schema(cycle, bytes);
  const symcr::Status cyclic = symcr::detail::parse_schema(bytes.data(), bytes.size(), parsed);
  EXPECT_EQ(cyclic.error(), symcr::Error::Corrupt);
  EXPECT_NE(std::strstr(cyclic.message(), "contains itself by value"), nullptr)
      << cyclic.message();
}

}  // namespace
}  // namespace reliability
