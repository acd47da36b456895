// Resolution: which values migration hooks change, and the schema-level report entries of a
// plan (planner.hpp).
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

// ---- migration hooks ------------------------------------------------------------------
// A node "differs" when restoring it changes values beyond a plain restore: a field removed,
// added, renamed or converted, an array length, a container's or optional's elements, a
// variant's alternatives, at any depth. Layout (offsets, field order, bit-field widths) and
// type names do not count: the values a hook would see are then the reader's own. Pointers do
// not either: their pointees are objects of their own, migrated by their own hooks.
// Computed as a least fixed point, since a recursive type's answer depends on itself.
void Planner::decide_migrations() {
  bool any_hook = false;
  for (std::uint32_t t = 0; t < reader_.type_count; ++t) {
    any_hook = any_hook || reader_.types[t].migrate || (reader_.types[t].flags & kTypeMigrated);
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
    const TypeInfo& rt = reader_.types[n.reader];
    n.migrates = (rt.migrate || (rt.flags & kTypeMigrated)) && differs_.count(&n);
    n.migrate = n.migrates ? rt.migrate : nullptr;
  }
}

// Whether `n` itself changes values, or a part already known to differ.
bool Planner::changes_values(const PlanNode& n) const {
  if (n.reader == kNoType) return true;
  const TypeInfo& wt = writer_.types[n.writer];
  const TypeInfo& rt = reader_.types[n.reader];
  switch (n.action) {
    case Action::Skip:
    case Action::Reject:
      return true;
    case Action::Scalar:
      return !n.identical;
    case Action::Union:
    case Action::Pointer:
    case Action::SharedPtr:
      return false;
    case Action::String:
      return n.decision != Decision::Restored;
    case Action::Struct: {
      if (wt.field_count != rt.field_count) return true;
      for (const FieldPlan& field : n.fields) {
        if (field.reader_field == kNoType ||
            !same_member(field.name, rt.fields[field.reader_field].name) || differs(field.node)) {
          return true;
        }
      }
      return false;
    }
    case Action::Array:
      return wt.count != n.reader_count || differs(n.element);
    case Action::Container:
    case Action::Optional:
    case Action::UniquePtr:
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
const PlanNode* Planner::migration_of(const PlanNode* n) {
  for (int i = 0; n && i < kMaxPlanDepth; ++i) {
    if (n->migrates) return n;
    if (n->action != Action::Optional && n->action != Action::UniquePtr) return nullptr;
    n = n->element;
  }
  return nullptr;
}

std::string Planner::migrated_by(const PlanNode& n) const {
  return std::string("migrated by symcr_migrate(") + reader_.types[n.reader].name + ")";
}

// A root's or field's entry also says that its value is migrated.
void Planner::note_migration(const PlanNode* n, Decision& decision, std::string& detail) const {
  note_unforeseen_validation(n, detail);
  const PlanNode* migrated = migration_of(n);
  if (!migrated) return;
  if (decision == Decision::Restored) decision = Decision::Converted;
  detail += (detail.empty() ? "" : "; ") + migrated_by(*migrated);
}

// An element (or pointee, or variant alternative) has no entry of its own unless migrated,
// or validated where the verdict cannot be known.
void Planner::add_migration_entry(const PlanNode* n, const std::string& path) {
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
void Planner::note_unforeseen_validation(const PlanNode* n, std::string& detail) const {
  if (!n || n->reader == kNoType || n->action == Action::Reject) return;
  const TypeInfo& type = reader_.types[n->reader];
  if (!(type.flags & kTypeValidated) || type.validate) return;
  detail += (detail.empty() ? "" : "; ") + std::string("checked by symcr_validate(") + type.name +
            ") when restored: its verdict cannot be foreseen here";
}

void Planner::build_report() {
  for (std::uint32_t wr = 0; wr < writer_.root_count; ++wr) {
    const RootPlan& root = plan_.roots[wr];
    const RootInfo& writer = writer_.roots[wr];
    if (root.reader_root == kNoType) {
      add(writer.name, Decision::Dropped, "root not in this build", true);
      continue;
    }
    const RootInfo& reader = reader_.roots[root.reader_root];
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
  for (std::uint32_t rr = 0; rr < reader_.root_count; ++rr) {
    bool matched = false;
    for (const RootPlan& root : plan_.roots) matched = matched || root.reader_root == rr;
    if (!matched) add(reader_.roots[rr].name, Decision::Kept, "root added in this build", false);
  }
  // Pointees once each, named by type: their fields are reached through any pointer. One
  // of a root's type was listed under the root already.
  std::size_t listed_pointees = 0;
  const auto list_pointees = [&] {
    for (; listed_pointees < pointees_.size(); ++listed_pointees) {
      const PlanNode* pointee = pointees_[listed_pointees];
      bool listed = false;
      for (const RootPlan& root : plan_.roots) listed = listed || root.node == pointee;
      if (listed) continue;
      const std::string path = std::string("(") + writer_.types[pointee->writer].name + ")";
      add_migration_entry(pointee, path);
      expand(pointee, path);
    }
  };
  list_pointees();
  // A heap object behind a pointer to a polymorphic base is saved as its own class, which
  // restore maps by name like any pointee (Planner::run): each such class of the writer is
  // listed too, after the pointees, whose fields its own entries then complete.
  for (std::uint32_t t = 0; t < writer_.type_count; ++t) {
    const TypeInfo& type = writer_.types[t];
    if (!(type.flags & kTypeDynamicType) || type.kind != Kind::Struct || !plan_.heap_nodes[t]) {
      continue;
    }
    const PlanNode* heap = plan_.heap_nodes[t];
    if (heap->reader == kNoType) {
      // Not lossy by itself: a checkpoint may hold no object of it. One that does has each
      // pointer to it rejected, value by value.
      add(std::string("(") + type.name + ")", Decision::Dropped,
          "class not in this build: a heap object of it is not rebuilt", false);
      continue;
    }
    note_pointee(heap);
    list_pointees();
  }
  for (const ReportEntry& entry : plan_.report_entries) {
    plan_.report_lossy = plan_.report_lossy || entry.lossy;
  }
}

std::string Planner::rename_hint(const TypeInfo& reader_type, const char* old_name,
                                 const char* new_name, std::size_t candidates) {
  if (candidates == 0) return "";
  const std::string annotation = std::string("SYMCR_RENAMED_FROM(\"") + old_name + "\") on " +
                                 new_name + " / renamed(" + reader_type.name + "::" + new_name +
                                 ", " + old_name + ")";
  return "; did you mean " + annotation +
         (candidates > 1 ? " (or another field of the same type)?" : "?");
}

void Planner::add(std::string path, Decision decision, std::string detail, bool lossy) {
  plan_.report_entries.push_back(ReportEntry{std::move(path), decision, std::move(detail), lossy});
}

void Planner::note_pointee(const PlanNode* n) {
  if (!n || n->action == Action::Skip) return;
  for (const PlanNode* seen : pointees_) {
    if (seen == n) return;
  }
  pointees_.push_back(n);
}

void Planner::expand(const PlanNode* n, const std::string& path) {
  for (const PlanNode* open : stack_) {
    if (open == n) return;  // recursion: listed once, where first met
  }
  stack_.push_back(n);
  switch (n->action) {
    case Action::Struct: {
      const TypeInfo& wt = writer_.types[n->writer];
      const TypeInfo& rt = reader_.types[n->reader];
      std::vector<bool> reader_matched(rt.field_count, false);
      for (const FieldPlan& field : n->fields) {
        if (field.reader_field != kNoType) reader_matched[field.reader_field] = true;
      }
      // The fields whose value is lost (not handed to a hook, not left to this build) and the
      // fields added: pairs of the same type get a rename hint.
      const auto lost = [&](std::size_t f) {
        return n->fields[f].reader_field == kNoType && !n->migrates &&
               !((rt.flags & kTypeLeavesMembers) &&
                 in_aliases(wt.fields[f].name, rt.left_to_new_build));
      };
      const auto same_type = [&](const FieldInfo& writer, const FieldInfo& reader) {
        const TypeInfo& a = writer_.types[writer.type];
        const TypeInfo& b = reader_.types[reader.type];
        return a.kind == b.kind && same_name(a.name, b.name);
      };
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
          } else if (!lost(f)) {
            // Made const (or a reference, or a code pointer) by the patch: the value is this
            // build's on purpose, not lost.
            add(path + "." + writer.name, Decision::Kept,
                "const, reference or code pointer in this build: this build's value is kept",
                false);
          } else {
            std::size_t candidates = 0;
            const char* added = nullptr;
            for (std::uint32_t r = 0; r < rt.field_count; ++r) {
              if (reader_matched[r] || !same_type(writer, rt.fields[r])) continue;
              if (candidates++ == 0) added = rt.fields[r].name;
            }
            add(path + "." + writer.name, Decision::Dropped,
                "field removed in this build" + rename_hint(rt, writer.name, added, candidates),
                true);
          }
          continue;
        }
        const FieldInfo& reader = rt.fields[field.reader_field];
        const std::string child = path + "." + reader.name;
        Decision decision = field.node->decision;
        std::string detail = field.node->detail;
        if (!same_member(reader.name, writer.name)) {
          if (decision != Decision::Rejected) decision = Decision::Converted;
          detail =
              std::string("renamed from ") + writer.name + (detail.empty() ? "" : "; ") + detail;
        }
        bool own_lossy = field.node->lossy && field.node->action != Action::Struct;
        if (n->migrates && field.node->action == Action::Reject) {
          // A kind change: like a removed field, its old value goes to the hook by name.
          decision = Decision::Converted;
          detail += "; the old value goes to symcr_migrate(" + std::string(rt.name) + ")";
          own_lossy = false;
        }
        if (const FieldTime* time = reader_time(reader_, *n, field)) {
          const std::string clock = std::string("a time of clock '") +
                                    (time->clock->name ? time->clock->name : "?") +
                                    "' (never: " + std::to_string(time->never) + ")";
          if (plan_.writer_clock_of[time->clock->index] == kNoType) {
            // Not a value the rules refuse: a time no clock of this build can place. The new
            // build's own value (its "never") stands, as for a member the old build lacked.
            decision = Decision::Kept;
            detail =
                clock + ", of which the checkpoint holds no reading: this build's value is kept";
            own_lossy = true;
          } else if (decision == Decision::Restored || decision == Decision::Converted) {
            decision = Decision::Rebased;
            detail = clock + (detail.empty() ? "" : "; " + detail);
          }
        }
        note_migration(field.node, decision, detail);
        add(child, decision, detail, own_lossy);
        expand(field.node, child);
      }
      for (std::uint32_t r = 0; r < rt.field_count; ++r) {
        if (reader_matched[r]) continue;
        std::size_t candidates = 0;
        const char* removed = nullptr;
        for (std::size_t f = 0; f < n->fields.size(); ++f) {
          if (!lost(f) || !same_type(wt.fields[f], rt.fields[r])) continue;
          if (candidates++ == 0) removed = wt.fields[f].name;
        }
        add(path + "." + rt.fields[r].name, Decision::Kept,
            "field added in this build" + rename_hint(rt, removed, rt.fields[r].name, candidates),
            false);
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
        const std::string child = path + "<" + writer_.types[alternative->writer].name + ">";
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

}  // namespace symcr::detail::planning

namespace symcr::detail {

// The report is written from the finished plan: its nodes, decisions and migration hooks.
__attribute__((cold)) const std::vector<ReportEntry>& Plan::entries() const {
  std::call_once(report_written,
                 [this] { planning::Planner(const_cast<Plan&>(*this)).build_report(); });
  return report_entries;
}

bool Plan::any_lossy() const {
  entries();
  return report_lossy;
}

}  // namespace symcr::detail
