// Resolution: a plan node per (writer type, reader type) pair (planner.hpp, docs/resolution.md):
// its action, its fields matched by name, its enumerators mapped.
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

// ---- nodes ---------------------------------------------------------------------------
const PlanNode* Planner::node(std::uint32_t writer, std::uint32_t reader) {
  auto key = std::make_pair(writer, reader);
  auto found = memo_.find(key);
  if (found != memo_.end()) return found->second;
  plan_.nodes.emplace_back();
  PlanNode& n = plan_.nodes.back();
  memo_[key] = &n;
  n.writer = writer;
  n.reader = reader;
  // Chains of distinct type pairs (a hostile writer schema nesting containers of containers)
  // must not exhaust the stack: past the limit the plan is refused as a whole.
  if (depth_ >= kMaxPlanDepth) {
    too_deep_ = true;
    n.action = Action::Skip;
    return &n;
  }
  struct DepthGuard {
    int& depth;
    explicit DepthGuard(int& d) : depth(d) { ++depth; }
    ~DepthGuard() { --depth; }
  } guard(depth_);
  if (reader == kNoType) {
    fill_skip(n);
  } else {
    fill(n);
    const TypeInfo& type = reader_.types[reader];
    n.validated = has_validator(type) && n.action != Action::Reject;
    n.flat_reader = is_flat(reader, 0);
  }
  return &n;
}

bool Planner::is_flat(std::uint32_t t, int depth) const {
  if (depth > 64) return false;
  const TypeInfo& type = reader_.types[t];
  switch (type.kind) {
    case Kind::Bool:
    case Kind::Int:
    case Kind::UInt:
    case Kind::Float:
    case Kind::Enum:
    case Kind::Union:
    case Kind::Pointer:
      return true;
    case Kind::Array:
      return is_flat(type.element, depth + 1);
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        if (!is_flat(type.fields[f].type, depth + 1)) return false;
      }
      return true;
    default:
      return false;
  }
}

void Planner::fill_skip(PlanNode& n) {
  const TypeInfo& type = writer_.types[n.writer];
  n.action = Action::Skip;
  n.decision = Decision::Dropped;
  n.lossy = true;
  switch (type.kind) {
    case Kind::Struct:
      n.fields.resize(type.field_count);
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        n.fields[f].node = node(type.fields[f].type, kNoType);
        n.fields[f].name = type.fields[f].name;
        n.fields[f].counter = 0;
      }
      break;
    case Kind::Array:
    case Kind::Container:
    case Kind::Optional:
    case Kind::UniquePtr:
      n.element = node(type.element, kNoType);
      n.element_skip = n.element;
      break;
    case Kind::Variant:
      for (std::uint32_t a = 0; a < type.alternative_count; ++a) {
        n.alternatives.push_back(node(type.alternatives[a], kNoType));
        n.alternative_map.push_back(kNoType);
      }
      break;
    default:
      break;
  }
}

void Planner::reject(PlanNode& n, std::string why) {
  n.action = Action::Reject;
  n.decision = Decision::Rejected;
  n.lossy = true;
  n.detail = std::move(why);
  n.skip = node(n.writer, kNoType);
}

std::string Planner::pair_text(const TypeInfo& writer, const TypeInfo& reader) const {
  return std::string(writer.name) + " -> " + reader.name;
}

void Planner::fill(PlanNode& n) {
  const TypeInfo& wt = writer_.types[n.writer];
  const TypeInfo& rt = reader_.types[n.reader];
  if (is_scalar_kind(wt.kind) && is_scalar_kind(rt.kind)) return fill_scalar(n, wt, rt);
  if (wt.kind != rt.kind) {
    return reject(n, std::string("incompatible kinds: ") + kind_name(wt.kind) + " " + wt.name +
                         " -> " + kind_name(rt.kind) + " " + rt.name);
  }
  switch (wt.kind) {
    case Kind::Struct:
      return fill_struct(n, wt, rt);
    case Kind::Union:
      if (wt.size != rt.size) {
        return reject(n, "union size changed: " + std::to_string(wt.size) + " -> " +
                             std::to_string(rt.size) + " bytes");
      }
      n.action = Action::Union;
      return;
    case Kind::Array: {
      n.action = Action::Array;
      n.element = node(wt.element, rt.element);
      // Only elements beyond the reader's length are skipped: no skip tree otherwise.
      n.element_skip = wt.count > rt.count ? node(wt.element, kNoType) : nullptr;
      n.reader_count = rt.count;
      n.reader_stride = reader_.types[rt.element].size;
      if (wt.count > rt.count) {
        n.decision = Decision::Converted;
        n.lossy = true;
        n.detail = "array shrinks " + std::to_string(wt.count) + " -> " + std::to_string(rt.count) +
                   ": trailing elements dropped";
      } else if (wt.count < rt.count) {
        n.decision = Decision::Converted;
        n.detail = "array grows " + std::to_string(wt.count) + " -> " + std::to_string(rt.count) +
                   ": new elements keep this build's values";
      }
      return inherit_element(n);
    }
    case Kind::String: {
      n.action = Action::String;
      n.element = node(wt.element, rt.element);  // the characters, for pointers into them
      const std::uint32_t from = writer_.types[wt.element].size,
                          to = reader_.types[rt.element].size;
      if (from != to) {
        // Re-encoded per value; a value that is not valid in its encoding is rejected.
        n.decision = Decision::Converted;
        n.detail = std::string("re-encoded ") + encoding_name(from) + " -> " + encoding_name(to);
      }
      return;
    }
    case Kind::Container: {
      n.action = Action::Container;
      n.element = node(wt.element, rt.element);
      // Associative elements are staged before insertion: scalars in a buffer, anything
      // else through its lifecycle.
      if (is_associative(rt) && !is_creatable(reader_.types[rt.element]) &&
          !is_scalar_kind(reader_.types[rt.element].kind)) {
        return reject(n, std::string("no lifecycle for element type ") +
                             reader_.types[rt.element].name + " of " + rt.name);
      }
      if (!same_name(wt.name, rt.name)) {
        n.decision = Decision::Converted;
        n.detail = pair_text(wt, rt);
      }
      return inherit_element(n);
    }
    case Kind::Optional:
      n.action = Action::Optional;
      n.element = node(wt.element, rt.element);
      return inherit_element(n);
    case Kind::UniquePtr:
      n.action = Action::UniquePtr;
      n.element = node(wt.element, rt.element);
      return inherit_element(n);
    case Kind::Variant: {
      n.action = Action::Variant;
      for (std::uint32_t a = 0; a < wt.alternative_count; ++a) {
        const TypeInfo& alternative = writer_.types[wt.alternatives[a]];
        std::uint32_t match = kNoType;
        for (std::uint32_t b = 0; b < rt.alternative_count && match == kNoType; ++b) {
          if (same_name(alternative.name, reader_.types[rt.alternatives[b]].name)) match = b;
        }
        for (std::uint32_t b = 0; b < rt.alternative_count && match == kNoType; ++b) {
          if (names_match(alternative, reader_.types[rt.alternatives[b]])) match = b;
        }
        n.alternative_map.push_back(match);
        n.alternatives.push_back(
            node(wt.alternatives[a], match == kNoType ? kNoType : rt.alternatives[match]));
        if (match == kNoType) {
          n.decision = Decision::Converted;
          if (!n.detail.empty()) n.detail += "; ";
          n.detail += std::string("alternative ") + alternative.name +
                      " not in this build: such values are rejected";
        }
      }
      return;
    }
    case Kind::Pointer:
    case Kind::SharedPtr: {
      const TypeInfo& wp = writer_.types[wt.element];
      const TypeInfo& rp = reader_.types[rt.element];
      if (!names_match(wp, rp)) {
        return reject(n, std::string("pointee type ") + wp.name + " -> " + rp.name);
      }
      n.action = wt.kind == Kind::Pointer ? Action::Pointer : Action::SharedPtr;
      n.element = node(wt.element, rt.element);
      // A raw pointer is restored by what it pointed at: a checkpointed object becomes a
      // reference to the new build's object at the same path. A polymorphic pointee is on
      // the heap only as a class the writer could create (by its dynamic type).
      if (n.action == Action::Pointer) {
        n.detail = !(rp.flags & kTypePolymorphic)
                       ? "reference to the object at the same path, or a heap object rebuilt"
                   : wt.element < dynamic_bases_.size() && dynamic_bases_[wt.element]
                       ? "reference to the object at the same path, or a heap object "
                         "rebuilt as its dynamic type"
                       : "reference to the object at the same path";
      }
      return;
    }
    default:
      return reject(n, "unsupported kind");
  }
}

// A container-like node reports its element's decision when it has none of its own, and its
// lossiness, at every nesting level (an inner array shrinking, a string re-encoded inside a
// vector). Struct elements are not folded in: their fields get entries of their own, and so
// do pointees.
void Planner::inherit_element(PlanNode& n) {
  const PlanNode* e = n.element;
  if (!e || e == &n) return;
  if (e->action == Action::Struct || e->action == Action::Pointer ||
      e->action == Action::SharedPtr || e->action == Action::Skip) {
    return;
  }
  if (e->action == Action::Reject && n.decision == Decision::Restored) {
    n.decision = Decision::Converted;
    n.detail = "elements rejected: " + e->detail;
  } else if (e->decision == Decision::Converted && n.decision == Decision::Restored) {
    n.decision = Decision::Converted;
    n.detail = "elements " + e->detail;
  }
  n.lossy = n.lossy || e->lossy;
}

void Planner::fill_scalar(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt) {
  n.action = Action::Scalar;
  n.identical = wt.kind == rt.kind && wt.size == rt.size;
  if (wt.kind == Kind::Enum) {
    for (std::uint32_t e = 0; e < wt.enumerator_count; ++e) {
      const EnumeratorInfo& writer = wt.enumerators[e];
      EnumMapping mapping{writer.value, writer.name, false, 0};
      if (rt.kind == Kind::Enum) {
        if (const EnumeratorInfo* reader = reader_enumerator(rt, writer.name)) {
          mapping.mapped = true;
          mapping.reader_value = reader->value;
        }
      }
      if (!mapping.mapped || mapping.reader_value != writer.value) n.identical = false;
      n.enum_map.push_back(mapping);
    }
    if (rt.kind == Kind::Enum && rt.enumerator_count != wt.enumerator_count) n.identical = false;
    if (rt.kind == Kind::Enum && writer_.types[wt.element].kind != reader_.types[rt.element].kind) {
      n.identical = false;
    }
  }
  // Sorted by writer value: restore looks values up by binary search.
  std::sort(n.enum_map.begin(), n.enum_map.end(), [](const EnumMapping& a, const EnumMapping& b) {
    return a.writer_value < b.writer_value;
  });
  collapse_enum_aliases(n.enum_map);
  if (n.identical) return;
  n.decision = Decision::Converted;
  n.detail = pair_text(wt, rt);
  if (wt.kind == Kind::Enum && rt.kind == Kind::Enum) {
    n.detail = "enum by name: " + n.detail;
    for (const EnumMapping& mapping : n.enum_map) {
      if (!mapping.mapped) n.detail += "; " + unmapped_enumerator(rt, mapping);
    }
  }
  if (wt.kind == Kind::Float && rt.kind == Kind::Float && rt.size < wt.size) {
    n.lossy = true;  // precision is rounded away, not rejected
    n.detail += " (precision rounded)";
  }
}

// A writer value with several names (an alias kept while renaming: `Loiter = 3, Hold = 3`)
// maps through whichever of its names the reader has, whatever their declaration order: one
// entry per value, mapped when its names that the reader knows agree on one reader value.
void Planner::collapse_enum_aliases(std::vector<EnumMapping>& map) {
  std::vector<EnumMapping> collapsed;
  for (std::size_t i = 0; i < map.size();) {
    std::size_t end = i;
    const EnumMapping* chosen = &map[i];
    bool conflicting = false;
    for (; end < map.size() && map[end].writer_value == map[i].writer_value; ++end) {
      const EnumMapping& alias = map[end];
      if (!alias.mapped) continue;
      if (!chosen->mapped) {
        chosen = &alias;
      } else if (alias.reader_value != chosen->reader_value) {
        conflicting = true;  // the names part ways in the reader: which one is meant?
      }
    }
    collapsed.push_back(*chosen);
    if (conflicting) collapsed.back().mapped = false;
    i = end;
  }
  map.swap(collapsed);
}

void Planner::fill_struct(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt) {
  n.action = Action::Struct;
  std::vector<bool> reader_used(rt.field_count, false);
  n.fields.resize(wt.field_count);
  for (std::uint32_t f = 0; f < wt.field_count; ++f) {
    const FieldInfo& writer = wt.fields[f];
    const std::uint32_t match = match_field(wt, f, rt, reader_used);
    FieldPlan& field = n.fields[f];
    field.name = writer.name;
    field.counter = new_counter(wt.name, writer.name);
    if (match == kNoType) {
      field.node = node(writer.type, kNoType);
      continue;
    }
    reader_used[match] = true;
    const FieldInfo& reader = rt.fields[match];
    field.reader_field = match;
    field.reader_offset = reader.offset;
    field.bit_offset = reader.bit_offset;
    field.bit_width = reader.bit_width;
    field.has_range = (reader.flags & kFieldHasRange) != 0 && reader.range != nullptr;
    if (field.has_range) {
      field.range_min = reader.range->min;
      field.range_max = reader.range->max;
    }
    field.node = node(writer.type, reader.type);
  }
}

std::uint32_t Planner::match_field(const TypeInfo& wt, std::uint32_t wf, const TypeInfo& rt,
                                   const std::vector<bool>& used) const {
  const FieldInfo& writer = wt.fields[wf];
  const bool base = (writer.flags & kFieldBase) != 0;
  for (std::uint32_t f = 0; f < rt.field_count; ++f) {
    const FieldInfo& reader = rt.fields[f];
    if (used[f] || ((reader.flags & kFieldBase) != 0) != base) continue;
    if (same_name(reader.name, writer.name)) return f;
  }
  for (std::uint32_t f = 0; f < rt.field_count; ++f) {
    const FieldInfo& reader = rt.fields[f];
    if (used[f] || ((reader.flags & kFieldBase) != 0) != base) continue;
    if (in_aliases(writer.name, reader.renamed_from)) return f;
    if (base && in_aliases(writer.name, reader_.types[reader.type].renamed_from)) return f;
  }
  if (is_anonymous_member(writer.name)) return match_anonymous_member(wt, wf, rt, used);
  return kNoType;
}

// Unnamed struct and union members are named after their declaration index, which moves when
// a field is added or removed before them. Their members are what the program names: an
// anonymous struct matches the reader's anonymous struct sharing the most member names; an
// anonymous union (restored as raw bytes, its members unlisted) matches the reader's anonymous
// union of the same rank among the anonymous unions.
bool Planner::is_anonymous_member(const char* name) {
  return std::strncmp(name, "(anonymous ", 11) == 0;
}

// The same member for the report: the same name, or two unnamed members matched above.
bool Planner::same_member(const char* writer, const char* reader) {
  return same_name(writer, reader) || (is_anonymous_member(writer) && is_anonymous_member(reader));
}

std::uint32_t Planner::match_anonymous_member(const TypeInfo& wt, std::uint32_t wf,
                                              const TypeInfo& rt,
                                              const std::vector<bool>& used) const {
  const TypeInfo& member = writer_.types[wt.fields[wf].type];
  auto anonymous_of_kind = [](const Schema& schema, const FieldInfo& field, Kind kind) {
    return is_anonymous_member(field.name) && schema.types[field.type].kind == kind;
  };
  if (member.kind == Kind::Union) {
    std::uint32_t rank = 0;
    for (std::uint32_t f = 0; f < wf; ++f)
      rank += anonymous_of_kind(writer_, wt.fields[f], Kind::Union);
    for (std::uint32_t f = 0; f < rt.field_count; ++f) {
      if (!anonymous_of_kind(reader_, rt.fields[f], Kind::Union)) continue;
      if (rank-- == 0) return used[f] ? kNoType : f;
    }
    return kNoType;
  }
  std::uint32_t best = kNoType, best_shared = 0;
  for (std::uint32_t f = 0; f < rt.field_count; ++f) {
    if (used[f] || !anonymous_of_kind(reader_, rt.fields[f], member.kind)) continue;
    const TypeInfo& candidate = reader_.types[rt.fields[f].type];
    std::uint32_t shared = 0;
    for (std::uint32_t a = 0; a < member.field_count; ++a) {
      for (std::uint32_t b = 0; b < candidate.field_count; ++b) {
        shared += same_name(member.fields[a].name, candidate.fields[b].name);
      }
    }
    if (shared > best_shared) {
      best = f;
      best_shared = shared;
    }
  }
  return best;
}

}  // namespace symcr::detail::planning
