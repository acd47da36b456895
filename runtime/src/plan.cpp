// Resolution of a writer schema against the reader schema (docs/resolution.md), and the cache of
// plans. Struct-to-struct matching is decided by the holder (root or field name): a type
// renamed without annotation still matches through the field that holds it. Type names are
// compared only where no holder exists: bases, variant alternatives and pointees.
#include <algorithm>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <utility>

#include "plan.hpp"
#include "unicode.hpp"
#include "schema_facts.hpp"

namespace symcr::detail {
namespace {

bool same_name(const char* a, const char* b) { return std::strcmp(a ? a : "", b ? b : "") == 0; }

bool in_aliases(const char* name, const char* const* aliases) {
  for (std::size_t i = 0; aliases && aliases[i]; ++i) {
    if (same_name(name, aliases[i])) return true;
  }
  return false;
}

constexpr int kMaxPlanDepth = 512;

bool is_associative(const TypeInfo& container) {
  const auto* ops = static_cast<const ContainerOps*>(container.ops);
  return ops && !ops->append;
}

class Planner {
 public:
  Planner(Plan& plan) : plan_(plan), w_(*plan.writer), r_(*plan.reader) {}

  // Once per (writer, reader) pair, then cached: cold, so that it and what only it calls are
  // optimised for size (tens of KB of .text) and kept off the hot pages.
  __attribute__((cold, noinline)) void run() {
    plan_.wire_sizes = wire_sizes(w_);
    plan_.shared_types.assign(r_.type_count, kNoType);
    for (std::uint32_t t = 0; t < r_.type_count; ++t) {
      const TypeInfo& type = r_.types[t];
      if (type.kind == Kind::SharedPtr && type.element < r_.type_count &&
          plan_.shared_types[type.element] == kNoType) {
        plan_.shared_types[type.element] = t;
      }
    }
    find_dynamic_bases();
    plan_roots();
    plan_.heap_nodes.assign(w_.type_count, nullptr);
    for (std::uint32_t t = 0; t < w_.type_count; ++t) {
      const TypeInfo& type = w_.types[t];
      if ((type.kind == Kind::Pointer || type.kind == Kind::SharedPtr) &&
          type.element < w_.type_count && !plan_.heap_nodes[type.element]) {
        plan_.heap_nodes[type.element] = node(type.element, find_reader_type(w_.types[type.element]));
      }
    }
    // A heap object behind a pointer to a polymorphic base is saved as its dynamic type.
    for (std::uint32_t t = 0; t < w_.type_count; ++t) {
      if ((w_.types[t].flags & kTypeDynamicType) && w_.types[t].kind == Kind::Struct &&
          !plan_.heap_nodes[t]) {
        plan_.heap_nodes[t] = node(t, find_reader_type(w_.types[t]));
      }
    }
    decide_migrations();
    build_report();
    for (PlanNode& n : plan_.nodes) compute_copy(n);
    compute_copy_only_payload();
    if (too_deep_) {
      plan_.status = Status(Error::Corrupt, "invalid schema: types nest deeper than %d levels",
                            kMaxPlanDepth);
    }
  }

 private:
  // Per writer type: the writer knew a class equal to it or derived from it that it could save
  // as a heap object's dynamic type.
  void find_dynamic_bases() {
    std::vector<std::uint32_t> pending;
    for (std::uint32_t t = 0; t < w_.type_count; ++t) {
      if (w_.types[t].flags & kTypeDynamicType) pending.push_back(t);
    }
    dynamic_bases_.clear();
    mark_with_bases(w_.types, w_.type_count, pending, dynamic_bases_);
  }

  // ---- matching ------------------------------------------------------------------------
  std::uint32_t find_reader_type(const TypeInfo& writer) const {
    for (std::uint32_t t = 0; t < r_.type_count; ++t) {
      if (same_name(r_.types[t].name, writer.name) && r_.types[t].kind == writer.kind) return t;
    }
    for (std::uint32_t t = 0; t < r_.type_count; ++t) {
      if (names_match(writer, r_.types[t])) return t;
    }
    return kNoType;
  }

  __attribute__((cold)) void plan_roots() {
    plan_.roots.resize(w_.root_count);
    bool any_restorable = false;
    // Each reader root takes at most one writer root: exact names first, then old names.
    std::vector<std::uint32_t> matches(w_.root_count, kNoType);
    std::vector<bool> taken(r_.root_count, false);
    for (int pass = 0; pass < 2; ++pass) {
      for (std::uint32_t wr = 0; wr < w_.root_count; ++wr) {
        for (std::uint32_t rr = 0; rr < r_.root_count && matches[wr] == kNoType; ++rr) {
          const bool named = pass == 0 ? same_name(r_.roots[rr].name, w_.roots[wr].name)
                                       : in_aliases(w_.roots[wr].name, r_.roots[rr].renamed_from);
          if (named && !taken[rr]) {
            matches[wr] = rr;
            taken[rr] = true;
          }
        }
      }
    }
    for (std::uint32_t wr = 0; wr < w_.root_count; ++wr) {
      const RootInfo& writer = w_.roots[wr];
      const std::uint32_t match = matches[wr];
      RootPlan& root = plan_.roots[wr];
      root.reader_root = match;
      root.node = node(writer.type, match == kNoType ? kNoType : r_.roots[match].type);
      root.counter = new_counter(writer.name);
      if (match != kNoType && root.node->action != Action::Reject) any_restorable = true;
    }
    if (w_.root_count > 0 && !any_restorable) {
      plan_.status = Status(Error::Incompatible,
                            "no root of the checkpoint can be restored into this build");
    }
  }

  std::uint32_t new_counter(std::string path) {
    plan_.counter_paths.push_back(std::move(path));
    return static_cast<std::uint32_t>(plan_.counter_paths.size() - 1);
  }

  // ---- nodes ---------------------------------------------------------------------------
  __attribute__((cold)) const PlanNode* node(std::uint32_t writer, std::uint32_t reader) {
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
      const TypeInfo& type = r_.types[reader];
      n.validated = type.validate != nullptr && n.action != Action::Reject;
      n.flat_reader = is_flat(reader, 0);
    }
    return &n;
  }

  bool is_flat(std::uint32_t t, int depth) const {
    if (depth > 64) return false;
    const TypeInfo& type = r_.types[t];
    switch (type.kind) {
      case Kind::Bool: case Kind::Int: case Kind::UInt: case Kind::Float: case Kind::Enum:
      case Kind::Union: case Kind::Pointer:
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

  __attribute__((cold)) void fill_skip(PlanNode& n) {
    const TypeInfo& type = w_.types[n.writer];
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
      case Kind::Array: case Kind::Container: case Kind::Optional: case Kind::UniquePtr:
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

  void reject(PlanNode& n, std::string why) {
    n.action = Action::Reject;
    n.decision = Decision::Rejected;
    n.lossy = true;
    n.detail = std::move(why);
    n.skip = node(n.writer, kNoType);
  }

  std::string pair_text(const TypeInfo& writer, const TypeInfo& reader) const {
    return std::string(writer.name) + " -> " + reader.name;
  }

  __attribute__((cold)) void fill(PlanNode& n) {
    const TypeInfo& wt = w_.types[n.writer];
    const TypeInfo& rt = r_.types[n.reader];
    if (is_scalar_kind(wt.kind) && is_scalar_kind(rt.kind)) return fill_scalar(n, wt, rt);
    if (wt.kind != rt.kind) {
      return reject(n, std::string("incompatible kinds: ") + kind_name(wt.kind) + " " + wt.name +
                           " -> " + kind_name(rt.kind) + " " + rt.name);
    }
    switch (wt.kind) {
      case Kind::Struct: return fill_struct(n, wt, rt);
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
        n.element_skip = node(wt.element, kNoType);
        n.reader_count = rt.count;
        n.reader_stride = r_.types[rt.element].size;
        if (wt.count > rt.count) {
          n.decision = Decision::Converted;
          n.lossy = true;
          n.detail = "array shrinks " + std::to_string(wt.count) + " -> " +
                     std::to_string(rt.count) + ": trailing elements dropped";
        } else if (wt.count < rt.count) {
          n.decision = Decision::Converted;
          n.detail = "array grows " + std::to_string(wt.count) + " -> " +
                     std::to_string(rt.count) + ": new elements keep this build's values";
        }
        return inherit_element(n);
      }
      case Kind::String: {
        n.action = Action::String;
        n.element = node(wt.element, rt.element);  // the characters, for pointers into them
        const std::uint32_t from = w_.types[wt.element].size, to = r_.types[rt.element].size;
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
        if (is_associative(rt) && !r_.types[rt.element].lifecycle &&
            !is_scalar_kind(r_.types[rt.element].kind)) {
          return reject(n, std::string("no lifecycle for element type ") +
                               r_.types[rt.element].name + " of " + rt.name);
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
          const TypeInfo& alternative = w_.types[wt.alternatives[a]];
          std::uint32_t match = kNoType;
          for (std::uint32_t b = 0; b < rt.alternative_count && match == kNoType; ++b) {
            if (same_name(alternative.name, r_.types[rt.alternatives[b]].name)) match = b;
          }
          for (std::uint32_t b = 0; b < rt.alternative_count && match == kNoType; ++b) {
            if (names_match(alternative, r_.types[rt.alternatives[b]])) match = b;
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
        const TypeInfo& wp = w_.types[wt.element];
        const TypeInfo& rp = r_.types[rt.element];
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
  void inherit_element(PlanNode& n) {
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

  __attribute__((cold)) void fill_scalar(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt) {
    n.action = Action::Scalar;
    n.identical = wt.kind == rt.kind && wt.size == rt.size;
    if (wt.kind == Kind::Enum) {
      for (std::uint32_t e = 0; e < wt.enumerator_count; ++e) {
        const EnumeratorInfo& writer = wt.enumerators[e];
        EnumMapping mapping{writer.value, writer.name, false, 0};
        if (rt.kind == Kind::Enum) {
          for (std::uint32_t f = 0; f < rt.enumerator_count; ++f) {
            if (same_name(writer.name, rt.enumerators[f].name)) {
              mapping.mapped = true;
              mapping.reader_value = rt.enumerators[f].value;
              break;
            }
          }
        }
        if (!mapping.mapped || mapping.reader_value != writer.value) n.identical = false;
        n.enum_map.push_back(mapping);
      }
      if (rt.kind == Kind::Enum && rt.enumerator_count != wt.enumerator_count) n.identical = false;
      if (rt.kind == Kind::Enum &&
          w_.types[wt.element].kind != r_.types[rt.element].kind) {
        n.identical = false;
      }
    }
    // Sorted by writer value: restore looks values up by binary search.
    std::sort(n.enum_map.begin(), n.enum_map.end(),
              [](const EnumMapping& a, const EnumMapping& b) {
                return a.writer_value < b.writer_value;
              });
    collapse_enum_aliases(n.enum_map);
    if (n.identical) return;
    n.decision = Decision::Converted;
    n.detail = pair_text(wt, rt);
    if (wt.kind == Kind::Enum && rt.kind == Kind::Enum) {
      n.detail = "enum by name: " + n.detail;
      for (const EnumMapping& mapping : n.enum_map) {
        if (!mapping.mapped) {
          n.detail += std::string("; ") + mapping.name + " not in this build";
        }
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
  static void collapse_enum_aliases(std::vector<EnumMapping>& map) {
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

  __attribute__((cold)) void fill_struct(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt) {
    n.action = Action::Struct;
    std::vector<bool> reader_used(rt.field_count, false);
    n.fields.resize(wt.field_count);
    for (std::uint32_t f = 0; f < wt.field_count; ++f) {
      const FieldInfo& writer = wt.fields[f];
      const std::uint32_t match = match_field(wt, f, rt, reader_used);
      FieldPlan& field = n.fields[f];
      field.name = writer.name;
      field.counter = new_counter(std::string(wt.name) + "::" + writer.name);
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
      field.has_range = (reader.flags & kFieldHasRange) != 0;
      field.range_min = reader.range_min;
      field.range_max = reader.range_max;
      field.node = node(writer.type, reader.type);
    }
  }

  std::uint32_t match_field(const TypeInfo& wt, std::uint32_t wf, const TypeInfo& rt,
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
      if (base && in_aliases(writer.name, r_.types[reader.type].renamed_from)) return f;
    }
    if (is_anonymous_member(writer.name)) return match_anonymous_member(wt, wf, rt, used);
    return kNoType;
  }

  // Unnamed struct and union members are named after their declaration index, which moves when
  // a field is added or removed before them. Their members are what the program names: an
  // anonymous struct matches the reader's anonymous struct sharing the most member names; an
  // anonymous union (restored as raw bytes, its members unlisted) matches the reader's anonymous
  // union of the same rank among the anonymous unions.
  static bool is_anonymous_member(const char* name) {
    return std::strncmp(name, "(anonymous ", 11) == 0;
  }
  // The same member for the report: the same name, or two unnamed members matched above.
  static bool same_member(const char* writer, const char* reader) {
    return same_name(writer, reader) || (is_anonymous_member(writer) && is_anonymous_member(reader));
  }

  std::uint32_t match_anonymous_member(const TypeInfo& wt, std::uint32_t wf, const TypeInfo& rt,
                                       const std::vector<bool>& used) const {
    const TypeInfo& member = w_.types[wt.fields[wf].type];
    auto anonymous_of_kind = [](const Schema& schema, const FieldInfo& field, Kind kind) {
      return is_anonymous_member(field.name) && schema.types[field.type].kind == kind;
    };
    if (member.kind == Kind::Union) {
      std::uint32_t rank = 0;
      for (std::uint32_t f = 0; f < wf; ++f) rank += anonymous_of_kind(w_, wt.fields[f], Kind::Union);
      for (std::uint32_t f = 0; f < rt.field_count; ++f) {
        if (!anonymous_of_kind(r_, rt.fields[f], Kind::Union)) continue;
        if (rank-- == 0) return used[f] ? kNoType : f;
      }
      return kNoType;
    }
    std::uint32_t best = kNoType, best_shared = 0;
    for (std::uint32_t f = 0; f < rt.field_count; ++f) {
      if (used[f] || !anonymous_of_kind(r_, rt.fields[f], member.kind)) continue;
      const TypeInfo& candidate = r_.types[rt.fields[f].type];
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

  // ---- migration hooks ------------------------------------------------------------------
  // A node "differs" when restoring it changes values beyond a plain restore: a field removed,
  // added, renamed or converted, an array length, a container's or optional's elements, a
  // variant's alternatives, at any depth. Layout (offsets, field order, bit-field widths) and
  // type names do not count: the values a hook would see are then the reader's own. Pointers do
  // not either: their pointees are objects of their own, migrated by their own hooks.
  // Computed as a least fixed point, since a recursive type's answer depends on itself.
  __attribute__((cold)) void decide_migrations() {
    bool any_hook = false;
    for (std::uint32_t t = 0; t < r_.type_count; ++t) {
      any_hook = any_hook || r_.types[t].migrate || (r_.types[t].flags & kTypeMigrated);
    }
    if (!any_hook) return;
    for (bool grew = true; grew;) {
      grew = false;
      // Children are created after their parents: backwards, most answers settle in one pass.
      for (auto it = plan_.nodes.rbegin(); it != plan_.nodes.rend(); ++it) {
        if (!differs_.count(&*it) && changes_values(*it)) {
          differs_.insert(&*it);
          grew = true;
        }
      }
    }
    for (PlanNode& n : plan_.nodes) {
      if (n.reader == kNoType || n.action != Action::Struct) continue;
      const TypeInfo& rt = r_.types[n.reader];
      n.migrates = (rt.migrate || (rt.flags & kTypeMigrated)) && differs_.count(&n);
      n.migrate = n.migrates ? rt.migrate : nullptr;
    }
  }

  bool differs(const PlanNode* n) const { return differs_.count(n) != 0; }

  // Whether `n` itself changes values, or a part already known to differ.
  bool changes_values(const PlanNode& n) const {
    if (n.reader == kNoType) return true;
    const TypeInfo& wt = w_.types[n.writer];
    const TypeInfo& rt = r_.types[n.reader];
    switch (n.action) {
      case Action::Skip: case Action::Reject: return true;
      case Action::Scalar: return !n.identical;
      case Action::Union: case Action::Pointer: case Action::SharedPtr: return false;
      case Action::String: return n.decision != Decision::Restored;
      case Action::Struct: {
        if (wt.field_count != rt.field_count) return true;
        for (const FieldPlan& field : n.fields) {
          if (field.reader_field == kNoType ||
              !same_member(field.name, rt.fields[field.reader_field].name) ||
              differs(field.node)) {
            return true;
          }
        }
        return false;
      }
      case Action::Array:
        return wt.count != n.reader_count || differs(n.element);
      case Action::Container: case Action::Optional: case Action::UniquePtr:
        return differs(n.element);
      case Action::Variant:
        if (wt.alternative_count != rt.alternative_count) return true;
        for (std::size_t a = 0; a < n.alternatives.size(); ++a) {
          if (n.alternative_map[a] != a || differs(n.alternatives[a])) return true;
        }
        return false;
    }
    return true;
  }

  // The node whose hook runs for a value: the value's own, or its optional's/unique_ptr's.
  static const PlanNode* migration_of(const PlanNode* n) {
    for (int i = 0; n && i < kMaxPlanDepth; ++i) {
      if (n->migrates) return n;
      if (n->action != Action::Optional && n->action != Action::UniquePtr) return nullptr;
      n = n->element;
    }
    return nullptr;
  }

  std::string migrated_by(const PlanNode& n) const {
    return std::string("migrated by symcr_migrate(") + r_.types[n.reader].name + ")";
  }

  // A root's or field's entry also says that its value is migrated.
  void note_migration(const PlanNode* n, Decision& decision, std::string& detail) const {
    note_unforeseen_validation(n, detail);
    const PlanNode* migrated = migration_of(n);
    if (!migrated) return;
    if (decision == Decision::Restored) decision = Decision::Converted;
    detail += (detail.empty() ? "" : "; ") + migrated_by(*migrated);
  }

  // An element (or pointee, or variant alternative) has no entry of its own unless migrated,
  // or validated where the verdict cannot be known.
  void add_migration_entry(const PlanNode* n, const std::string& path) {
    std::string detail;
    note_unforeseen_validation(n, detail);
    if (const PlanNode* migrated = migration_of(n)) {
      add(path, Decision::Converted, detail + (detail.empty() ? "" : "; ") + migrated_by(*migrated),
          false);
    } else if (!detail.empty()) {
      add(path, Decision::Restored, detail, false);
    }
  }

  // A build known only by its schema file (the CLI's plan) has validators it cannot run: each
  // value they check says so, rather than being promised.
  void note_unforeseen_validation(const PlanNode* n, std::string& detail) const {
    if (!n || n->reader == kNoType || n->action == Action::Reject) return;
    const TypeInfo& type = r_.types[n->reader];
    if (!(type.flags & kTypeValidated) || type.validate) return;
    detail += (detail.empty() ? "" : "; ") + std::string("checked by symcr_validate(") + type.name +
              ") when restored: its verdict cannot be foreseen here";
  }

  // ---- the schema-level report ---------------------------------------------------------
  // ---- copy-only programs (restore's fast path) ------------------------------------------
  static constexpr std::size_t kMaxCopyRuns = 512;
  static constexpr std::size_t kMaxCopyBools = 1024;
  static constexpr std::uint32_t kMaxCopyWire = 1u << 24;

  static void add_run(PlanNode& n, std::uint64_t wire, std::uint64_t dst, std::uint64_t length) {
    if (length == 0) return;
    if (!n.copy_runs.empty()) {
      CopyRun& last = n.copy_runs.back();
      if (std::uint64_t{last.wire} + last.length == wire &&
          std::uint64_t{last.dst} + last.length == dst) {
        last.length += static_cast<std::uint32_t>(length);
        return;
      }
    }
    n.copy_runs.push_back(CopyRun{static_cast<std::uint32_t>(wire),
                                  static_cast<std::uint32_t>(dst),
                                  static_cast<std::uint32_t>(length)});
  }

  // Appends `child`'s program at (wire, dst); false when `n` grows past the limits.
  __attribute__((noinline, cold)) static bool append_copy(PlanNode& n, const PlanNode& child, std::uint64_t wire,
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
  bool add_bit_field(PlanNode& n, const FieldPlan& field, std::uint64_t wire) {
    const PlanNode* child = field.node;
    if (!child || child->validated || child->action != Action::Scalar || !child->identical ||
        n.copy_bits.size() >= kMaxCopyBools || wire + 8 > kMaxCopyWire) {
      return false;
    }
    const TypeInfo& wt = w_.types[child->writer];
    const bool integer = wt.kind == Kind::Int || wt.kind == Kind::UInt || wt.kind == Kind::Bool;
    if (!integer || (wt.size != 1 && wt.size != 2 && wt.size != 4 && wt.size != 8)) return false;
    if (wt.kind == Kind::Bool) n.copy_bools.push_back(static_cast<std::uint32_t>(wire));
    n.copy_bits.push_back(CopyBits{static_cast<std::uint32_t>(wire), field.reader_offset,
                                   field.bit_offset, field.bit_width,
                                   static_cast<std::uint8_t>(wt.size), wt.kind == Kind::Int});
    return true;
  }

  __attribute__((noinline, cold)) void compute_copy(PlanNode& n) {
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
  void compute_copy_only_payload() {
    std::uint64_t size = 2 * sizeof(std::uint32_t);
    for (const RootPlan& root : plan_.roots) {
      if (root.reader_root == kNoType || !child_copy_only(root.node)) return;
      size += root.node->copy_wire;
    }
    plan_.copy_only_payload = true;
    plan_.copy_only_payload_size = size;
  }

  bool child_copy_only(const PlanNode* child) {
    if (!child || child->validated || child->migrates) return false;
    auto& mutable_child = const_cast<PlanNode&>(*child);  // a node of plan_.nodes
    compute_copy(mutable_child);
    return child->copy_only;
  }

  __attribute__((noinline, cold)) bool build_copy(PlanNode& n) {
    if (n.reader == kNoType || n.writer >= w_.type_count) return false;
    const TypeInfo& wt = w_.types[n.writer];
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
          if (field.bit_width) {
            if (!add_bit_field(n, field, wire)) return false;
            wire += w_.types[field.node->writer].size;
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

  __attribute__((cold)) void build_report() {
    for (std::uint32_t wr = 0; wr < w_.root_count; ++wr) {
      const RootPlan& root = plan_.roots[wr];
      const RootInfo& writer = w_.roots[wr];
      if (root.reader_root == kNoType) {
        add(writer.name, Decision::Dropped, "root not in this build", true);
        continue;
      }
      const RootInfo& reader = r_.roots[root.reader_root];
      std::string detail = root.node->detail;
      Decision decision = root.node->decision;
      if (!same_name(reader.name, writer.name)) {
        decision = decision == Decision::Rejected ? decision : Decision::Converted;
        detail = std::string("renamed from ") + writer.name + (detail.empty() ? "" : "; ") + detail;
      }
      note_migration(root.node, decision, detail);
      add(reader.name, decision, detail, root.node->lossy && root.node->action != Action::Struct);
      expand(root.node, reader.name);
    }
    for (std::uint32_t rr = 0; rr < r_.root_count; ++rr) {
      bool matched = false;
      for (const RootPlan& root : plan_.roots) matched = matched || root.reader_root == rr;
      if (!matched) add(r_.roots[rr].name, Decision::Kept, "root added in this build", false);
    }
    // Pointees once each, named by type: their fields are reached through any pointer. One
    // of a root's type was listed under the root already.
    for (std::size_t i = 0; i < pointees_.size(); ++i) {
      const PlanNode* pointee = pointees_[i];
      bool listed = false;
      for (const RootPlan& root : plan_.roots) listed = listed || root.node == pointee;
      if (listed) continue;
      const std::string path = std::string("(") + w_.types[pointee->writer].name + ")";
      add_migration_entry(pointee, path);
      expand(pointee, path);
    }
    for (const ReportEntry& entry : plan_.entries) plan_.any_lossy = plan_.any_lossy || entry.lossy;
  }

  void add(std::string path, Decision decision, std::string detail, bool lossy) {
    plan_.entries.push_back(ReportEntry{std::move(path), decision, std::move(detail), lossy});
  }

  void note_pointee(const PlanNode* n) {
    if (!n || n->action == Action::Skip) return;
    for (const PlanNode* seen : pointees_) {
      if (seen == n) return;
    }
    pointees_.push_back(n);
  }

  __attribute__((cold)) void expand(const PlanNode* n, const std::string& path) {
    for (const PlanNode* open : stack_) {
      if (open == n) return;  // recursion: listed once, where first met
    }
    stack_.push_back(n);
    switch (n->action) {
      case Action::Struct: {
        const TypeInfo& wt = w_.types[n->writer];
        const TypeInfo& rt = r_.types[n->reader];
        for (std::size_t f = 0; f < n->fields.size(); ++f) {
          const FieldPlan& field = n->fields[f];
          const FieldInfo& writer = wt.fields[f];
          if (field.reader_field == kNoType) {
            // Under a migration hook a removed field's value is handed to the hook by name:
            // a decision of the new build's code, not a loss.
            if (n->migrates) {
              add(path + "." + writer.name, Decision::Dropped,
                  "field removed in this build; its value goes to symcr_migrate(" +
                      std::string(rt.name) + ")",
                  false);
            } else if ((rt.flags & kTypeLeavesMembers) &&
                       in_aliases(writer.name, rt.left_to_new_build)) {
              // Made const (or a reference, or a code pointer) by the patch: the value is this
              // build's on purpose, not lost.
              add(path + "." + writer.name, Decision::Kept,
                  "const, reference or code pointer in this build: this build's value is kept",
                  false);
            } else {
              add(path + "." + writer.name, Decision::Dropped, "field removed in this build", true);
            }
            continue;
          }
          const FieldInfo& reader = rt.fields[field.reader_field];
          const std::string child = path + "." + reader.name;
          Decision decision = field.node->decision;
          std::string detail = field.node->detail;
          if (!same_member(reader.name, writer.name)) {
            if (decision != Decision::Rejected) decision = Decision::Converted;
            detail = std::string("renamed from ") + writer.name + (detail.empty() ? "" : "; ") + detail;
          }
          const bool own_lossy = field.node->lossy && field.node->action != Action::Struct;
          note_migration(field.node, decision, detail);
          add(child, decision, detail, own_lossy);
          expand(field.node, child);
        }
        for (std::uint32_t f = 0; f < rt.field_count; ++f) {
          bool matched = false;
          for (const FieldPlan& field : n->fields) matched = matched || field.reader_field == f;
          if (!matched) {
            add(path + "." + rt.fields[f].name, Decision::Kept, "field added in this build", false);
          }
        }
        break;
      }
      case Action::Array:
      case Action::Container:
        add_migration_entry(n->element, path + "[]");
        expand(n->element, path + "[]");
        break;
      case Action::Optional:
      case Action::UniquePtr:
        expand(n->element, path);
        break;
      case Action::Variant:
        for (std::size_t a = 0; a < n->alternatives.size(); ++a) {
          const PlanNode* alternative = n->alternatives[a];
          if (alternative->action == Action::Skip) continue;
          const std::string child = path + "<" + w_.types[alternative->writer].name + ">";
          add_migration_entry(alternative, child);
          expand(alternative, child);
        }
        break;
      case Action::Pointer:
      case Action::SharedPtr:
        note_pointee(n->element);
        break;
      default:
        break;
    }
    stack_.pop_back();
  }

  Plan& plan_;
  const Schema& w_;
  const Schema& r_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, PlanNode*> memo_;
  std::vector<const PlanNode*> stack_;
  std::vector<const PlanNode*> pointees_;
  std::set<const PlanNode*> differs_;  // nodes whose restore changes values (migration hooks)
  int depth_ = 0;
  bool too_deep_ = false;
  std::vector<bool> dynamic_bases_;  // find_dynamic_bases()
};

struct CachedPlan {
  std::uint64_t writer_hash;
  const Schema* reader;
  const TypeInfo* reader_types;
  const RootInfo* reader_roots;
  std::shared_ptr<const Plan> plan;

  bool serves(std::uint64_t hash, const Schema& r) const {
    return writer_hash == hash && reader == &r && reader_types == r.types &&
           reader_roots == r.roots;
  }
};

std::mutex& plan_cache_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::deque<CachedPlan>& plan_cache() {
  static auto* cache = new std::deque<CachedPlan>();  // never freed
  return *cache;
}

}  // namespace

bool names_match(const TypeInfo& writer, const TypeInfo& reader) {
  return same_name(writer.name, reader.name) || in_aliases(writer.name, reader.renamed_from);
}

std::shared_ptr<const Plan> plan_for(const Schema& writer, std::uint64_t writer_hash,
                                     const Schema& reader, Status& status) {
  constexpr std::size_t kMaxPlans = 8;
  {
    std::lock_guard<std::mutex> lock(plan_cache_mutex());
    for (const CachedPlan& cached : plan_cache()) {
      // The counts guard against a caller passing one hash for different schemas.
      if (cached.serves(writer_hash, reader) &&
          cached.plan->writer->type_count == writer.type_count &&
          cached.plan->writer->root_count == writer.root_count) {
        return cached.plan;
      }
    }
  }
  auto plan = std::make_shared<Plan>();
  // The plan keeps its own copy of the writer schema (a round trip through the wire form) so
  // that cached plans never point into a caller's buffers.
  serialise_blob(writer, plan->writer_blob);
  status = parse_schema(plan->writer_blob.data, plan->writer_blob.size,
                        plan->writer_copy);
  if (!status.ok()) return nullptr;
  plan->writer = &plan->writer_copy.schema();
  plan->reader = &reader;
  Planner(*plan).run();
  std::lock_guard<std::mutex> lock(plan_cache_mutex());
  plan_cache().push_front(CachedPlan{writer_hash, &reader, reader.types, reader.roots, plan});
  if (plan_cache().size() > kMaxPlans) plan_cache().pop_back();
  return plan;
}

std::shared_ptr<const Plan> cached_plan(std::uint64_t writer_hash, const Schema& reader) {
  std::lock_guard<std::mutex> lock(plan_cache_mutex());
  for (const CachedPlan& cached : plan_cache()) {
    if (cached.serves(writer_hash, reader)) return cached.plan;
  }
  return nullptr;
}

}  // namespace symcr::detail
