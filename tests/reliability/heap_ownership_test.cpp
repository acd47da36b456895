// Heap objects restore creates for raw pointers end up reachable from the restored state: an
// object that only a field removed by the patch pointed to is not created (nothing would own
// it: a leak on every restore, holding old data the user dropped the way to).
//
// (While fuzzing, LeakSanitizer flagged heap nodes that only an interior pointer -- an int32*
// into a node -- still reached after the patch removed every Node* to them. Restore must create
// those, since the interior pointer is restored; who frees them is the program's business, as
// for any raw pointer. The fuzzers' worlds therefore track such objects themselves.)
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "reliability_schemas.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

struct Node {
  std::int64_t value;
  Node* next;
};
int created = 0;
int destroyed = 0;
void* create_node() {
  ++created;
  return new Node();
}
void destroy_node(void* node) {
  ++destroyed;
  delete static_cast<Node*>(node);
}
const symcr::Lifecycle counted_node{&create_node, &destroy_node, nullptr};

// The old build: a list with head and tail. The new build dropped `head`.
struct OldList {
  Node* head;
  Node* tail;
};
struct NewList {
  Node* tail;
};
OldList old_list;
NewList new_list;

const symcr::Schema& old_schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(Node, value)),
                                          field("next", 2, offsetof(Node, next))};
  static const FieldInfo list_fields[] = {field("head", 2, offsetof(OldList, head)),
                                          field("tail", 2, offsetof(OldList, tail))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      record("Node", sizeof(Node), alignof(Node), node_fields, 2, &counted_node),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      record("List", sizeof(OldList), alignof(OldList), list_fields, 2),
  };
  static const symcr::RootInfo roots[] = {{"list", 3, &old_list, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

const symcr::Schema& new_schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(Node, value)),
                                          field("next", 2, offsetof(Node, next))};
  static const FieldInfo list_fields[] = {field("tail", 2, offsetof(NewList, tail))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      record("Node", sizeof(Node), alignof(Node), node_fields, 2, &counted_node),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      record("List", sizeof(NewList), alignof(NewList), list_fields, 1),
  };
  static const symcr::RootInfo roots[] = {{"list", 3, &new_list, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

TEST(HeapOwnership, ObjectsOnlyReachableThroughADroppedFieldAreNotCreated) {
  // head -> n0 -> n1 -> n2 -> n3 = tail
  std::vector<Node> nodes(4);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    nodes[i].value = static_cast<std::int64_t>(i);
    nodes[i].next = i + 1 < nodes.size() ? &nodes[i + 1] : nullptr;
  }
  old_list = OldList{&nodes[0], &nodes[3]};
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(old_schema(), buffer).ok());
  old_list = OldList{};

  created = destroyed = 0;
  new_list = NewList{};
  const symcr::Report report =
      symcr::restore_from_buffer(new_schema(), buffer.data(), buffer.size());
  ASSERT_TRUE(report.ok()) << report.to_text();
  ASSERT_NE(new_list.tail, nullptr);
  EXPECT_EQ(new_list.tail->value, 3);
  EXPECT_EQ(new_list.tail->next, nullptr);
  // Only the tail is reachable in the new build; n0..n2 must not be created (or must be
  // destroyed again before restore returns).
  EXPECT_EQ(created - destroyed, 1) << "restore created " << created - destroyed
                                     << " objects of which only 1 is reachable";
  destroy_node(new_list.tail);
  new_list = NewList{};
}

}  // namespace
}  // namespace reliability
