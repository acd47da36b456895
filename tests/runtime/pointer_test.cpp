// Pointers restored symbolically (docs/resolution.md). World C saves a cyclic graph of heap nodes
// with sharing, pointers into a root's fields, into an array element and into a container
// element, a null, an outside pointer and a shared_ptr held twice; the reader build moved every
// one of those fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <string>

#include "encode.hpp"
#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "visit.hpp"

namespace engine_tests {
namespace {

using symcr::Decision;

std::int32_t writer_static = 5;   // static storage outside the checkpointed state
std::int32_t reader_static = 6;

struct WriterGraph {
  c0::Node* n1;
  c0::Node* n2;
};

WriterGraph build_writer_world() {
  c0::World& w = c0::world;
  w.nav = c0::Nav{1.5, 2.5, {10, 11, 12, 13}};
  w.navs = {c0::Nav{3.5, 4.5, {20, 21, 22, 23}}, c0::Nav{5.5, 6.5, {30, 31, 32, 33}}};
  auto* n1 = new c0::Node{100, nullptr, nullptr};
  auto* n2 = new c0::Node{200, nullptr, nullptr};
  n1->next = n2;
  n2->next = n1;  // a cycle
  n1->other = n1;
  n2->other = n2;
  w.head = n1;
  w.target_ptr = &w.nav.target[2];
  w.lon_ptr = &w.nav.lon;
  w.pick = &w.navs[1];
  w.again = n2;  // a second pointer to the same node
  w.outside = &writer_static;
  w.null_ptr = nullptr;
  w.s1 = std::make_shared<c0::Leaf>(c0::Leaf{77});
  w.s2 = w.s1;
  w.into_node = &n1->value;
  return {n1, n2};
}

void free_writer_world(const WriterGraph& graph) {
  c0::world = c0::World();  // no dangling pointers left for later tests
  delete graph.n1;
  delete graph.n2;
}

void free_reader_nodes() {
  c1::World& r = c1::world;
  c1::Node* first = r.head;
  c1::Node* second = first ? first->next : nullptr;
  delete first;
  if (second != first) delete second;
  r.head = r.again = nullptr;
  r.s1.reset();
  r.s2.reset();
}

TEST(WorldC, PointerGraphIsRestoredSymbolically) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);

  c1::world = c1::World();
  c1::world.outside = &reader_static;
  c1::world.null_ptr = reinterpret_cast<c1::Node*>(&reader_static);  // must become null
  const symcr::Report report = load(saved, c1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  const c1::World& r = c1::world;

  // Fields the pointers target moved; the pointers follow by name.
  EXPECT_EQ(r.nav.lat, 1.5);
  EXPECT_EQ(r.nav.lon, 2.5);
  EXPECT_EQ(r.nav.target[2], 12);
  EXPECT_EQ(r.target_ptr, &r.nav.target[2]);
  EXPECT_EQ(r.lon_ptr, &r.nav.lon);
  ASSERT_EQ(r.navs.size(), 2u);
  EXPECT_EQ(r.pick, &r.navs[1]);
  EXPECT_EQ(r.navs[1].lat, 5.5);

  // The heap graph: cycle and sharing preserved, new fields at the new build's defaults.
  ASSERT_NE(r.head, nullptr);
  EXPECT_EQ(r.head->value, 100);
  EXPECT_EQ(r.head->tag, 9);
  ASSERT_NE(r.head->next, nullptr);
  EXPECT_EQ(r.head->next->value, 200);
  EXPECT_EQ(r.head->next->next, r.head);
  EXPECT_EQ(r.head->other, r.head);
  EXPECT_EQ(r.head->next->other, r.head->next);
  EXPECT_EQ(r.again, r.head->next);
  EXPECT_EQ(r.into_node, &r.head->value);

  // Null stays null; outside keeps the new build's value and says so.
  EXPECT_EQ(r.null_ptr, nullptr);
  EXPECT_EQ(r.outside, &reader_static);
  expect_entry(report, "world.outside", Decision::Kept, "outside the checkpointed state", 0);

  // shared_ptr sharing kept, pointee converted int32 -> int64.
  ASSERT_NE(r.s1, nullptr);
  EXPECT_EQ(r.s1, r.s2);
  EXPECT_EQ(r.s1.use_count(), 2);
  EXPECT_EQ(r.s1->payload, 77);
  expect_entry(report, "(Leaf).payload", Decision::Converted, "int32 -> int64");
  free_reader_nodes();
}

TEST(WorldC, LiveObjectsOfTheNewBuildAreFilledInsteadOfAllocated) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);

  c1::world = c1::World();
  auto* preallocated = new c1::Node();
  preallocated->tag = 1234;
  c1::world.head = preallocated;
  const symcr::Report report = load(saved, c1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(c1::world.head, preallocated);  // claimed, not reallocated
  EXPECT_EQ(preallocated->value, 100);
  EXPECT_EQ(preallocated->tag, 1234);       // a field the checkpoint lacks keeps its value
  EXPECT_EQ(preallocated->next->next, preallocated);
  EXPECT_NE(preallocated->next, preallocated);
  free_reader_nodes();
}

TEST(WorldC, AnObjectInsideARootIsNeverClaimed) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);
  c1::world = c1::World();
  // A pointer into the root itself: claiming it would overwrite the root's bytes.
  c1::world.head = reinterpret_cast<c1::Node*>(&c1::world.nav);
  const symcr::Report report = load(saved, c1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_NE(static_cast<void*>(c1::world.head), static_cast<void*>(&c1::world.nav));
  EXPECT_EQ(c1::world.head->value, 100);
  free_reader_nodes();
}

TEST(WorldC, IdentityRestoreKeepsTheGraph) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);
  c0::world = c0::World();
  const symcr::Report report = load(saved, c0::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  c0::World& w = c0::world;
  EXPECT_EQ(w.head->next->next, w.head);
  EXPECT_EQ(w.into_node, &w.head->value);
  EXPECT_EQ(w.target_ptr, &w.nav.target[2]);
  EXPECT_EQ(w.pick, &w.navs[1]);
  EXPECT_EQ(w.s1, w.s2);
  EXPECT_EQ(w.s1->payload, 77);
  delete w.head->next;
  delete w.head;
  w.head = w.again = nullptr;
  w.into_node = nullptr;
  w.s1.reset();
  w.s2.reset();
}

TEST(WorldC, PointerIntoAHeapObjectMetBeforeTheObjectIsFolded) {
  // into_node (&node->value, the node's own address) is met before node: the save makes the
  // Node the heap object and into_node a path into it, not an int32 object of its own.
  auto* node = new c0::Node{41, nullptr, nullptr};
  node->next = node;
  c_interior::holder.node = node;
  c_interior::holder.into_node = &node->value;
  const Saved saved = save(c_interior::schema());
  c_interior::holder = {};
  const symcr::Report report = load(saved, c_interior::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(report.count(symcr::Decision::Rejected), 0u) << report.to_text();
  c0::Node* restored = c_interior::holder.node;
  ASSERT_NE(restored, nullptr);
  EXPECT_NE(restored, node);
  EXPECT_EQ(restored->value, 41);
  EXPECT_EQ(restored->next, restored);
  EXPECT_EQ(c_interior::holder.into_node, &restored->value);
  delete restored;
  delete node;
  c_interior::holder = {};
}

TEST(WorldC, PointerBetweenAHeapObjectsMembersIsRefused) {
  // An int32* two bytes into node->value: the Node encloses it, but no int32 member starts
  // there, so it cannot be a path into the Node: refused, naming both, and nothing written.
  auto* node = new c0::Node{1, nullptr, nullptr};
  c_interior::holder.node = node;
  c_interior::holder.into_node =
      reinterpret_cast<std::int32_t*>(reinterpret_cast<char*>(&node->value) + 2);
  std::vector<std::uint8_t> payload;
  const symcr::Status status = symcr::detail::encode_payload(c_interior::schema(), payload);
  EXPECT_EQ(status.error(), symcr::Error::Unsupported);
  EXPECT_NE(std::string(status.message()).find("a pointer to int32"), std::string::npos)
      << status.message();
  EXPECT_NE(std::string(status.message()).find("(Node) but not at a int32 subobject"),
            std::string::npos)
      << status.message();
  EXPECT_TRUE(payload.empty());
  delete node;
  c_interior::holder = {};
}

struct Leaves : symcr::detail::ValueVisitor {
  std::vector<std::string> lines;
  void leaf(const char* path, const symcr::TypeInfo& type, const std::uint8_t*, std::size_t size,
            const char* text) override {
    lines.push_back(std::string(path) + " " + type.name + " " + std::to_string(size) +
                    (text ? std::string(" ") + text : std::string()));
  }
};

TEST(WorldC, VisitNamesLeavesAndPointerTargets) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);
  Leaves leaves;
  const symcr::Status status = symcr::detail::visit_payload(c0::schema(), saved.payload.data(),
                                                            saved.payload.size(), leaves);
  ASSERT_TRUE(status.ok()) << status.message();
  auto has = [&](const std::string& line) {
    for (const auto& l : leaves.lines) {
      if (l == line) return true;
    }
    return false;
  };
  EXPECT_TRUE(has("world.nav.lat float64 8")) << ::testing::PrintToString(leaves.lines);
  EXPECT_TRUE(has("world.navs[1].target[3] int32 4"));
  EXPECT_TRUE(has("world.target_ptr int32* 4 -> world.nav.target[2]"));
  EXPECT_TRUE(has("world.pick Nav* 4 -> world.navs[1]"));
  EXPECT_TRUE(has("world.head Node* 4 -> heap#0(Node)"));
  EXPECT_TRUE(has("world.into_node int32* 4 -> heap#0(Node).value"));
  EXPECT_TRUE(has("world.outside int32* 4 outside"));
  EXPECT_TRUE(has("world.null_ptr Node* 4 null"));
  EXPECT_TRUE(has("heap#0(Node).value int32 4"));
  // Truncated payloads are refused by the visitor too.
  Leaves ignored;
  EXPECT_FALSE(symcr::detail::visit_payload(c0::schema(), saved.payload.data(),
                                            saved.payload.size() - 1, ignored).ok());
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

// World C's reader with some fields of one type no longer described (as if removed).
struct ReaderWithoutFields {
  symcr::TypeInfo types[14];
  symcr::FieldInfo fields[16];
  symcr::Schema schema;

  ReaderWithoutFields(std::uint32_t type, std::initializer_list<std::string> removed) {
    const symcr::Schema& base = c1::schema();
    if (base.type_count > 14 || base.types[type].field_count > 16) std::abort();
    for (std::uint32_t t = 0; t < base.type_count; ++t) types[t] = base.types[t];
    std::uint32_t kept = 0;
    for (std::uint32_t f = 0; f < base.types[type].field_count; ++f) {
      const symcr::FieldInfo& field = base.types[type].fields[f];
      if (std::find(removed.begin(), removed.end(), field.name) == removed.end()) {
        fields[kept++] = field;
      }
    }
    types[type].fields = fields;
    types[type].field_count = kept;
    schema = symcr::Schema{types, base.type_count, base.roots, base.root_count, nullptr};
  }
};

// The reader of world C without Nav::lon.
const symcr::Schema& reader_without_lon() {
  static const ReaderWithoutFields reader(3, {"lon"});
  return reader.schema;
}

TEST(WorldC, PointerToARemovedFieldKeepsTheNewBuildsValue) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);
  c1::world = c1::World();
  double sentinel = 0;
  c1::world.lon_ptr = &sentinel;
  const symcr::Report report = load(saved, reader_without_lon());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(c1::world.lon_ptr, &sentinel);
  EXPECT_EQ(c1::world.target_ptr, &c1::world.nav.target[2]);
  expect_entry(report, "world.lon_ptr", Decision::Rejected, "target field lon removed", 1);
  expect_entry(report, "world.nav.lon", Decision::Dropped, "removed");
  EXPECT_EQ(load(saved, reader_without_lon(), /*strict=*/true).status().error(),
            symcr::Error::Strict);
  c1::world.lon_ptr = nullptr;
  free_reader_nodes();
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

struct SharedOnly {
  std::shared_ptr<c0::Leaf> a, b, c, none;
};
SharedOnly shared_only;

// A schema with shared_ptrs and no raw pointer (the save path then indexes no regions).
const symcr::Schema& shared_only_schema() {
  using symcr::ops::offset_of;
  static const symcr::FieldInfo leaf_fields[] = {field("payload", 0, offsetof(c0::Leaf, payload))};
  static const symcr::FieldInfo fields[] = {
      field("a", 2, offset_of(&SharedOnly::a)), field("b", 2, offset_of(&SharedOnly::b)),
      field("c", 2, offset_of(&SharedOnly::c)), field("none", 2, offset_of(&SharedOnly::none))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      record("Leaf", sizeof(c0::Leaf), alignof(c0::Leaf), leaf_fields, 1,
             &symcr::ops::lifecycle<c0::Leaf>::table),
      holder("std::shared_ptr<Leaf>", Kind::SharedPtr, sizeof(std::shared_ptr<c0::Leaf>),
             alignof(std::shared_ptr<c0::Leaf>), 1,
             &symcr::ops::shared_ptr<std::shared_ptr<c0::Leaf>>::table),
      record("SharedOnly", sizeof(SharedOnly), alignof(SharedOnly), fields, 4),
  };
  static const symcr::RootInfo roots[] = {{"shared", 3, &shared_only, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

TEST(WorldC, SharedPtrsWithoutRawPointersKeepSharing) {
  shared_only.a = std::make_shared<c0::Leaf>(c0::Leaf{1});
  shared_only.b = shared_only.a;
  shared_only.c = std::make_shared<c0::Leaf>(c0::Leaf{2});
  shared_only.none.reset();
  const Saved saved = save(shared_only_schema());
  shared_only = SharedOnly();
  shared_only.none = std::make_shared<c0::Leaf>(c0::Leaf{9});
  const symcr::Report report = load(saved, shared_only_schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  ASSERT_NE(shared_only.a, nullptr);
  EXPECT_EQ(shared_only.a, shared_only.b);
  EXPECT_EQ(shared_only.a.use_count(), 2);
  EXPECT_EQ(shared_only.a->payload, 1);
  ASSERT_NE(shared_only.c, nullptr);
  EXPECT_NE(shared_only.c, shared_only.a);
  EXPECT_EQ(shared_only.c->payload, 2);
  EXPECT_EQ(shared_only.c.use_count(), 1);
  EXPECT_EQ(shared_only.none, nullptr);
  shared_only = SharedOnly();
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

struct UHolder {
  std::unique_ptr<c0::Leaf> owned;
};
struct URoot {
  std::unique_ptr<c0::Leaf> owned;
  c0::Leaf* view;       // -> *owned (inside the root's unique_ptr)
  UHolder* holder;      // a heap object
  c0::Leaf* deep_view;  // -> *holder->owned (a unique_ptr inside a heap object)
};
URoot uroot;

const symcr::Schema& uroot_schema() {
  using symcr::ops::offset_of;
  static const symcr::FieldInfo leaf_fields[] = {field("payload", 0, offsetof(c0::Leaf, payload))};
  static const symcr::FieldInfo holder_fields[] = {field("owned", 2, offset_of(&UHolder::owned))};
  static const symcr::FieldInfo root_fields[] = {
      field("owned", 2, offset_of(&URoot::owned)), field("view", 3, offset_of(&URoot::view)),
      field("holder", 5, offset_of(&URoot::holder)),
      field("deep_view", 3, offset_of(&URoot::deep_view))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      record("Leaf", sizeof(c0::Leaf), alignof(c0::Leaf), leaf_fields, 1,
             &symcr::ops::lifecycle<c0::Leaf>::table),
      holder("std::unique_ptr<Leaf>", Kind::UniquePtr, sizeof(std::unique_ptr<c0::Leaf>),
             alignof(std::unique_ptr<c0::Leaf>), 1,
             &symcr::ops::unique_ptr<std::unique_ptr<c0::Leaf>>::table),
      holder("Leaf*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      record("UHolder", sizeof(UHolder), alignof(UHolder), holder_fields, 1,
             &symcr::ops::lifecycle<UHolder>::table),
      holder("UHolder*", Kind::Pointer, sizeof(void*), alignof(void*), 4, nullptr),
      record("URoot", sizeof(URoot), alignof(URoot), root_fields, 4),
  };
  static const symcr::RootInfo roots[] = {{"uroot", 6, &uroot, 0, nullptr}};
  static const symcr::Schema schema{types, 7, roots, 1, nullptr};
  return schema;
}

TEST(WorldC, PointersIntoUniquePtrPointeesFollowTheirOwner) {
  uroot.owned.reset(new c0::Leaf{11});
  uroot.view = uroot.owned.get();
  uroot.holder = new UHolder();
  uroot.holder->owned.reset(new c0::Leaf{22});
  uroot.deep_view = uroot.holder->owned.get();
  const Saved saved = save(uroot_schema());
  delete uroot.holder;
  uroot.owned.reset();
  uroot.view = uroot.deep_view = nullptr;
  uroot.holder = nullptr;

  const symcr::Report report = load(saved, uroot_schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  ASSERT_NE(uroot.owned, nullptr);
  EXPECT_EQ(uroot.owned->payload, 11);
  EXPECT_EQ(uroot.view, uroot.owned.get());
  ASSERT_NE(uroot.holder, nullptr);
  ASSERT_NE(uroot.holder->owned, nullptr);
  EXPECT_EQ(uroot.holder->owned->payload, 22);
  EXPECT_EQ(uroot.deep_view, uroot.holder->owned.get());
  delete uroot.holder;
  uroot = URoot();
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

TEST(WorldC, PointersToTheStackAndToConstantsAreOutside) {
  c0::world = c0::World();
  std::int32_t on_stack = 1;
  static const std::int32_t constant = 2;
  c0::world.outside = &on_stack;
  c0::world.into_node = const_cast<std::int32_t*>(&constant);
  const Saved saved = save(c0::schema());
  Leaves leaves;
  ASSERT_TRUE(symcr::detail::visit_payload(c0::schema(), saved.payload.data(), saved.payload.size(),
                                           leaves).ok());
  int outside = 0;
  for (const auto& line : leaves.lines) {
    if (line == "world.outside int32* 4 outside" || line == "world.into_node int32* 4 outside") {
      ++outside;
    }
  }
  EXPECT_EQ(outside, 2) << ::testing::PrintToString(leaves.lines);
  c0::world = c0::World();
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

// World C's reader without the fields that pointed to the heap nodes: nothing may be created.
const symcr::Schema& reader_without_node_pointers() {
  static const ReaderWithoutFields reader(12, {"head", "again", "into_node"});
  return reader.schema;
}

TEST(WorldC, HeapObjectsReachedOnlyThroughDroppedFieldsAreNotCreated) {
  const WriterGraph graph = build_writer_world();
  const Saved saved = save(c0::schema());
  free_writer_world(graph);
  c1::world = c1::World();
  const symcr::Report report = load(saved, reader_without_node_pointers());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(c1::world.head, nullptr);
  EXPECT_EQ(c1::world.again, nullptr);
  EXPECT_EQ(c1::world.target_ptr, &c1::world.nav.target[2]);
  expect_entry(report, "world.head", Decision::Dropped);
  // The sanitizer build's leak checker proves the nodes were never allocated.
  c1::world = c1::World();
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

struct MEntry {
  std::int32_t* p = nullptr;
  std::vector<std::int32_t*> many;
};
struct MRoot {
  std::int32_t values[4];
  std::map<std::int32_t, MEntry> map;
};
MRoot mroot;

const symcr::Schema& mroot_schema() {
  using symcr::ops::offset_of;
  using Pair = std::pair<std::int32_t, MEntry>;
  static const symcr::FieldInfo entry_fields[] = {field("p", 2, offset_of(&MEntry::p)),
                                                  field("many", 3, offset_of(&MEntry::many))};
  static const symcr::FieldInfo pair_fields[] = {field("first", 0, offset_of(&Pair::first)),
                                                 field("second", 4, offset_of(&Pair::second))};
  static const symcr::FieldInfo root_fields[] = {field("values", 1, offset_of(&MRoot::values)),
                                                 field("map", 6, offset_of(&MRoot::map))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      array("int32[4]", 0, 4, 16, 4),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      holder("std::vector<int32*>", Kind::Container, sizeof(std::vector<std::int32_t*>),
             alignof(std::vector<std::int32_t*>), 2,
             &symcr::ops::container<std::vector<std::int32_t*>>::table),
      record("MEntry", sizeof(MEntry), alignof(MEntry), entry_fields, 2,
             &symcr::ops::lifecycle<MEntry>::table),
      record("std::pair<int32,MEntry>", sizeof(Pair), alignof(Pair), pair_fields, 2,
             &symcr::ops::lifecycle<Pair>::table),
      holder("std::map<int32,MEntry>", Kind::Container, sizeof(std::map<std::int32_t, MEntry>),
             alignof(std::map<std::int32_t, MEntry>), 5,
             &symcr::ops::container<std::map<std::int32_t, MEntry>>::table,
             symcr::ContainerKind::Map),
      record("MRoot", sizeof(MRoot), alignof(MRoot), root_fields, 2),
  };
  static const symcr::RootInfo roots[] = {{"mroot", 7, &mroot, 0, nullptr}};
  static const symcr::Schema schema{types, 8, roots, 1, nullptr};
  return schema;
}

TEST(WorldC, PointersInsideStagedMapElementsAreRelocated) {
  mroot.values[0] = 10, mroot.values[1] = 11, mroot.values[2] = 12, mroot.values[3] = 13;
  mroot.map.clear();
  mroot.map[1] = MEntry{&mroot.values[1], {&mroot.values[2], &mroot.values[3]}};
  mroot.map[2] = MEntry{&mroot.values[0], {}};
  const Saved saved = save(mroot_schema());
  mroot.map.clear();
  mroot.map[7] = MEntry{};
  const symcr::Report report = load(saved, mroot_schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  ASSERT_EQ(mroot.map.size(), 2u);
  EXPECT_EQ(mroot.map.at(1).p, &mroot.values[1]);
  EXPECT_EQ(mroot.map.at(1).many,
            (std::vector<std::int32_t*>{&mroot.values[2], &mroot.values[3]}));
  EXPECT_EQ(mroot.map.at(2).p, &mroot.values[0]);
  EXPECT_TRUE(mroot.map.at(2).many.empty());
  mroot.map.clear();
}

}  // namespace
}  // namespace engine_tests
