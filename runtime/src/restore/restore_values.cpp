// Restore: values, decoded along the plan: the one traversal every pass runs
// (restore_traversal.hpp). Pass 1 records what the later passes look up by ordinal.
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

#include "old_values_view.hpp"
#include "payload_error.hpp"
#include "report_access.hpp"
#include "restore_traversal.hpp"
#include "symcr/format/payload.hpp"
#include "unicode.hpp"

namespace symcr::detail::restoring {

// ---- errors and report ---------------------------------------------------------------
const Status& Restorer::corrupt(const char* format, ...) {
  va_list args;
  va_start(args, format);
  set_corrupt_payload(error_, format, args);
  va_end(args);
  return error_;
}

void Restorer::summarise_rejections() {
  // No counter can exceed the cap otherwise.
  if (value_rejections_ + values_handed_ <= kMaxConcretePerField) return;
  for (std::size_t c = 0; c < rejection_counts_.size(); ++c) {
    if (rejection_counts_[c] > kMaxConcretePerField) {
      ReportAccess::add(report_, counter_path(static_cast<std::uint32_t>(c)), Decision::Rejected,
                        "and " + std::to_string(rejection_counts_[c] - kMaxConcretePerField) +
                            " more values rejected",
                        true);
    }
    if (handed_counts_[c] > kMaxConcretePerField) {
      ReportAccess::add(report_, counter_path(static_cast<std::uint32_t>(c)), Decision::Converted,
                        "and " + std::to_string(handed_counts_[c] - kMaxConcretePerField) +
                            " more values for a migration hook",
                        false);
    }
  }
}

std::string Restorer::counter_path(std::uint32_t counter) const {
  if (counter >= plan_.counter_paths.size()) return "heap objects";
  const Plan::CounterPath& path = plan_.counter_paths[counter];
  return path.scope ? std::string(path.scope) + "::" + path.name : std::string(path.name);
}

// ---- the passes' points -------------------------------------------------------------------
bool CheckPass::heap_object(std::uint32_t h, std::uint32_t type, std::uint8_t owner,
                            std::uint8_t*& dst) {
  if (!r_.plan_.heap_nodes[type]) {
    return r_
        .corrupt("heap object %u of type %s, which no pointer points to", h,
                 r_.writer_.types[type].name)
        .ok();
  }
  r_.heap_.push_back(HeapRecord{type, owner, r_.plan_.heap_nodes[type], false, false});
  heap_refusals_ = refusals;
  heap_rejections_ = rejections;
  dst = nullptr;
  return true;
}

bool CheckPass::container(const PlanNode* n, std::uint32_t count, std::uint32_t,
                          std::uint32_t object, std::vector<void*>*&) {
  if (n->action == Action::Container && !r_.allocation_justified(count, n->reader)) {
    return r_
        .corrupt("container of %u elements would need %" PRIu64
                 " bytes in this build, more than the checkpoint can justify",
                 count,
                 std::uint64_t{count} * r_.reader_.types[r_.reader_.types[n->reader].element].size)
        .ok();
  }
  r_.containers_.push_back(ContainerRecord{count, n->element, object});
  return true;
}

void CheckPass::pointer(const PlanNode* n, bool shared, std::uint32_t code, std::uint8_t* dst,
                        std::uint32_t, std::uint32_t counter, std::uint32_t object,
                        const std::vector<PathFrame>&) {
  const bool to_reader = n->action == Action::Pointer || n->action == Action::SharedPtr;
  SlotRecord record{};
  record.code = code;
  record.pointer_type = n->writer;
  record.node = to_reader ? n : nullptr;
  record.shared = shared;
  if (to_reader && dst && !shared) std::memcpy(&record.live, dst, sizeof(void*));
  record.counter = counter;
  record.object = object;
  record.outcome = SlotOutcome::Skip;
  r_.slots_.push_back(record);
}

// Concrete paths are capped per field.
void CheckPass::report_value(const PlanNode* hook, std::uint32_t counter,
                             const std::vector<PathFrame>& frames, const char* format,
                             va_list args) {
  ++(hook ? r_.values_handed_ : r_.value_rejections_);
  if (++r_.entry_count(hook ? r_.handed_counts_ : r_.rejection_counts_, counter) >
      kMaxConcretePerField) {
    return;
  }
  char buffer[240];
  std::vsnprintf(buffer, sizeof buffer, format, args);
  if (hook) {
    ReportAccess::add(r_.report_, render_path(frames.data(), frames.size()), Decision::Converted,
                      std::string(buffer) + "; the old value goes to symcr_migrate(" +
                          r_.reader_.types[hook->reader].name + ")",
                      false);
    return;
  }
  ReportAccess::add(r_.report_, render_path(frames.data(), frames.size()), Decision::Rejected,
                    buffer, true);
}

void ApplyPass::duplicate_key(const std::vector<PathFrame>& frames) {
  ReportAccess::add(report_, render_path(frames.data(), frames.size()), Decision::Rejected,
                    "duplicate key: element not inserted", true);
}

// ---- the traversal ----------------------------------------------------------------------
template <typename Pass>
Traversal<Pass>::Traversal(Restorer& restorer, Pass& pass)
    : restorer_(restorer),
      pass_(pass),
      plan_(restorer.plan_),
      writer_(restorer.writer_),
      reader_(restorer.reader_),
      in_(restorer.writer_, restorer.plan_.wire_sizes, restorer.error_),
      frames_(restorer.frames_) {
  in_.start(restorer.payload_, restorer.size_);
  frames_.clear();
}

template <typename Pass>
template <typename Outer>
Traversal<Pass>::Traversal(const Traversal<Outer>& outer, Pass& pass, const std::uint8_t* start,
                           const Cursors& at)
    : restorer_(outer.restorer_),
      pass_(pass),
      plan_(outer.plan_),
      writer_(outer.writer_),
      reader_(outer.reader_),
      in_(outer.in_),
      cursors_(at),
      frames_(outer.frames_),
      depth_(outer.depth_),
      counter_(outer.counter_),
      object_(outer.object_),
      migrating_(outer.migrating_),
      time_(outer.time_) {
  in_.seek(start);
}

template <typename Pass>
void Traversal<Pass>::reject_value(std::uint32_t counter, const char* format, ...) {
  if constexpr (Pass::kJudges) {
    if (!migrating_) {
      ++pass_.rejections;
      pass_.rejection_depth = frames_.size();
    }
  }
  va_list args;
  va_start(args, format);
  pass_.report_value(migrating_, counter, frames_, format, args);
  va_end(args);
}

template <typename Pass>
void Traversal<Pass>::refuse_value(std::uint32_t counter, const char* format, ...) {
  va_list args;
  va_start(args, format);
  pass_.report_value(nullptr, counter, frames_, format, args);
  va_end(args);
}

// ---- objects: roots then heap objects ------------------------------------------------
template <typename Pass>
bool Traversal<Pass>::objects() {
  for (std::uint32_t wr = 0; wr < writer_.root_count; ++wr) {
    const RootPlan& root = plan_.roots[wr];
    std::uint8_t* dst = root.reader_root == kNoType
                            ? nullptr
                            : static_cast<std::uint8_t*>(reader_.roots[root.reader_root].address);
    frames_.push_back({PathFrame::Kind::Name, writer_.roots[wr].name, 0});
    counter_ = root.counter;
    object_ = wr;
    if (!object(root.node, dst)) return false;
    frames_.pop_back();
  }
  std::uint32_t heap_count = 0;
  if (!in_.heap_count(heap_count)) return false;
  if (Pass::kJudges) restorer_.heap_.reserve(heap_count);
  for (std::uint32_t h = 0; h < heap_count; ++h) {
    std::uint32_t type = 0;
    std::uint8_t owner = 0;
    std::uint8_t* dst = nullptr;
    if (!in_.heap_object(h, type, owner) || !pass_.heap_object(h, type, owner, dst)) return false;
    frames_.push_back({PathFrame::Kind::Heap, writer_.types[type].name, h});
    counter_ = restorer_.heap_counter();
    object_ = writer_.root_count + h;
    if (!object(restorer_.heap_[h].node, dst)) return false;
    pass_.heap_object_decoded(h);
    frames_.pop_back();
  }
  return true;
}

// ---- values --------------------------------------------------------------------------
template <typename Pass>
bool Traversal<Pass>::value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field) {
  return runs_validator(n) ? validated_value(n, dst, field) : plain_value(n, dst, field);
}

// Containers and unique_ptrs nest without a bound in the schema: each element or pointee is
// charged against the nesting limit, as the save side charges it.
template <typename Pass>
bool Traversal<Pass>::nested(const PlanNode* n, std::uint8_t* dst) {
  const int outer = depth_;
  depth_ = in_.element_depth(outer, n->writer);
  const bool ok = in_.nest(depth_) && value(n, dst, nullptr);
  depth_ = outer;
  return ok;
}

template <typename Pass>
bool Traversal<Pass>::object(const PlanNode* n, std::uint8_t* dst) {
  depth_ = in_.object_depth(n->writer);
  const bool ok = in_.nest(depth_) && value(n, dst, nullptr);
  depth_ = 0;
  return ok;
}

template <typename Pass>
bool Traversal<Pass>::validated_value(const PlanNode* n, std::uint8_t* dst,
                                      const FieldPlan* field) {
  if constexpr (Pass::kJudges) {
    const std::size_t verdict = restorer_.verdicts_.size();
    restorer_.verdicts_.push_back(1);
    ++cursors_.verdict;
    return judge(n, dst, field, verdict);
  } else {
    const bool passed = restorer_.verdicts_[cursors_.verdict++] != 0;
    return plain_value(n, passed ? dst : nullptr, field);
  }
}

// Decodes the value (recording what is in it), then decodes the same bytes again into a
// staged copy for symcr_validate to judge.
template <typename Pass>
bool Traversal<Pass>::judge(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field,
                            std::size_t verdict) {
  const std::uint8_t* start = in_.position();
  const Cursors at = cursors_;
  const std::size_t first_slot = restorer_.slots_.size();
  if (!plain_value(n, dst, field)) return false;

  const TypeInfo& type = reader_.types[n->reader];
  bool passed = false;
  const char* why = "failed its symcr_validate";
  std::vector<std::max_align_t> flat;
  void* staged = nullptr;
  if (type.lifecycle) {
    staged = type.lifecycle->create();
  } else if (n->flat_reader) {
    flat.resize((type.size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t) + 1);
    staged = flat.data();
    if (dst)
      std::memcpy(staged, dst, type.size);
    else
      std::memset(staged, 0, type.size);
  } else {
    why = "has a symcr_validate but no lifecycle to check a staged copy";
  }
  if (staged) {
    StagePass stage;
    const bool decoded = Traversal<StagePass>(*this, stage, start, at)
                             .plain_value(n, static_cast<std::uint8_t*>(staged), field);
    passed = decoded && type.validate(staged);
    if (type.lifecycle) type.lifecycle->destroy(staged);
  }
  restorer_.verdicts_[verdict] = passed ? 1 : 0;
  if (!passed) {
    ++pass_.refusals;
    for (std::size_t s = first_slot; s < restorer_.slots_.size(); ++s) {
      restorer_.slots_[s].node = nullptr;
    }
    refuse_value(field ? field->counter : counter_, "%s %s", type.name, why);
  }
  return true;
}

template <typename Pass>
bool Traversal<Pass>::begin_part(const PlanNode* part, PartMark& mark) {
  if (!part->holds_judged) return false;
  if constexpr (Pass::kJudges) {
    mark.judged = true;
    mark.verdict = restorer_.part_verdicts_.size();
    restorer_.part_verdicts_.push_back(1);
    ++cursors_.part;
    mark.own_verdict = restorer_.verdicts_.size();
    mark.refusals = pass_.refusals;
    mark.rejections = pass_.rejections;
    mark.first_slot = restorer_.slots_.size();
    return false;
  } else {
    return restorer_.part_verdicts_[cursors_.part++] == 0;
  }
}

template <typename Pass>
void Traversal<Pass>::end_part(const PlanNode* part, const PartMark& mark, bool element) {
  if constexpr (Pass::kJudges) {
    const bool validator = pass_.refusals != mark.refusals;
    if (!mark.judged || (!validator && pass_.rejections == mark.rejections)) return;
    restorer_.part_verdicts_[mark.verdict] = 0;
    // Its pointers are not restored: the part is not written.
    for (std::size_t s = mark.first_slot; s < restorer_.slots_.size(); ++s) {
      restorer_.slots_[s].node = nullptr;
    }
    if (!element) return;
    // An element refused or rejected as a whole already has its entry at this path.
    const bool own = validator ? runs_validator(part) && restorer_.verdicts_[mark.own_verdict] == 0
                               : pass_.rejections == mark.rejections + 1 &&
                                     pass_.rejection_depth == frames_.size();
    pass_.refusals = mark.refusals;
    pass_.rejections = mark.rejections;
    if (!own) {
      refuse_value(
          counter_, "left out of its container: %s",
          validator ? "a value in it failed its symcr_validate" : "a value in it was rejected");
    }
  } else {
    (void)part;
    (void)mark;
    (void)element;
  }
}

template <typename Pass>
bool Traversal<Pass>::plain_value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field) {
  if (n->action == Action::Reject) return value(n->skip, nullptr, nullptr);
  if (n->copy_only && !time_ && !(field && (field->bit_width || field->has_range)) &&
      copy(n, dst)) {
    return true;
  }
  const TypeInfo& wt = writer_.types[n->writer];
  switch (wt.kind) {
    case Kind::Bool:
    case Kind::Int:
    case Kind::UInt:
    case Kind::Float:
    case Kind::Enum:
      return scalar(n, wt, dst, field);
    case Kind::Struct: {
      const std::uint32_t saved = counter_;
      const std::uint8_t* start = in_.position();
      const PlanNode* outer_migration = migrating_;
      if (n->migrates) migrating_ = n;
      // One path frame for all the fields, renamed per field.
      const std::size_t frame = frames_.size();
      frames_.push_back({PathFrame::Kind::Name, "", 0});
      const FieldTime* outer_time = time_;
      if (n->copy_segments.empty()) {
        if (!fields(n, 0, static_cast<std::uint32_t>(n->fields.size()), dst, frame)) return false;
      }
      for (const CopySegment& segment : n->copy_segments) {
        // A segment whose bytes fail the copy checks goes field by field, which names the fault.
        if (segment.copy && copy(segment.copy, dst)) continue;
        if (!fields(n, segment.first_field, segment.end_field, dst, frame)) return false;
      }
      time_ = outer_time;
      frames_.pop_back();
      counter_ = saved;
      migrating_ = outer_migration;
      // The migration hook, once the mechanical rules wrote the object and everything in it
      // (so nested objects' hooks ran first). Also on a validator's staged copy, so that
      // symcr_validate judges the migrated value. Pointers are fixed up after all objects.
      if (n->migrate && dst && Pass::kWrites) {
        n->migrate(dst, old_values_view(writer_, plan_.wire_sizes, n->writer, start,
                                        static_cast<std::size_t>(in_.position() - start)));
      }
      return true;
    }
    case Kind::Union: {
      const std::uint8_t* bytes = nullptr;
      if (!in_.scalar(wt, bytes)) return false;
      if (n->action == Action::Union && dst && Pass::kWrites) std::memcpy(dst, bytes, wt.size);
      return true;
    }
    case Kind::Array:
      return array(n, wt, dst);
    case Kind::String:
      return string(n, wt, dst);
    case Kind::Container:
      return container(n, wt, dst);
    case Kind::Optional: {
      bool engaged = false;
      if (!in_.presence(wt, engaged)) return false;
      const bool to_reader = n->action == Action::Optional && dst;
      const auto* ops =
          to_reader ? static_cast<const OptionalOps*>(reader_.types[n->reader].ops) : nullptr;
      if (!engaged) {
        if (to_reader && Pass::kWrites) ops->reset(dst);
        return true;
      }
      PartMark mark;
      const bool refused = begin_part(n->element, mark);
      std::uint8_t* inner = nullptr;
      if (to_reader && !refused) {
        inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
        if (!inner && Pass::kWrites) inner = static_cast<std::uint8_t*>(ops->emplace(dst));
      }
      if (!value(n->element, inner, nullptr)) return false;
      end_part(n->element, mark, false);
      return true;
    }
    case Kind::UniquePtr: {
      bool present = false;
      if (!in_.presence(wt, present)) return false;
      const bool to_reader = n->action == Action::UniquePtr && dst;
      const auto* ops =
          to_reader ? static_cast<const UniquePtrOps*>(reader_.types[n->reader].ops) : nullptr;
      if (!present) {
        if (to_reader && Pass::kWrites) ops->reset(dst);
        return true;
      }
      PartMark mark;
      const bool refused = begin_part(n->element, mark);
      std::uint8_t* inner = nullptr;
      if (to_reader && !refused) {
        // An object the new build already owns is filled in place (its address may be known).
        inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
        if (!inner && Pass::kWrites) inner = static_cast<std::uint8_t*>(ops->make(dst));
      }
      if (!nested(n->element, inner)) return false;
      end_part(n->element, mark, false);
      return true;
    }
    case Kind::Variant: {
      std::uint32_t index = 0;
      if (!in_.variant(wt, index)) return false;
      if (index == kNoType) return true;  // valueless when saved: keep the reader's value
      const PlanNode* alternative = n->alternatives[index];
      if (n->action != Action::Variant) return value(alternative, nullptr, nullptr);
      const std::uint32_t reader_index = n->alternative_map[index];
      if (reader_index == kNoType) {
        reject_value(field ? field->counter : counter_, "alternative %s not in this build",
                     writer_.types[wt.alternatives[index]].name);
        return value(alternative, nullptr, nullptr);
      }
      PartMark mark;
      const bool refused = begin_part(alternative, mark);
      std::uint8_t* inner = nullptr;
      if (dst && !refused) {
        const auto* ops = static_cast<const VariantOps*>(reader_.types[n->reader].ops);
        if (ops->index(dst) == reader_index) {
          inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
        } else if (Pass::kWrites) {
          inner = static_cast<std::uint8_t*>(ops->emplace(dst, reader_index));
        }
      }
      if (!value(alternative, inner, nullptr)) return false;
      end_part(alternative, mark, false);
      return true;
    }
    case Kind::Pointer:
    case Kind::SharedPtr:
      return pointer(n, wt, dst);
  }
  return restorer_.corrupt("unknown kind").ok();
}

// Fields [first, end) of struct `n` one by one, each under its name in path frame `frame`.
template <typename Pass>
bool Traversal<Pass>::fields(const PlanNode* n, std::uint32_t first, std::uint32_t end,
                             std::uint8_t* dst, std::size_t frame) {
  for (std::uint32_t f = first; f < end; ++f) {
    const FieldPlan& child = n->fields[f];
    frames_[frame].name = child.name;
    counter_ = child.counter;
    std::uint8_t* at = dst && child.reader_field != kNoType ? dst + child.reader_offset : nullptr;
    time_ = child.time;
    // A time of a clock the checkpoint has no reading of keeps this build's value (the plan's
    // report rejects the field).
    if (time_ && plan_.writer_clock_of[time_->clock->index] == kNoType) at = nullptr;
    if (!value(child.node, at, &child)) return false;
  }
  return true;
}

// A copy-only value in one step: check it (pass 1), copy it (writing passes). False,
// consuming nothing, when the bytes are short or a bool or bit-field value is invalid: the
// general path then finds and reports the same error at its place.
template <typename Pass>
bool Traversal<Pass>::copy(const PlanNode* n, std::uint8_t* dst) {
  if (in_.remaining() < n->copy_wire) return false;
  const std::uint8_t* base = in_.position();
  // A value the first pass sent to the general path (a rejected bit-field value) must take it
  // in the second too: checked again unless every copy of the first pass was valid.
  if (pass_.checks_copies() && !copy_only_valid(*n, base)) {
    restorer_.copy_refused_ = true;
    return false;
  }
  if (dst && Pass::kWrites) copy_only_write(*n, base, dst);
  in_.seek(base + n->copy_wire);
  return true;
}

template <typename Pass>
bool Traversal<Pass>::copy_elements(const PlanNode* e, std::uint64_t count, std::uint8_t* dst,
                                    std::uint32_t stride) {
  const std::size_t wire = e->copy_wire;
  if (count > in_.remaining() / wire) return false;
  const std::uint8_t* base = in_.position();
  if (pass_.checks_copies() && (!e->copy_bools.empty() || !e->copy_bits.empty())) {
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!copy_only_valid(*e, base + i * wire)) {
        restorer_.copy_refused_ = true;
        return false;
      }
    }
  }
  if (dst && Pass::kWrites) {
    for (std::uint64_t i = 0; i < count; ++i)
      copy_only_write(*e, base + i * wire, dst + i * stride);
  }
  in_.seek(base + count * wire);
  return true;
}

template <typename Pass>
bool Traversal<Pass>::scalar(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst,
                             const FieldPlan* field) {
  const std::uint8_t* bytes = nullptr;
  if (!in_.scalar(wt, bytes)) return false;
  if (n->action != Action::Scalar) return true;
  const bool bit_field = field && field->bit_width;
  const bool ranged = field && field->has_range;
  const TypeInfo& rt = reader_.types[n->reader];
  if (n->identical && !bit_field && !ranged) {
    if (dst && Pass::kWrites) {
      std::memcpy(dst, bytes, wt.kind == Kind::Float && wt.size == 16 ? 10 : wt.size);
      if (time_) pass_.rebase(dst, rt, *time_);
    }
    return true;
  }
  const std::uint32_t counter = field ? field->counter : counter_;
  Number in;
  read_number(writer_, wt, bytes, in);
  if (wt.kind == Kind::Enum && rt.kind == Kind::Enum && !n->identical) {
    const std::int64_t value =
        in.tag == Number::Tag::Signed ? in.s : static_cast<std::int64_t>(in.u);
    const EnumMapping* mapping = nullptr;
    const auto found = std::lower_bound(
        n->enum_map.begin(), n->enum_map.end(), value,
        [](const EnumMapping& candidate, std::int64_t v) { return candidate.writer_value < v; });
    if (found != n->enum_map.end() && found->writer_value == value) mapping = &*found;
    if (!mapping) {
      reject_value(counter, "value %" PRId64 " is not an enumerator of %s", value, wt.name);
      return true;
    }
    if (!mapping->mapped) {
      reject_value(counter, "enum %s", unmapped_enumerator(rt, *mapping).c_str());
      return true;
    }
    in.tag = Number::Tag::Signed;
    in.s = mapping->reader_value;
    if (reader_.types[rt.element].kind == Kind::UInt) {
      in.tag = Number::Tag::Unsigned;
      in.u = static_cast<std::uint64_t>(mapping->reader_value);
    }
  }
  Number out;
  char why[160];
  if (!convert_number(reader_, rt, in, out, why, sizeof why)) {
    reject_value(counter, "%s", why);
    return true;
  }
  if (bit_field) {
    const TypeInfo& integer = rt.kind == Kind::Enum ? reader_.types[rt.element] : rt;
    if (!fits_bits(out, field->bit_width, integer.kind == Kind::Int)) {
      char text[64];
      format_number(out, text, sizeof text);
      reject_value(counter, "%s does not fit in %u bits", text, field->bit_width);
      return true;
    }
  }
  if (ranged) {
    const long double v = out.as_long_double();
    const bool inside =
        out.tag == Number::Tag::Floating
            ? !std::isnan(v) && v >= field->range_min && v <= field->range_max
            : format::integer_in_range(
                  out.tag == Number::Tag::Signed ? static_cast<std::uint64_t>(out.s) : out.u,
                  out.tag == Number::Tag::Signed, field->range_min, field->range_max);
    if (!inside) {
      char text[64];
      format_number(out, text, sizeof text);
      reject_value(counter, "%s outside [%g, %g]", text, field->range_min, field->range_max);
      return true;
    }
  }
  if (dst && Pass::kWrites) {
    if (bit_field) {
      store_bits(dst, field->bit_offset, field->bit_width, out);
    } else {
      store_number(reader_, rt, out, dst);
      if (time_) pass_.rebase(dst, rt, *time_);
    }
  }
  return true;
}

template <typename Pass>
bool Traversal<Pass>::array(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
  const bool to_reader = n->action == Action::Array;
  const TypeInfo& we = writer_.types[wt.element];
  const PlanNode* e = n->element;
  // Identical packed scalars: one bounds check and one copy.
  if (to_reader && !time_ && e->identical && we.kind != Kind::Bool &&
      !(we.kind == Kind::Float && we.size == 16)) {
    const std::uint8_t* bytes = nullptr;
    if (!in_.scalar_run(we, wt.count, bytes)) return false;
    const std::uint64_t common = wt.count < n->reader_count ? wt.count : n->reader_count;
    if (dst && Pass::kWrites) std::memcpy(dst, bytes, common * we.size);
    return true;
  }
  // Elements that encode to nothing would let a few bytes of schema drive billions of
  // iterations: such arrays are bounded like containers.
  if (!in_.array(wt)) return false;
  std::uint64_t i = 0;
  if (to_reader && !time_ && e->copy_only && e->copy_wire != 0 && !runs_validator(e)) {
    const std::uint64_t kept = wt.count < n->reader_count ? wt.count : n->reader_count;
    if (copy_elements(e, kept, dst, n->reader_stride)) i = kept;
    if (i == wt.count) return true;
  }
  const std::size_t frame = frames_.size();
  frames_.push_back({PathFrame::Kind::Index, nullptr, 0});
  for (; i < wt.count; ++i) {
    const bool kept = to_reader && i < n->reader_count;
    frames_[frame].index = i;
    std::uint8_t* at = kept && dst ? dst + i * n->reader_stride : nullptr;
    if (!value(kept ? e : n->element_skip, at, nullptr)) return false;
  }
  frames_.pop_back();
  return true;
}

template <typename Pass>
bool Traversal<Pass>::string(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
  std::uint32_t length = 0;
  const std::uint8_t* bytes = nullptr;
  if (!in_.string(wt, bytes, length)) return false;
  const std::uint32_t width = writer_.types[wt.element].size;
  if (n->action != Action::String) return true;
  const TypeInfo& rt = reader_.types[n->reader];
  const std::uint32_t reader_width = reader_.types[rt.element].size;
  const void* chars = bytes;
  std::uint32_t reader_length = length;
  if (reader_width != width) {
    // Another character width: re-encoded (UTF-8/16/32), both passes alike; a string not
    // valid in its encoding is rejected and keeps this build's value.
    char why[160];
    if (!transcode_string(bytes, length, width, reader_width, restorer_.string_scratch_,
                          reader_length, why, sizeof why)) {
      reject_value(counter_, "%s", why);
      return true;
    }
    chars = restorer_.string_scratch_.data();
  } else if (reinterpret_cast<std::uintptr_t>(bytes) % width != 0) {
    restorer_.string_scratch_.assign(bytes, bytes + std::size_t{length} * width);
    chars = restorer_.string_scratch_.data();
  }
  if (!dst || !Pass::kWrites) return true;
  static_cast<const StringOps*>(rt.ops)->assign(dst, chars, reader_length);
  return true;
}

template <typename Pass>
bool Traversal<Pass>::container(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
  std::uint32_t count = 0;
  if (!in_.container(wt, count)) return false;
  const std::uint32_t ordinal = cursors_.container++;
  const bool to_reader = n->action == Action::Container;
  const PlanNode* e = n->element;
  std::vector<void*>* addresses = nullptr;  // where pass 2 lists the elements' addresses
  if (!pass_.container(n, count, ordinal, object_, addresses)) return false;
  // Identical fixed-width scalars (not bool: its bytes need checking) need no per-element
  // decoding: one bounds check, and into a contiguous reader container one copy.
  const TypeInfo& we = writer_.types[wt.element];
  const bool packed = e->action == Action::Scalar && e->identical && !e->validated &&
                      we.kind != Kind::Bool && !(we.kind == Kind::Float && we.size == 16) &&
                      count > 0 && in_.element_depth(depth_, wt.element) <= kMaxValueNesting;
  if (packed && (!to_reader || !dst || !Pass::kWrites)) {
    const std::uint8_t* bytes = nullptr;
    return in_.scalar_run(we, count, bytes);
  }
  if (!to_reader || !dst || !Pass::kWrites) {
    for (std::uint32_t i = 0; i < count; ++i) {
      frames_.push_back({PathFrame::Kind::Index, nullptr, i});
      PartMark mark;
      begin_part(e, mark);
      if (!nested(e, nullptr)) return false;
      end_part(e, mark, true);
      frames_.pop_back();
    }
    return true;
  }
  const TypeInfo& rt = reader_.types[n->reader];
  const auto* ops = static_cast<const ContainerOps*>(rt.ops);
  if (packed && ops->resize_default && reader_.types[rt.element].size == we.size) {
    // Resized, not cleared first: the elements it keeps are overwritten below, so only
    // the new ones are value-initialised.
    const std::uint8_t* bytes = nullptr;
    if (!in_.scalar_run(we, count, bytes)) return false;
    auto* elements = static_cast<std::uint8_t*>(ops->resize_default(dst, count));
    std::memcpy(elements, bytes, std::size_t{count} * we.size);
    if (addresses) {
      for (std::uint32_t i = 0; i < count; ++i)
        addresses->push_back(elements + std::size_t{i} * we.size);
    }
    return true;
  }
  ops->clear(dst);
  if (ops->append) {
    ops->reserve(dst, count);  // vectors: element addresses stay valid while we append
    for (std::uint32_t i = 0; i < count; ++i) {
      frames_.push_back({PathFrame::Kind::Index, nullptr, i});
      PartMark mark;
      if (begin_part(e, mark)) {  // not appended: the container holds what passed
        if (addresses) addresses->push_back(nullptr);
        if (!nested(e, nullptr)) return false;
        frames_.pop_back();
        continue;
      }
      auto* element = static_cast<std::uint8_t*>(ops->append(dst));
      if (addresses) addresses->push_back(element);
      if (!nested(e, element)) return false;
      frames_.pop_back();
    }
    return true;
  }
  // Associative: stage each element, then insert (moving from it).
  const Lifecycle* lifecycle = reader_.types[rt.element].lifecycle;
  for (std::uint32_t i = 0; i < count; ++i) {
    frames_.push_back({PathFrame::Kind::Index, nullptr, i});
    alignas(16) std::uint64_t scalar_buffer[2] = {0, 0};  // a scalar element without a lifecycle
    auto* staged = lifecycle ? static_cast<std::uint8_t*>(lifecycle->create())
                             : reinterpret_cast<std::uint8_t*>(scalar_buffer);
    const std::size_t first_slot = restorer_.applied_slots_.size();
    PartMark mark;
    const bool refused = begin_part(e, mark);
    if (!nested(e, staged)) {
      if (lifecycle) lifecycle->destroy(staged);
      return false;
    }
    auto* inserted = refused ? nullptr : static_cast<std::uint8_t*>(ops->insert(dst, staged));
    if (inserted) {
      // Slots in the staged element's own bytes moved with it; slots in storage it owns
      // (a vector's buffer, a unique_ptr's pointee) were moved by pointer and stay put.
      const std::size_t element_size = reader_.types[rt.element].size;
      for (std::size_t s = first_slot; s < restorer_.applied_slots_.size(); ++s) {
        std::uint8_t* at = restorer_.applied_slots_[s].address;
        if (at >= staged && at < staged + element_size) {
          restorer_.applied_slots_[s].address = inserted + (at - staged);
        }
      }
    } else if (refused) {
      restorer_.applied_slots_.resize(first_slot);
    } else {
      restorer_.applied_slots_.resize(first_slot);
      pass_.duplicate_key(frames_);
    }
    if (addresses) addresses->push_back(inserted);
    if (lifecycle) lifecycle->destroy(staged);
    frames_.pop_back();
  }
  return true;
}

template <typename Pass>
bool Traversal<Pass>::pointer(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
  std::uint32_t code = 0;
  if (!in_.pointer(wt, code)) return false;
  pass_.pointer(n, wt.kind == Kind::SharedPtr, code, dst, cursors_.slot++, counter_, object_,
                frames_);
  return true;
}

// The passes' walks (restorer.hpp runs them), and pass 1's staged decoding.
template Traversal<CheckPass>::Traversal(Restorer&, CheckPass&);
template Traversal<ApplyPass>::Traversal(Restorer&, ApplyPass&);
template Traversal<ExplainPass>::Traversal(Restorer&, ExplainPass&);
template bool Traversal<CheckPass>::objects();
template bool Traversal<ApplyPass>::objects();
template bool Traversal<ExplainPass>::objects();

}  // namespace symcr::detail::restoring
