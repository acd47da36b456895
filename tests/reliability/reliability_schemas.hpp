// Hand-written schemas for the reliability tests, in the form symcr-gen emits.
#ifndef SYMCR_TESTS_RELIABILITY_RELIABILITY_SCHEMAS_HPP
#define SYMCR_TESTS_RELIABILITY_RELIABILITY_SCHEMAS_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "schema_tables.hpp"
#include "symcr/ops.hpp"
#include "symcr/generated.hpp"

namespace reliability {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

// ---- A frame large enough that a write of it spans several pages: a torn write shows up as a
// mix of two sequences, which the checks below would see.
constexpr std::size_t kFrameBytes = 16384;
struct Frame {
  std::uint64_t sequence;
  std::uint8_t bytes[kFrameBytes];
  std::uint64_t check;
};
inline Frame frame;

inline void fill_frame(std::uint64_t sequence) {
  frame.sequence = sequence;
  for (std::size_t i = 0; i < kFrameBytes; ++i) {
    frame.bytes[i] = static_cast<std::uint8_t>(sequence * 131 + i * 7);
  }
  frame.check = ~sequence;
}

// True when the live frame is exactly what fill_frame(sequence) wrote.
inline bool frame_is(std::uint64_t sequence) {
  if (frame.sequence != sequence || frame.check != ~sequence) return false;
  for (std::size_t i = 0; i < kFrameBytes; ++i) {
    if (frame.bytes[i] != static_cast<std::uint8_t>(sequence * 131 + i * 7)) return false;
  }
  return true;
}

inline const symcr::Schema& frame_schema() {
  static const FieldInfo fields[] = {field("sequence", 0, offsetof(Frame, sequence)),
                                     field("bytes", 2, offsetof(Frame, bytes)),
                                     field("check", 0, offsetof(Frame, check))};
  static const TypeInfo types[] = {
      scalar("uint64", Kind::UInt, 8),
      scalar("uint8", Kind::UInt, 1),
      array("uint8[16384]", 1, kFrameBytes, kFrameBytes, 1),
      record("reliability::Frame", sizeof(Frame), alignof(Frame), fields, 3),
  };
  static const symcr::RootInfo roots[] = {{"frame", 3, &frame, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

// ---- A linked list through raw pointers (heap nodes only reachable through them).
struct ListNode {
  std::int64_t value;
  ListNode* next;
};
struct List {
  ListNode* head;
  std::int64_t length;
};
inline List list;

inline const symcr::Schema& list_schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(ListNode, value)),
                                          field("next", 2, offsetof(ListNode, next))};
  static const FieldInfo list_fields[] = {field("head", 2, offsetof(List, head)),
                                          field("length", 0, offsetof(List, length))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      record("reliability::ListNode", sizeof(ListNode), alignof(ListNode), node_fields, 2,
             &symcr::ops::lifecycle<ListNode>::table),
      holder("reliability::ListNode*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      record("reliability::List", sizeof(List), alignof(List), list_fields, 2),
  };
  static const symcr::RootInfo roots[] = {{"list", 3, &list, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

// ---- A chain of containers nested in containers.
struct Chain {
  std::int32_t value = 0;
  std::vector<Chain> inner;
};
inline Chain chain;

inline const symcr::Schema& chain_schema() {
  static const FieldInfo fields[] = {field("value", 0, offsetof(Chain, value)),
                                     field("inner", 1, offsetof(Chain, inner))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      holder("std::vector<reliability::Chain>", Kind::Container, sizeof(std::vector<Chain>),
             alignof(std::vector<Chain>), 2, &symcr::ops::container<std::vector<Chain>>::table),
      record("reliability::Chain", sizeof(Chain), alignof(Chain), fields, 2,
             &symcr::ops::lifecycle<Chain>::table),
  };
  static const symcr::RootInfo roots[] = {{"chain", 2, &chain, 0, nullptr}};
  static const symcr::Schema schema{types, 3, roots, 1, nullptr};
  return schema;
}

// Builds a chain `depth` levels deep and takes one apart, both without recursion (the
// destructor of a deep std::vector<Chain> would recurse once per level).
inline void build_chain(Chain& root, std::size_t depth) {
  root = Chain{};
  Chain* at = &root;
  for (std::size_t level = 0; level < depth; ++level) {
    at->value = static_cast<std::int32_t>(level);
    at->inner.emplace_back();
    at = &at->inner.back();
  }
  at->value = static_cast<std::int32_t>(depth);
}
inline void dismantle_chain(Chain& root) {
  std::vector<Chain> pending;
  pending.push_back(std::move(root));
  root = Chain{};
  while (!pending.empty()) {
    Chain node = std::move(pending.back());
    pending.pop_back();
    for (Chain& child : node.inner) pending.push_back(std::move(child));
  }
}

}  // namespace reliability

#endif  // SYMCR_TESTS_RELIABILITY_RELIABILITY_SCHEMAS_HPP
