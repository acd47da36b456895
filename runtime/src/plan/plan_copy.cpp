// Resolution: copy-only programs (PlanNode::copy_only), restore's fast path for values whose
// bytes it copies as they are (planner.hpp).
#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "planner.hpp"
#include "schema_facts.hpp"
#include "unicode.hpp"

namespace symcr::detail::planning {

void Planner::add_run(PlanNode& n, std::uint64_t wire, std::uint64_t dst, std::uint64_t length) {
  if (length == 0) return;
  if (!n.copy_runs.empty()) {
    CopyRun& last = n.copy_runs.back();
    if (std::uint64_t{last.wire} + last.length == wire &&
        std::uint64_t{last.dst} + last.length == dst) {
      last.length += static_cast<std::uint32_t>(length);
      return;
    }
  }
  n.copy_runs.push_back(CopyRun{static_cast<std::uint32_t>(wire), static_cast<std::uint32_t>(dst),
                                static_cast<std::uint32_t>(length)});
}

// Appends `child`'s program at (wire, dst); false when `n` grows past the limits.
bool Planner::append_copy(PlanNode& n, const PlanNode& child, std::uint64_t wire,
                          std::uint64_t dst) {
  if (wire + child.copy_wire > kMaxCopyWire || dst + kMaxCopyWire > 0xFFFFFFFFu) return false;
  for (std::uint32_t offset : child.copy_bools) {
    if (n.copy_bools.size() >= kMaxCopyBools) return false;
    n.copy_bools.push_back(static_cast<std::uint32_t>(wire + offset));
  }
  for (const CopyRun& run : child.copy_runs) {
    add_run(n, wire + run.wire, dst + run.dst, run.length);
    if (n.copy_runs.size() > kMaxCopyRuns) return false;
  }
  for (CopyBits bits : child.copy_bits) {
    if (n.copy_bits.size() >= kMaxCopyBools) return false;
    bits.wire += static_cast<std::uint32_t>(wire);
    bits.dst += static_cast<std::uint32_t>(dst);
    n.copy_bits.push_back(bits);
  }
  return true;
}

// An integer or bool bit-field whose writer and reader types are identical, at `wire`.
bool Planner::add_bit_field(PlanNode& n, const FieldPlan& field, std::uint64_t wire) {
  const PlanNode* child = field.node;
  if (!child || child->validated || child->action != Action::Scalar || !child->identical ||
      n.copy_bits.size() >= kMaxCopyBools || wire + 8 > kMaxCopyWire) {
    return false;
  }
  const TypeInfo& wt = writer_.types[child->writer];
  const bool integer = wt.kind == Kind::Int || wt.kind == Kind::UInt || wt.kind == Kind::Bool;
  if (!integer || (wt.size != 1 && wt.size != 2 && wt.size != 4 && wt.size != 8)) return false;
  if (wt.kind == Kind::Bool) n.copy_bools.push_back(static_cast<std::uint32_t>(wire));
  n.copy_bits.push_back(CopyBits{static_cast<std::uint32_t>(wire), field.reader_offset,
                                 field.bit_offset, field.bit_width,
                                 static_cast<std::uint8_t>(wt.size), wt.kind == Kind::Int});
  return true;
}

void Planner::compute_copy(PlanNode& n) {
  if (n.copy_state) return;
  n.copy_state = 1;  // from now on: a (malformed) cycle back to it is not copy-only
  n.copy_only = build_copy(n);
  if (!n.copy_only) {
    n.copy_wire = 0;
    n.copy_runs.clear();
    n.copy_runs.shrink_to_fit();
    n.copy_bools.clear();
    n.copy_bools.shrink_to_fit();
    n.copy_bits.clear();
    n.copy_bits.shrink_to_fit();
  }
}

// The whole payload is copy-only when every writer root is kept and copy-only: then it is
// the roots' copy programs back to back and two empty sections (heap objects, references).
void Planner::compute_copy_only_payload() {
  std::uint64_t size = format::kHeapCountSize + format::kReferenceCountSize +
                       format::clock_readings_size(plan_.wire_sizes.clock_count);
  for (const RootPlan& root : plan_.roots) {
    if (root.reader_root == kNoType || !child_copy_only(root.node)) return;
    size += root.node->copy_wire;
  }
  plan_.copy_only_payload = true;
  plan_.copy_only_payload_size = size;
}

bool Planner::child_copy_only(const PlanNode* child) {
  if (!child || child->validated || child->migrates) return false;
  auto& mutable_child = const_cast<PlanNode&>(*child);  // a node of plan_.nodes
  compute_copy(mutable_child);
  return child->copy_only;
}

bool Planner::build_copy(PlanNode& n) {
  if (n.reader == kNoType || n.writer >= writer_.type_count) return false;
  const TypeInfo& wt = writer_.types[n.writer];
  switch (n.action) {
    case Action::Scalar:
      if (!n.identical || (wt.kind == Kind::Float && wt.size == 16)) return false;
      if (wt.kind == Kind::Bool) n.copy_bools.push_back(0);
      n.copy_wire = wt.size;
      add_run(n, 0, 0, wt.size);
      return true;
    case Action::Union:
      n.copy_wire = wt.size;
      add_run(n, 0, 0, wt.size);
      return true;
    case Action::Struct: {
      if (n.migrates) return false;  // the hook runs after the fields are written
      std::uint64_t wire = 0;
      for (const FieldPlan& field : n.fields) {
        if (field.reader_field == kNoType || field.has_range) return false;
        if (reader_time(reader_, n, field)) return false;  // rebased value by value
        if (field.bit_width) {
          if (!add_bit_field(n, field, wire)) return false;
          wire += writer_.types[field.node->writer].size;
          continue;
        }
        if (!child_copy_only(field.node)) return false;
        if (!append_copy(n, *field.node, wire, field.reader_offset)) return false;
        wire += field.node->copy_wire;
      }
      n.copy_wire = static_cast<std::uint32_t>(wire);
      return true;
    }
    case Action::Array: {
      if (wt.count != n.reader_count || !child_copy_only(n.element)) return false;
      const PlanNode& e = *n.element;
      if (e.copy_wire == 0 || wt.count > kMaxCopyWire / e.copy_wire) return false;
      for (std::uint64_t i = 0; i < wt.count; ++i) {
        if (!append_copy(n, e, i * e.copy_wire, i * n.reader_stride)) return false;
      }
      n.copy_wire = static_cast<std::uint32_t>(wt.count * e.copy_wire);
      return true;
    }
    default:
      return false;
  }
}

bool Planner::segment_field(const FieldPlan& field) {
  const PlanNode* child = field.node;
  return field.reader_field != kNoType && !field.has_range && !field.bit_width && child &&
         child->copy_only && !child->validated && !child->migrates && !field.time;
}

// Splits a struct that is not copy-only into segments; none when no field could be copied
// (nothing gained) or a program outgrows the copy limits (the fields then go one by one, as
// they would without segments).
void Planner::derive_segments(PlanNode& n) {
  n.copy_segments.clear();
  if (n.action != Action::Struct || n.copy_only || n.reader == kNoType) return;
  std::vector<CopySegment> segments;
  PlanNode* program = nullptr;  // the open segment's program
  std::uint64_t wire = 0;       // its wire bytes so far
  bool any_copy = false;
  for (std::uint32_t f = 0; f < n.fields.size(); ++f) {
    const FieldPlan& field = n.fields[f];
    if (!segment_field(field)) {
      program = nullptr;
      segments.push_back(CopySegment{f, f + 1, nullptr});
      continue;
    }
    if (program) {
      // A failed append leaves the program part-written: no segments then.
      if (!append_copy(*program, *field.node, wire, field.reader_offset)) return;
      wire += field.node->copy_wire;
      program->copy_wire = static_cast<std::uint32_t>(wire);
      segments.back().end_field = f + 1;
      continue;
    }
    plan_.segment_programs.emplace_back();
    program = &plan_.segment_programs.back();
    program->writer = n.writer;
    program->reader = n.reader;
    program->copy_only = true;
    program->copy_state = 1;
    if (!append_copy(*program, *field.node, 0, field.reader_offset)) return;
    wire = field.node->copy_wire;
    program->copy_wire = static_cast<std::uint32_t>(wire);
    segments.push_back(CopySegment{f, f + 1, program});
    any_copy = true;
  }
  if (!any_copy) return;
  // A program of no bytes (fields of empty structs) has nothing to check or copy.
  segments.erase(std::remove_if(segments.begin(), segments.end(),
                                [](const CopySegment& segment) {
                                  return segment.copy && segment.copy->copy_wire == 0;
                                }),
                 segments.end());
  n.copy_segments = std::move(segments);
}

void Planner::derive_copy_segments() {
  plan_.segment_programs.clear();
  for (PlanNode& n : plan_.nodes) {
    for (FieldPlan& field : n.fields) field.time = reader_time(reader_, n, field);
    if (plan_.status.ok()) derive_segments(n);
  }
}

}  // namespace symcr::detail::planning

namespace symcr::detail {

void derive_copy_segments(Plan& plan) { planning::Planner(plan).derive_copy_segments(); }

}  // namespace symcr::detail
