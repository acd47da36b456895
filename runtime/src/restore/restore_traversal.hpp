// Restore's one traversal of a payload along its plan, and the passes that run it
// (restorer.hpp). Internal to the runtime; the traversal's code is in restore_values.cpp,
// instantiated there for each pass.
//
// Like walk_value<Sink> (payload_grammar.hpp), the walk is written once and a pass says what
// happens at its points: a value's bytes, a container, a pointer slot, a heap object, a value
// rejected. The passes:
//   CheckPass    pass 1: reads and judges everything, records what later passes look up, never
//                writes; judges each validated value by decoding it again into a staged copy
//   StagePass    that staged decoding, inside pass 1: writes the copy, records nothing
//   ApplyPass    pass 2: writes live objects, records slot and element addresses
//   ExplainPass  between the passes, only if needed: renders the paths of reported pointers
// A traversal owns where it stands: its payload reader and its Cursors. A staged value is a
// traversal of its own, started from the outer one's position and cursors, so nothing is
// rewound.
#ifndef SYMCR_SRC_RESTORE_TRAVERSAL_HPP
#define SYMCR_SRC_RESTORE_TRAVERSAL_HPP

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "restorer.hpp"

namespace symcr::detail::restoring {

// The ordinals a traversal has passed, in stream order: every pass walks the payload alike, so
// each finds at its ordinal what pass 1 recorded there (pass 1 appends at its ordinals).
struct Cursors {
  std::uint32_t container = 0;  // containers (ContainerRecord, element address lists)
  std::uint32_t slot = 0;       // pointer slots (SlotRecord)
  std::size_t verdict = 0;      // validated values' verdicts
  std::size_t part = 0;         // verdicts of parts judged whole (Traversal::begin_part)
};

template <typename Pass>
class Traversal {
 public:
  // A walk of the whole payload from its first byte.
  Traversal(Restorer& restorer, Pass& pass);
  // The value `outer` is at, decoded again from `start` with the cursors `at` it had there, in
  // `outer`'s context (path, nesting, field, clock time, migrated object).
  template <typename Outer>
  Traversal(const Traversal<Outer>& outer, Pass& pass, const std::uint8_t* start,
            const Cursors& at);

  // The roots, then the heap objects.
  bool objects();
  // The value of plan node `n` into `dst` (null: read, not written), without its validator.
  bool plain_value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field);

  // After objects(): the reference table and what follows are read on from here.
  PayloadReader& reader() { return in_; }

 private:
  template <typename>
  friend class Traversal;

  bool value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field);
  // A value checked by its type's symcr_validate. A plan for a build known only by its schema
  // file (the CLI's) marks validated types whose code it does not have: restored unchecked.
  bool runs_validator(const PlanNode* n) const {
    return n->validated && reader_.types[n->reader].validate != nullptr;
  }
  // A root's or heap object's value, and a container's element or unique_ptr's pointee: each
  // charged against the nesting limit (payload_grammar.hpp), as the save side charges it.
  bool object(const PlanNode* n, std::uint8_t* dst);
  bool nested(const PlanNode* n, std::uint8_t* dst);
  bool validated_value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field);
  // Pass 1's judgement of a validated value (its verdict, reserved at `verdict`).
  bool judge(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field, std::size_t verdict);
  // Fields [first, end) of struct `n` at `dst`, one by one (path frame `frame` names each).
  bool fields(const PlanNode* n, std::uint32_t first, std::uint32_t end, std::uint8_t* dst,
              std::size_t frame);
  // A copy-only value in one step: check it, copy it (writing passes). False, consuming
  // nothing, when the bytes are short or a bool or bit-field value is invalid: the general
  // path then finds and reports the same error at its place.
  __attribute__((noinline)) bool copy(const PlanNode* n, std::uint8_t* dst);
  __attribute__((noinline)) bool scalar(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst,
                                        const FieldPlan* field);
  bool array(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst);
  // The first `count` elements of an array whose element `e` is copy-only, `stride` bytes apart
  // in the reader: checked all, then copied, in two loops without a call per element. False,
  // consuming nothing, as copy() is: the general path then takes every element.
  bool copy_elements(const PlanNode* e, std::uint64_t count, std::uint8_t* dst,
                     std::uint32_t stride);
  __attribute__((noinline)) bool string(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst);
  bool container(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst);
  __attribute__((noinline)) bool pointer(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst);

  // ---- parts judged whole (docs/resolution.md, Validators) ---------------------------------
  // A container element, or the value an optional, unique_ptr or variant holds, in which a
  // validator refused a value or a rule rejected one is never inserted, emplaced or made with
  // a value-initialised stand-in: the element is left out of its container, the holder keeps
  // this build's value.
  // Pass 1 reserves one verdict per such part before decoding it (stream order, like the
  // validators' verdicts) and settles it after; the later passes read it before the part.
  struct PartMark {
    bool judged = false;
    std::size_t verdict = 0;       // index in the part verdicts
    std::size_t own_verdict = 0;   // index in the verdicts of the part's own validator, if any
    std::uint32_t refusals = 0;    // the pass's refusals before the part
    std::uint32_t rejections = 0;  // and its rejections
    std::size_t first_slot = 0;    // slots before the part
  };
  // Before a part: whether pass 1 refused it (false in pass 1 itself).
  bool begin_part(const PlanNode* part, PartMark& mark);
  // After a part, in pass 1: its verdict. A container element takes in its parts' refusals
  // (the container holds what passed); a holder passes them on to what holds it.
  void end_part(const PlanNode* part, const PartMark& mark, bool element);

  // A value-level rejection (pass 1 reports and counts it): the reader keeps its value, and a
  // part holding it is refused. Inside an object whose migration hook runs, the value is the
  // hook's to handle.
  __attribute__((format(printf, 3, 4), noinline)) void reject_value(std::uint32_t counter,
                                                                    const char* format, ...);
  // A value a validator refused: rejected even inside a migrated object (its hook ran).
  __attribute__((format(printf, 3, 4), noinline)) void refuse_value(std::uint32_t counter,
                                                                    const char* format, ...);

  Restorer& restorer_;
  Pass& pass_;
  const Plan& plan_;
  const Schema& writer_;
  const Schema& reader_;
  PayloadReader in_;
  Cursors cursors_;
  std::vector<PathFrame>& frames_;
  int depth_ = 0;
  std::uint32_t counter_ = 0;
  std::uint32_t object_ = 0;  // the object (root or heap) being decoded
  // The innermost object being decoded whose migration hook runs (not across pointers: a
  // pointee is an object of its own), or null.
  const PlanNode* migrating_ = nullptr;
  const FieldTime* time_ = nullptr;  // the reader field being decoded is a time of this clock
};

// Each pass: kJudges (pass 1: verdicts are decided and recorded, not read), kWrites (values go
// into their destinations), and what it does at the traversal's points.

class CheckPass {
 public:
  static constexpr bool kJudges = true;
  static constexpr bool kWrites = false;
  explicit CheckPass(Restorer& restorer) : r_(restorer) {}

  bool heap_object(std::uint32_t h, std::uint32_t type, std::uint8_t owner, std::uint8_t*& dst);
  void heap_object_decoded(std::uint32_t h) {
    // Created, it would hold value-initialised stand-ins where its refused values were.
    r_.heap_[h].validator = refusals != heap_refusals_;
    r_.heap_[h].refused = r_.heap_[h].validator || rejections != heap_rejections_;
  }
  bool container(const PlanNode* n, std::uint32_t count, std::uint32_t ordinal,
                 std::uint32_t object, std::vector<void*>*& addresses);
  void pointer(const PlanNode* n, bool shared, std::uint32_t code, std::uint8_t* dst,
               std::uint32_t ordinal, std::uint32_t counter, std::uint32_t object,
               const std::vector<PathFrame>& frames);
  // Every copy is checked (and a refused one marks the restore: copy_refused_).
  bool checks_copies() const { return true; }
  void rebase(std::uint8_t*, const TypeInfo&, const FieldTime&) const {}
  void duplicate_key(const std::vector<PathFrame>&) {}
  // `hook`: the migrated object the value is handed to, or null for a rejection.
  __attribute__((format(printf, 5, 0))) void report_value(const PlanNode* hook,
                                                          std::uint32_t counter,
                                                          const std::vector<PathFrame>& frames,
                                                          const char* format, va_list args);

  std::uint32_t refusals = 0;       // values refused by validators, not yet taken in by a part
  std::uint32_t rejections = 0;     // values rejected by the rules, likewise
  std::size_t rejection_depth = 0;  // the path depth of the last of them

 private:
  Restorer& r_;
  std::uint32_t heap_refusals_ = 0;  // refusals before the heap object being decoded
  std::uint32_t heap_rejections_ = 0;
};

// What a pass that keeps no records does at each of the traversal's points: nothing. A pass
// derives from it and hides the points it acts at (the traversal calls them on the pass's own
// type, so no call is virtual).
class PassDefaults {
 public:
  bool heap_object(std::uint32_t, std::uint32_t, std::uint8_t, std::uint8_t*& dst) {
    dst = nullptr;
    return true;
  }
  void heap_object_decoded(std::uint32_t) {}
  bool container(const PlanNode*, std::uint32_t, std::uint32_t, std::uint32_t,
                 std::vector<void*>*&) {
    return true;
  }
  void pointer(const PlanNode*, bool, std::uint32_t, std::uint8_t*, std::uint32_t, std::uint32_t,
               std::uint32_t, const std::vector<PathFrame>&) {}
  bool checks_copies() const { return true; }
  void rebase(std::uint8_t*, const TypeInfo&, const FieldTime&) const {}
  void duplicate_key(const std::vector<PathFrame>&) {}
  void report_value(const PlanNode*, std::uint32_t, const std::vector<PathFrame>&, const char*,
                    va_list) {}
};

class StagePass : public PassDefaults {
 public:
  static constexpr bool kJudges = false;
  static constexpr bool kWrites = true;
};

class ApplyPass : public PassDefaults {
 public:
  static constexpr bool kJudges = false;
  static constexpr bool kWrites = true;
  ApplyPass(Restorer& restorer, Report& report) : r_(restorer), report_(report) {}

  bool heap_object(std::uint32_t h, std::uint32_t, std::uint8_t, std::uint8_t*& dst) {
    dst = static_cast<std::uint8_t*>(r_.heap_live_[h]);
    return true;
  }
  bool container(const PlanNode*, std::uint32_t, std::uint32_t ordinal, std::uint32_t,
                 std::vector<void*>*& addresses) {
    if (ordinal < r_.element_slots_.size() && r_.element_slots_[ordinal] != kNoType) {
      addresses = &r_.element_addresses_[r_.element_slots_[ordinal]];
    }
    return true;
  }
  void pointer(const PlanNode* n, bool, std::uint32_t, std::uint8_t* dst, std::uint32_t ordinal,
               std::uint32_t, std::uint32_t, const std::vector<PathFrame>&) {
    const bool to_reader = n->action == Action::Pointer || n->action == Action::SharedPtr;
    if (to_reader && dst) r_.applied_slots_.push_back(AppliedSlot{ordinal, dst});
  }
  // A value pass 1 sent to the general path (a rejected bit-field value) must take it here
  // too: checked again unless every copy of pass 1 was valid.
  bool checks_copies() const { return r_.copy_refused_; }
  void rebase(std::uint8_t* dst, const TypeInfo& type, const FieldTime& time) const {
    r_.rebase(dst, type, time);
  }
  void duplicate_key(const std::vector<PathFrame>& frames);

 private:
  Restorer& r_;
  Report& report_;
};

class ExplainPass : public PassDefaults {
 public:
  static constexpr bool kJudges = false;
  static constexpr bool kWrites = false;
  // `wanted`: slot ordinal -> its path, filled in for the ordinals it holds.
  explicit ExplainPass(std::unordered_map<std::uint32_t, std::string>& wanted) : wanted_(wanted) {}

  void pointer(const PlanNode*, bool, std::uint32_t, std::uint8_t*, std::uint32_t ordinal,
               std::uint32_t, std::uint32_t, const std::vector<PathFrame>& frames) {
    auto found = wanted_.find(ordinal);
    if (found != wanted_.end()) found->second = render_path(frames.data(), frames.size());
  }

 private:
  std::unordered_map<std::uint32_t, std::string>& wanted_;
};

}  // namespace symcr::detail::restoring

#endif  // SYMCR_SRC_RESTORE_TRAVERSAL_HPP
