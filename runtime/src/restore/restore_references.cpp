// Restore: the reference table, the decision for each pointer, heap objects and the fix-up of
// pointer slots after all values are written (restorer.hpp).
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "report_access.hpp"
#include "planner.hpp"
#include "restore_traversal.hpp"
#include "schema_facts.hpp"

namespace symcr::detail::restoring {

// ---- references ----------------------------------------------------------------------
bool Restorer::decode_references(PayloadReader& in) {
  std::uint32_t count = 0;
  if (!in.reference_count(count)) return false;
  refs_.resize(count);
  const std::uint32_t object_count = writer_.root_count + static_cast<std::uint32_t>(heap_.size());
  auto object_type = [&](std::uint32_t a, std::uint32_t& type) {
    if (a >= object_count) return false;
    type = a < writer_.root_count ? writer_.roots[a].type : heap_[a - writer_.root_count].type;
    return true;
  };
  auto element_type = [&](std::uint32_t a, std::uint32_t b, std::uint32_t& type) {
    if (a >= containers_.size() || b >= containers_[a].count) return false;
    type = containers_[a].element->writer;
    return true;
  };
  auto on_step = [&](std::uint32_t step) { steps_.push_back(step); };
  for (std::uint32_t i = 0; i < count; ++i) {
    RefRecord& ref = refs_[i];
    ref.steps_at = static_cast<std::uint32_t>(steps_.size());
    if (!in.reference(i, ref, object_type, element_type, on_step)) return false;
  }
  return true;
}

bool Restorer::check_slots() {
  for (const SlotRecord& slot : slots_) {
    if (slot.code < kFirstReference) continue;
    const std::uint32_t index = slot.code - kFirstReference;
    if (index >= refs_.size())
      return corrupt("pointer to reference %u of %zu", index, refs_.size()).ok();
    const RefRecord& ref = refs_[index];
    if (ref.target != writer_.types[slot.pointer_type].element) {
      return corrupt("a %s refers to a %s", writer_.types[slot.pointer_type].name,
                     writer_.types[ref.target].name)
          .ok();
    }
    if (slot.shared && (ref.base != 0 || ref.a < writer_.root_count || ref.step_count != 0 ||
                        heap_[ref.a - writer_.root_count].owner != 1)) {
      return corrupt("a shared_ptr refers to something other than a shared heap object").ok();
    }
  }
  return true;
}

bool Restorer::inside_reader_root(std::uintptr_t address) const {
  for (std::uint32_t r = 0; r < reader_.root_count; ++r) {
    const auto start = reinterpret_cast<std::uintptr_t>(reader_.roots[r].address);
    if (address >= start && address < start + reader_.types[reader_.roots[r].type].size)
      return true;
  }
  return false;
}

// docs/resolution.md, pointers: a non-null pointer the new build already holds, of the pointee's
// type, lends its object to the heap object it now refers to (once; never an object in a root).
void Restorer::claim_live_objects() {
  claimed_.assign(heap_.size(), nullptr);
  if (heap_.empty()) return;  // most states: pointers into the roots only
  std::unordered_set<std::uintptr_t> taken;
  for (const SlotRecord& slot : slots_) {
    if (!slot.node || slot.shared || slot.code < kFirstReference || !slot.live) continue;
    const RefRecord& ref = refs_[slot.code - kFirstReference];
    if (ref.base != 0 || ref.a < writer_.root_count || ref.step_count != 0) continue;
    const std::uint32_t h = ref.a - writer_.root_count;
    if (heap_[h].owner != 0 || claimed_[h]) continue;
    if (heap_[h].node->reader == kNoType || heap_[h].node->reader != slot.node->element->reader)
      continue;
    if (inside_reader_root(slot.live) || !taken.insert(slot.live).second) continue;
    claimed_[h] = reinterpret_cast<void*>(slot.live);
  }
}

// A heap object is created (or claimed) only when the new build can make it and a pointer
// that will really be restored reaches it from a restored root, so nothing is allocated for
// pointers in dropped fields. A shared_ptr object must be reached through a shared_ptr: with
// no restored owner it would die at once and leave raw pointers to it dangling.
void Restorer::decide_materialisation() {
  if (heap_.empty()) {
    materialisable_.clear();
    return;
  }
  const std::uint32_t roots = writer_.root_count;
  const std::size_t objects = roots + heap_.size();
  std::vector<bool> creatable(heap_.size(), false);
  for (std::size_t h = 0; h < heap_.size(); ++h) {
    const PlanNode* node = heap_[h].node;
    if (node->reader == kNoType || node->action == Action::Reject) continue;
    const TypeInfo& type = reader_.types[node->reader];
    const bool can_create =
        type.lifecycle != nullptr || (dry_run_ && (type.flags & kTypeCreatable) != 0);
    // A claimed object keeps this build's values where the checkpoint's were refused.
    creatable[h] =
        claimed_[h] || (!heap_[h].refused && heap_[h].owner == 0 && can_create) ||
        (!heap_[h].refused && heap_[h].owner == 1 && plan_.shared_types[node->reader] != kNoType);
  }
  // Every heap object was discovered from a root when saved: if every root, heap object and
  // pointer slot is restorable, all of them are reached and the walk below can be skipped.
  bool everything_restorable = true;
  for (std::uint32_t r = 0; r < roots && everything_restorable; ++r) {
    everything_restorable = plan_.roots[r].reader_root != kNoType;
  }
  for (std::size_t h = 0; h < heap_.size() && everything_restorable; ++h) {
    everything_restorable = creatable[h] && heap_[h].node->action != Action::Skip;
  }
  for (const SlotRecord& slot : slots_) {
    if (!everything_restorable) break;
    if (slot.code < kFirstReference) continue;
    everything_restorable = slot.node != nullptr;
    if (everything_restorable && slot.shared) {  // shared targets are whole heap objects
      const std::uint32_t h = refs_[slot.code - kFirstReference].a - roots;
      everything_restorable = heap_[h].node->reader == slot.node->element->reader;
    }
  }
  if (everything_restorable) {
    materialisable_ = creatable;
    return;
  }
  // Slots grouped by their holding object (a counting sort).
  std::vector<std::uint32_t> first(objects + 1, 0);
  for (const SlotRecord& slot : slots_) ++first[slot.object + 1];
  for (std::size_t o = 0; o < objects; ++o) first[o + 1] += first[o];
  std::vector<std::uint32_t> by_object(slots_.size());
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::uint32_t s = 0; s < slots_.size(); ++s) by_object[next[slots_[s].object]++] = s;
  }
  materialisable_.assign(heap_.size(), false);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t r = 0; r < roots; ++r) {
    if (plan_.roots[r].reader_root != kNoType) queue.push_back(r);
  }
  while (!queue.empty()) {
    const std::uint32_t object = queue.back();
    queue.pop_back();
    for (std::uint32_t i = first[object]; i < first[object + 1]; ++i) {
      const SlotRecord& slot = slots_[by_object[i]];
      if (!slot.node || slot.code < kFirstReference) continue;
      const RefRecord& ref = refs_[slot.code - kFirstReference];
      const std::uint32_t target = ref.base == kBaseObject ? ref.a : containers_[ref.a].object;
      if (target < roots) continue;
      const std::uint32_t h = target - roots;
      if (!creatable[h] || materialisable_[h]) continue;
      if (heap_[h].owner == 1 &&
          (!slot.shared || heap_[h].node->reader != slot.node->element->reader)) {
        continue;
      }
      materialisable_[h] = true;
      queue.push_back(target);
    }
  }
}

namespace {

// The reader's member (a field, or else a reference member) the writer's `member` maps to, by
// name or the reader's renamed_from, bases to bases; kNoType when the reader has none. Its
// offset and type go to `offset` and `type`.
bool reader_member(const TypeInfo& reader, const FieldInfo& member, std::uint32_t& offset,
                   std::uint32_t& type) {
  const bool base = (member.flags & kFieldBase) != 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::uint32_t count = reader.field_count + reader.reference_member_count;
    for (std::uint32_t m = 0; m < count; ++m) {
      const FieldInfo& candidate = *step_member(reader, m);
      if (((candidate.flags & kFieldBase) != 0) != base || candidate.bit_width != 0) continue;
      if (pass == 0 ? planning::same_name(candidate.name, member.name)
                    : planning::in_aliases(member.name, candidate.renamed_from)) {
        offset = candidate.offset;
        type = candidate.type;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

// The steps of `ref` from `from` on, which enter a member whose value is not saved (a
// reference member): no plan node covers them, so each is matched by name in the reader's
// types (fields and reference members alike), never by offset, like a plan would.
void Restorer::map_by_names(RefRecord& ref, std::uint32_t writer, std::uint32_t reader,
                            std::uint16_t from) {
  for (std::uint16_t s = from; s < ref.step_count; ++s) {
    const std::uint32_t step = steps_[ref.steps_at + s];
    const std::uint32_t holder = reader;
    const TypeInfo& wt = writer_.types[writer];
    const TypeInfo& rt = reader_.types[reader];
    if (wt.kind != rt.kind) {
      ref.why = std::string("target's enclosing type ") + wt.name + " changed incompatibly";
      return;
    }
    std::uint64_t offset = 0;
    if (wt.kind == Kind::Struct) {
      const FieldInfo* member = step_member(wt, step);
      std::uint32_t member_offset = 0;
      if (!member || !reader_member(rt, *member, member_offset, reader)) {
        ref.why = std::string("target member ") + (member ? member->name : "?") + " of " + wt.name +
                  " not in this build";
        return;
      }
      writer = member->type;
      offset = member_offset;
    } else if (wt.kind == Kind::Array) {
      if (step >= rt.count) {
        ref.why = "target element " + std::to_string(step) + " beyond this build's array";
        return;
      }
      offset = std::uint64_t{step} * reader_.types[rt.element].size;
      writer = wt.element;
      reader = rt.element;
    } else {
      ref.why = std::string("target lies inside a ") + wt.name + " whose value is not checkpointed";
      return;
    }
    mapped_.push_back({MappedStep::Kind::Offset, holder, offset});
  }
  if (!names_match(writer_.types[writer], reader_.types[reader])) {
    ref.why = std::string("target is a ") + reader_.types[reader].name + " in this build, not a " +
              writer_.types[writer].name;
    return;
  }
  ref.mapped_count = static_cast<std::uint32_t>(mapped_.size()) - ref.mapped_at;
  ref.reader_type = reader;
  ref.resolved = true;
}

// Maps a reference's writer steps onto reader steps by name (via the plan), never offsets.
void Restorer::map_reference(RefRecord& ref) {
  const PlanNode* node = nullptr;
  if (ref.base == kBaseObject && ref.a < writer_.root_count) {
    const RootPlan& root = plan_.roots[ref.a];
    if (root.reader_root == kNoType) {
      ref.why = std::string("root ") + writer_.roots[ref.a].name + " not in this build";
      return;
    }
    node = root.node;
  } else if (ref.base == kBaseObject) {
    const std::uint32_t h = ref.a - writer_.root_count;
    if (!materialisable_[h]) {
      ref.why =
          std::string("heap object of type ") + writer_.types[heap_[h].type].name +
          (heap_[h].refused && heap_[h].validator ? " holds a value its symcr_validate refused"
           : heap_[h].refused                     ? " holds a value this build rejects"
           : heap_[h].owner == 1 ? " has no shared_ptr owner restored in this build"
                                 : " cannot be created in this build or is not "
                                   "reached from a restored root");
      return;
    }
    node = heap_[h].node;
  } else {
    node = containers_[ref.a].element;
    element_needed_.push_back(ref.a);
  }
  ref.mapped_at = static_cast<std::uint32_t>(mapped_.size());
  for (std::uint16_t s = 0; s < ref.step_count; ++s) {
    const std::uint32_t step = steps_[ref.steps_at + s];
    if (node->action == Action::Skip || node->action == Action::Reject) break;
    switch (node->action) {
      case Action::Struct: {
        if (step >= node->fields.size()) {
          // A member whose value is not saved: no plan node, matched by name from here on.
          map_by_names(ref, node->writer, node->reader, s);
          return;
        }
        const FieldPlan& field = node->fields[step];
        if (field.reader_field == kNoType) {
          ref.why = std::string("target field ") + field.name + " removed in this build";
          return;
        }
        mapped_.push_back({MappedStep::Kind::Offset, node->reader, field.reader_offset});
        node = field.node;
        break;
      }
      case Action::Array:
        if (step >= node->reader_count) {
          ref.why = "target element " + std::to_string(step) + " beyond this build's array";
          return;
        }
        mapped_.push_back(
            {MappedStep::Kind::Offset, node->reader, std::uint64_t{step} * node->reader_stride});
        node = node->element;
        break;
      case Action::Optional:
        mapped_.push_back({MappedStep::Kind::Optional, node->reader, 0});
        node = node->element;
        break;
      case Action::UniquePtr:
        mapped_.push_back({MappedStep::Kind::Unique, node->reader, 0});
        node = node->element;
        break;
      case Action::Variant: {
        const std::uint32_t reader_index = node->alternative_map[step];
        if (reader_index == kNoType) {
          ref.why = "target alternative not in this build";
          return;
        }
        mapped_.push_back({MappedStep::Kind::Variant, node->reader, reader_index});
        node = node->alternatives[step];
        break;
      }
      case Action::String:
        // The same character of the restored string: its index holds only while the
        // characters are copied, not re-encoded.
        if (writer_.types[writer_.types[node->writer].element].size !=
            reader_.types[reader_.types[node->reader].element].size) {
          ref.why = "target is a character of a string re-encoded in this build";
          return;
        }
        mapped_.push_back({MappedStep::Kind::Character, node->reader, step});
        node = node->element;
        break;
      default:
        ref.why = "target's enclosing type changed";
        return;
    }
  }
  if (node->action == Action::Skip || node->action == Action::Reject) {
    ref.why =
        std::string("target's type ") + writer_.types[ref.target].name + " changed incompatibly";
    return;
  }
  ref.mapped_count = static_cast<std::uint32_t>(mapped_.size()) - ref.mapped_at;
  ref.reader_type = node->reader;
  ref.resolved = true;
}

// Decides every pointer slot; the concrete paths of the few reported ones are rendered by a
// third walk rather than remembered for every pointer of a large graph.
void Restorer::decide_slots() {
  struct Pending {
    std::uint32_t ordinal;
    Decision decision;
    std::string detail;
  };
  std::vector<Pending> pending;
  std::size_t outside_count = 0;
  for (std::size_t ordinal = 0; ordinal < slots_.size(); ++ordinal) {
    SlotRecord& slot = slots_[ordinal];
    if (!slot.node) continue;
    auto reject = [&](const std::string& why) {
      slot.outcome = SlotOutcome::Rejected;
      ++value_rejections_;
      if (++entry_count(rejection_counts_, slot.counter) > kMaxConcretePerField) return;
      pending.push_back({static_cast<std::uint32_t>(ordinal), Decision::Rejected,
                         "pointer not restored: " + why});
    };
    if (slot.code == kNullCode) {
      slot.outcome = SlotOutcome::Null;
    } else if (slot.code == kOutsideCode) {
      slot.outcome = SlotOutcome::Outside;
      if (++outside_count <= kMaxConcretePerField) {
        pending.push_back({static_cast<std::uint32_t>(ordinal), Decision::Kept,
                           "pointed outside the checkpointed state: kept this build's value"});
      }
    } else {
      const RefRecord& ref = refs_[slot.code - kFirstReference];
      if (!ref.resolved) {
        reject(ref.why);
      } else if (ref.reader_type != slot.node->element->reader) {
        reject(std::string("target is a ") + reader_.types[ref.reader_type].name +
               " in this build, not a " + reader_.types[slot.node->element->reader].name);
      } else {
        slot.outcome = SlotOutcome::Target;
      }
    }
  }
  if (!pending.empty()) {
    for (const Pending& entry : pending) explained_[entry.ordinal];
    ExplainPass pass(explained_);
    Traversal<ExplainPass>(*this, pass).objects();  // cannot fail: pass 1 decoded the same bytes
    for (Pending& entry : pending) {
      ReportAccess::add(report_, explained_[entry.ordinal], entry.decision, std::move(entry.detail),
                        entry.decision == Decision::Rejected);
    }
  }
  if (outside_count > kMaxConcretePerField) {
    ReportAccess::add(report_, "pointers", Decision::Kept,
                      "and " + std::to_string(outside_count - kMaxConcretePerField) +
                          " more pointed outside the checkpointed state",
                      false);
  }
}

// ---- pass 2 --------------------------------------------------------------------------
void Restorer::create_heap_objects() {
  heap_live_.assign(heap_.size(), nullptr);
  holders_.assign(heap_.size(), nullptr);
  for (std::size_t h = 0; h < heap_.size(); ++h) {
    if (!materialisable_[h]) continue;
    if (claimed_[h]) {
      heap_live_[h] = claimed_[h];
      continue;
    }
    const std::uint32_t reader = heap_[h].node->reader;
    if (heap_[h].owner == 0) {
      heap_live_[h] = reader_.types[reader].lifecycle->create();
    } else {
      const auto* ops =
          static_cast<const SharedPtrOps*>(reader_.types[plan_.shared_types[reader]].ops);
      holders_[h] = ops->make_holder();
      heap_live_[h] = ops->holder_get(holders_[h]);
    }
  }
  element_slots_.assign(containers_.size(), kNoType);
  for (std::uint32_t ordinal : element_needed_) {
    if (element_slots_[ordinal] != kNoType) continue;
    // The lists of an earlier restore on this thread are reused with their capacity.
    element_slots_[ordinal] = static_cast<std::uint32_t>(element_lists_);
    if (element_lists_ == element_addresses_.size()) element_addresses_.emplace_back();
    std::vector<void*>& addresses = element_addresses_[element_lists_++];
    addresses.clear();
    addresses.reserve(containers_[ordinal].count);
  }
}

void* Restorer::target_of(const RefRecord& ref) {
  std::uint8_t* at = nullptr;
  if (ref.base == kBaseObject && ref.a < writer_.root_count) {
    at = static_cast<std::uint8_t*>(reader_.roots[plan_.roots[ref.a].reader_root].address);
  } else if (ref.base == kBaseObject) {
    at = static_cast<std::uint8_t*>(heap_live_[ref.a - writer_.root_count]);
  } else {
    const std::uint32_t slot = element_slots_[ref.a];
    const std::vector<void*>& addresses = element_addresses_[slot];
    if (ref.b < addresses.size()) at = static_cast<std::uint8_t*>(addresses[ref.b]);
  }
  for (std::uint32_t s = 0; s < ref.mapped_count && at; ++s) {
    const MappedStep& step = mapped_[ref.mapped_at + s];
    const void* ops = reader_.types[step.holder_type].ops;
    switch (step.kind) {
      case MappedStep::Kind::Offset:
        at += step.value;
        break;
      case MappedStep::Kind::Optional:
        at = static_cast<std::uint8_t*>(
            const_cast<void*>(static_cast<const OptionalOps*>(ops)->get(at)));
        break;
      case MappedStep::Kind::Unique:
        at = static_cast<std::uint8_t*>(
            const_cast<void*>(static_cast<const UniquePtrOps*>(ops)->get(at)));
        break;
      case MappedStep::Kind::Variant: {
        const auto* variant = static_cast<const VariantOps*>(ops);
        at = variant->index(at) == step.value
                 ? static_cast<std::uint8_t*>(const_cast<void*>(variant->get(at)))
                 : nullptr;
        break;
      }
      case MappedStep::Kind::Character: {
        // Into the restored string's own storage, up to its terminator.
        const auto* string = static_cast<const StringOps*>(ops);
        const std::uint32_t width = reader_.types[reader_.types[step.holder_type].element].size;
        at = step.value <= string->size(at)
                 ? static_cast<std::uint8_t*>(const_cast<void*>(string->data(at))) +
                       step.value * width
                 : nullptr;
        break;
      }
    }
  }
  return at;
}

void Restorer::fix_up_slots() {
  for (const AppliedSlot& applied : applied_slots_) {
    const SlotRecord& slot = slots_[applied.ordinal];
    const auto* shared_ops =
        slot.shared ? static_cast<const SharedPtrOps*>(reader_.types[slot.node->reader].ops)
                    : nullptr;
    switch (slot.outcome) {
      case SlotOutcome::Null:
        if (shared_ops)
          shared_ops->reset(applied.address);
        else
          std::memset(applied.address, 0, sizeof(void*));
        break;
      case SlotOutcome::Target: {
        const RefRecord& ref = refs_[slot.code - kFirstReference];
        if (shared_ops) {
          shared_ops->assign_from_holder(applied.address, holders_[ref.a - writer_.root_count]);
          break;
        }
        void* target = target_of(ref);
        if (!target) {
          ReportAccess::add(report_, counter_path(slot.counter), Decision::Rejected,
                            "pointer not restored: its target does not exist after restore", true);
          break;
        }
        std::memcpy(applied.address, &target, sizeof target);
        break;
      }
      default:
        break;
    }
  }
}

}  // namespace symcr::detail::restoring
