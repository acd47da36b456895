// The resolver (plan.cpp): a Planner builds one Plan. Internal to the runtime. Its work is
// split by job:
//   plan.cpp           running the planner: roots, matching by name, the plan cache
//   plan_nodes.cpp     a plan node per (writer type, reader type): actions, fields, enums
//   plan_report.cpp    migration hooks and the schema-level report entries
//   plan_copy.cpp      copy-only programs, restore's fast path
#ifndef SYMCR_SRC_PLANNER_HPP
#define SYMCR_SRC_PLANNER_HPP

#include <cstring>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "plan.hpp"

namespace symcr::detail::planning {

inline bool same_name(const char* a, const char* b) {
  return std::strcmp(a ? a : "", b ? b : "") == 0;
}

inline bool in_aliases(const char* name, const char* const* aliases) {
  for (std::size_t i = 0; aliases && aliases[i]; ++i) {
    if (same_name(name, aliases[i])) return true;
  }
  return false;
}

constexpr int kMaxPlanDepth = 512;

// The planner decides from what the schema records, never from whether a table's code pointer
// is set: symcr-gen plans a previous build against tables without code (plan_image.hpp), and
// its plan must be the one the running build would make. Tables written by hand may set only
// the pointer.
inline bool is_associative(const TypeInfo& container) {
  if (const auto* ops = static_cast<const ContainerOps*>(container.ops)) return !ops->append;
  return container.container_kind >= static_cast<std::uint8_t>(ContainerKind::Set);
}
inline bool is_creatable(const TypeInfo& type) {
  return type.lifecycle != nullptr || (type.flags & kTypeCreatable);
}
inline bool has_validator(const TypeInfo& type) {
  return type.validate != nullptr || (type.flags & kTypeValidated);
}

// Every method is cold: a plan is built once per pair of schemas, so the planner is compiled for
// size (tens of KB of .text) and kept off the hot pages, wherever its methods are defined.
class Planner {
 public:
  Planner(Plan& plan) : plan_(plan), writer_(*plan.writer), reader_(*plan.reader) {}

  // Once per (writer, reader) pair, then cached: cold, so that it and what only it calls are
  // optimised for size (tens of KB of .text) and kept off the hot pages.
  __attribute__((cold, noinline)) void run();
  // The schema-level report of a finished plan (Plan::entries()): touches only the plan's
  // report fields.
  __attribute__((cold)) void build_report();
  // derive_copy_segments (plan.hpp) on this planner's plan.
  __attribute__((cold)) void derive_copy_segments();

 private:
  // Per writer type: the writer knew a class equal to it or derived from it that it could save
  // as a heap object's dynamic type.
  __attribute__((cold)) void find_dynamic_bases();

  // ---- matching ------------------------------------------------------------------------
  __attribute__((cold)) std::uint32_t find_reader_type(const TypeInfo& writer) const;

  __attribute__((cold)) void plan_roots();

  __attribute__((cold)) std::uint32_t new_counter(const char* scope, const char* name);

  // ---- nodes ---------------------------------------------------------------------------
  __attribute__((cold)) const PlanNode* node(std::uint32_t writer, std::uint32_t reader);

  __attribute__((cold)) bool is_flat(std::uint32_t t, int depth) const;

  __attribute__((cold)) void fill_skip(PlanNode& n);

  __attribute__((cold)) void reject(PlanNode& n, std::string why);

  __attribute__((cold)) std::string pair_text(const TypeInfo& writer, const TypeInfo& reader) const;

  __attribute__((cold)) void fill(PlanNode& n);

  // A container-like node reports its element's decision when it has none of its own, and its
  // lossiness, at every nesting level (an inner array shrinking, a string re-encoded inside a
  // vector). Struct elements are not folded in: their fields get entries of their own, and so
  // do pointees.
  __attribute__((cold)) void inherit_element(PlanNode& n);

  __attribute__((cold)) void fill_scalar(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt);

  // A writer value with several names (an alias kept while renaming: `Loiter = 3, Hold = 3`)
  // maps through whichever of its names the reader has, whatever their declaration order: one
  // entry per value, mapped when its names that the reader knows agree on one reader value.
  static __attribute__((cold)) void collapse_enum_aliases(std::vector<EnumMapping>& map);

  __attribute__((cold)) void fill_struct(PlanNode& n, const TypeInfo& wt, const TypeInfo& rt);

  __attribute__((cold)) std::uint32_t match_field(const TypeInfo& wt, std::uint32_t wf,
                                                  const TypeInfo& rt,
                                                  const std::vector<bool>& used) const;

  // Unnamed struct and union members are named after their declaration index, which moves when
  // a field is added or removed before them. Their members are what the program names: an
  // anonymous struct matches the reader's anonymous struct sharing the most member names; an
  // anonymous union (restored as raw bytes, its members unlisted) matches the reader's anonymous
  // union of the same rank among the anonymous unions.
  static __attribute__((cold)) bool is_anonymous_member(const char* name);
  // The same member for the report: the same name, or two unnamed members matched above.
  static __attribute__((cold)) bool same_member(const char* writer, const char* reader);

  __attribute__((cold)) std::uint32_t match_anonymous_member(const TypeInfo& wt, std::uint32_t wf,
                                                             const TypeInfo& rt,
                                                             const std::vector<bool>& used) const;

  // ---- migration hooks ------------------------------------------------------------------
  // A node "differs" when restoring it changes values beyond a plain restore: a field removed,
  // added, renamed or converted, an array length, a container's or optional's elements, a
  // variant's alternatives, at any depth. Layout (offsets, field order, bit-field widths) and
  // type names do not count: the values a hook would see are then the reader's own. Pointers do
  // not either: their pointees are objects of their own, migrated by their own hooks.
  // Computed as a least fixed point, since a recursive type's answer depends on itself.
  __attribute__((cold)) void decide_migrations();

  bool differs(const PlanNode* n) const { return differs_.count(n) != 0; }

  // Whether `n` itself changes values, or a part already known to differ.
  __attribute__((cold)) bool changes_values(const PlanNode& n) const;

  // The node whose hook runs for a value: the value's own, or its optional's/unique_ptr's.
  static __attribute__((cold)) const PlanNode* migration_of(const PlanNode* n);

  __attribute__((cold)) std::string migrated_by(const PlanNode& n) const;

  // A root's or field's entry also says that its value is migrated.
  __attribute__((cold)) void note_migration(const PlanNode* n, Decision& decision,
                                            std::string& detail) const;

  // An element (or pointee, or variant alternative) has no entry of its own unless migrated,
  // or validated where the verdict cannot be known.
  __attribute__((cold)) void add_migration_entry(const PlanNode* n, const std::string& path);

  // A build known only by its schema file (the CLI's plan) has validators it cannot run: each
  // value they check says so, rather than being promised.
  __attribute__((cold)) void note_unforeseen_validation(const PlanNode* n,
                                                        std::string& detail) const;

  // ---- copy-only programs (restore's fast path) ------------------------------------------
  static constexpr std::size_t kMaxCopyRuns = 512;
  static constexpr std::size_t kMaxCopyBools = 1024;
  static constexpr std::uint32_t kMaxCopyWire = 1u << 24;

  static __attribute__((cold)) void add_run(PlanNode& n, std::uint64_t wire, std::uint64_t dst,
                                            std::uint64_t length);

  // Appends `child`'s program at (wire, dst); false when `n` grows past the limits.
  __attribute__((noinline, cold)) static bool append_copy(PlanNode& n, const PlanNode& child,
                                                          std::uint64_t wire, std::uint64_t dst);

  // An integer or bool bit-field whose writer and reader types are identical, at `wire`.
  __attribute__((cold)) bool add_bit_field(PlanNode& n, const FieldPlan& field, std::uint64_t wire);

  __attribute__((noinline, cold)) void compute_copy(PlanNode& n);

  // The whole payload is copy-only when every writer root is kept and copy-only: then it is
  // the roots' copy programs back to back and two empty sections (heap objects, references).
  __attribute__((cold)) void compute_copy_only_payload();

  __attribute__((cold)) bool child_copy_only(const PlanNode* child);

  __attribute__((noinline, cold)) bool build_copy(PlanNode& n);

  // A field a copy segment can hold: kept, no range or bit-field, not a time of a clock
  // (FieldPlan::time set), and copy-only without a validator or migration of its own.
  __attribute__((cold)) static bool segment_field(const FieldPlan& field);
  __attribute__((cold)) void derive_segments(PlanNode& n);

  __attribute__((cold)) void add(std::string path, Decision decision, std::string detail,
                                 bool lossy);

  __attribute__((cold)) void note_pointee(const PlanNode* n);

  __attribute__((cold)) void expand(const PlanNode* n, const std::string& path);

  // A field removed and one of the same type added in the same struct is most often a rename
  // without its annotation: "; did you mean ..." naming the annotation for the pair, or ""
  // when `candidates` (the other side's fields of that type) is empty.
  __attribute__((cold)) static std::string rename_hint(const TypeInfo& reader_type,
                                                       const char* old_name, const char* new_name,
                                                       std::size_t candidates);

  Plan& plan_;
  const Schema& writer_;
  const Schema& reader_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, PlanNode*> memo_;
  std::vector<const PlanNode*> stack_;
  std::vector<const PlanNode*> pointees_;
  std::set<const PlanNode*> differs_;  // nodes whose restore changes values (migration hooks)
  int depth_ = 0;
  bool too_deep_ = false;
  std::vector<bool> dynamic_bases_;  // find_dynamic_bases()
};

}  // namespace symcr::detail::planning

#endif  // SYMCR_SRC_PLANNER_HPP
