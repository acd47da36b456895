// The restore path (docs/resolution.md): a payload written with the writer schema is decoded
// twice along the same plan.
//   Pass 1 (Check) reads everything, checks every bound, conversion, enumerator, range,
//   validator and reference, and builds the report; nothing live is written.
//   Pass 2 (Apply) runs only when pass 1 succeeded (and, in strict mode, found nothing lossy):
//   it decodes again, writing into live objects, materialises heap objects, and fixes up
//   pointer slots last.
// Both passes walk the payload identically, so per-value facts that pass 1 decides
// (validator verdicts, pointer decisions, container counts) are looked up by their ordinal in
// stream order in pass 2.
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

#include "engine.hpp"
#include "payload_grammar.hpp"
#include "plan.hpp"
#include "scalar.hpp"
#include "schema_facts.hpp"
#include "unicode.hpp"

namespace symcr::detail {
namespace {

// ---- copy-only values (PlanNode::copy_only) ------------------------------------------------
std::uint64_t bit_field_raw(const CopyBits& bits, const std::uint8_t* wire) {
  std::uint64_t raw = 0;
  std::memcpy(&raw, wire + bits.wire, bits.size);  // little-endian, as the copy runs assume
  return raw;
}

Number bit_field_value(const CopyBits& bits, const std::uint8_t* wire) {
  Number value;
  const std::uint64_t raw = bit_field_raw(bits, wire);
  if (bits.is_signed) {
    const unsigned unused = 64 - 8 * bits.size;
    value.tag = Number::Tag::Signed;
    value.s = static_cast<std::int64_t>(raw << unused) >> unused;
  } else {
    value.tag = Number::Tag::Unsigned;
    value.u = raw;
  }
  return value;
}

// The first pass's checks of a copy-only value at `wire`: bools are 0 or 1, bit-field values
// fit their widths. False sends the value to the general path, which names the fault.
bool copy_only_valid(const PlanNode& n, const std::uint8_t* wire) {
  for (std::uint32_t offset : n.copy_bools) {
    if (wire[offset] > 1) return false;
  }
  for (const CopyBits& bits : n.copy_bits) {
    if (!fits_bits(bit_field_value(bits, wire), bits.width, bits.is_signed)) return false;
  }
  return true;
}

void copy_only_write(const PlanNode& n, const std::uint8_t* wire, std::uint8_t* dst) {
  for (const CopyRun& run : n.copy_runs) std::memcpy(dst + run.dst, wire + run.wire, run.length);
  for (const CopyBits& bits : n.copy_bits) {
    store_bits(dst + bits.dst, bits.bit_offset, bits.width, bit_field_value(bits, wire));
  }
}

template <typename T>
std::size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

// The last restore's scratch on this thread (thread_scratch_bytes).
thread_local std::size_t last_restore_scratch = 0;

enum class Mode : std::uint8_t {
  Check,  // pass 1: read and record, never write
  Stage,  // pass 1, inside a validated value: write into a staged copy, record nothing
  Apply,  // pass 2: write into live objects, record slot and element addresses
  Explain,  // between the passes, only if needed: render the paths of reported pointers
};

constexpr std::uint32_t kMaxConcretePerField = 100;

enum class SlotOutcome : std::uint8_t { Skip, Null, Outside, Target, Rejected };

struct SlotRecord {
  std::uint32_t code;              // wire value: 0 null, 1 outside, n >= 2 reference n - 2
  std::uint32_t pointer_type;      // writer pointer type
  const PlanNode* node;            // restorable pointer node, or nullptr
  bool shared;
  std::uintptr_t live;             // the reader's current pointer (raw slots with a place)
  std::uint32_t counter;
  std::uint32_t object;            // the object (root or heap) holding the slot
  SlotOutcome outcome;
};

struct ContainerRecord {
  std::uint32_t count;
  const PlanNode* element;  // restorable element node, or a skip node
  std::uint32_t object;     // the object (root or heap) holding the container
};

struct HeapRecord {
  std::uint32_t type;
  std::uint8_t owner;
  const PlanNode* node;
};

struct MappedStep {
  enum class Kind : std::uint8_t { Offset, Optional, Unique, Variant, Character } kind;
  std::uint32_t holder_type;  // reader type whose ops apply
  std::uint64_t value;
};

struct RefRecord : Reference {
  std::uint32_t steps_at = 0;
  bool resolved = false;
  std::uint32_t reader_type = kNoType;
  std::uint32_t mapped_at = 0, mapped_count = 0;
  std::string why;
};

struct AppliedSlot {
  std::uint32_t ordinal;
  std::uint8_t* address;
};

class Restorer {
 public:
  // `dry_run`: a plan of a build known only by its schema (no code): types it can create are
  // known by their kTypeCreatable flag instead of a Lifecycle; nothing is ever applied.
  Restorer(const Plan& plan, const std::uint8_t* payload, std::size_t size,
           Report& report, bool dry_run)
      : plan_(plan),
        w_(*plan.writer),
        r_(*plan.reader),
        in_(*plan.writer, plan.wire_sizes, error_),
        payload_(payload),
        size_(size),
        report_(report),
        dry_run_(dry_run) {}

  Status check() {
    mode_ = Mode::Check;
    in_.start(payload_, size_);
    rejection_counts_.assign(plan_.counter_paths.size() + 1, 0);
    heap_counter_ = static_cast<std::uint32_t>(plan_.counter_paths.size());
    if (!decode_objects() || !decode_references() || !in_.finish() || !check_slots()) {
      return error_;
    }
    claim_live_objects();
    decide_materialisation();
    for (RefRecord& ref : refs_) map_reference(ref);
    decide_slots();
    summarise_rejections();
    return Status();
  }

  std::size_t value_rejections() const { return value_rejections_; }

  // Capacity of the decoding tables (thread_scratch_bytes).
  std::size_t scratch_bytes() const {
    std::size_t bytes = bytes_of(frames_) + bytes_of(rejection_counts_) + bytes_of(verdicts_) +
                        bytes_of(slots_) + bytes_of(containers_) + bytes_of(heap_) +
                        bytes_of(refs_) + bytes_of(steps_) + bytes_of(mapped_) +
                        bytes_of(claimed_) + materialisable_.capacity() / 8 +
                        bytes_of(element_needed_) + bytes_of(heap_live_) + bytes_of(holders_) +
                        bytes_of(applied_slots_) + bytes_of(element_slots_) +
                        bytes_of(element_addresses_) + bytes_of(string_scratch_) +
                        explained_.bucket_count() * sizeof(void*) +
                        explained_.size() * (sizeof(std::pair<std::uint32_t, std::string>) +
                                             2 * sizeof(void*));
    for (const std::vector<void*>& addresses : element_addresses_) bytes += bytes_of(addresses);
    return bytes;
  }

  void apply() {
    mode_ = Mode::Apply;
    in_.start(payload_, size_);
    container_ordinal_ = 0;
    slot_ordinal_ = 0;
    verdict_cursor_ = 0;
    frames_.clear();
    create_heap_objects();
    decode_objects();  // cannot fail: pass 1 checked the same bytes along the same plan
    fix_up_slots();
    for (std::size_t h = 0; h < holders_.size(); ++h) {
      if (!holders_[h]) continue;
      const auto* ops = static_cast<const SharedPtrOps*>(
          r_.types[plan_.shared_types[heap_[h].node->reader]].ops);
      ops->destroy_holder(holders_[h]);
    }
  }

 private:
  // ---- errors and report ---------------------------------------------------------------
  __attribute__((format(printf, 2, 3))) const Status& corrupt(const char* format, ...) {
    va_list args;
    va_start(args, format);
    set_corrupt_payload(error_, format, args);
    va_end(args);
    return error_;
  }

  // A value-level rejection: the reader keeps its value. Concrete paths are capped per field.
  __attribute__((format(printf, 3, 4), noinline)) void reject_value(std::uint32_t counter,
                                                                    const char* format, ...) {
    if (mode_ != Mode::Check) return;
    ++value_rejections_;
    if (++rejection_counts_[counter] > kMaxConcretePerField) return;
    char buffer[240];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    report_.add(render_path(frames_.data(), frames_.size()), Decision::Rejected, buffer, true);
  }

  void summarise_rejections() {
    if (value_rejections_ <= kMaxConcretePerField) return;  // no counter can exceed the cap
    for (std::size_t c = 0; c < rejection_counts_.size(); ++c) {
      if (rejection_counts_[c] <= kMaxConcretePerField) continue;
      report_.add(counter_path(static_cast<std::uint32_t>(c)), Decision::Rejected,
                  "and " + std::to_string(rejection_counts_[c] - kMaxConcretePerField) +
                      " more values rejected",
                  true);
    }
  }

  std::string counter_path(std::uint32_t counter) const {
    return counter < plan_.counter_paths.size() ? plan_.counter_paths[counter] : "heap objects";
  }

  bool writing() const { return mode_ == Mode::Stage || mode_ == Mode::Apply; }

  // ---- objects: roots then heap objects ------------------------------------------------
  bool decode_objects() {
    for (std::uint32_t wr = 0; wr < w_.root_count; ++wr) {
      const RootPlan& root = plan_.roots[wr];
      std::uint8_t* dst = root.reader_root == kNoType
                              ? nullptr
                              : static_cast<std::uint8_t*>(r_.roots[root.reader_root].address);
      frames_.push_back({PathFrame::Kind::Name, w_.roots[wr].name, 0});
      counter_ = root.counter;
      current_object_ = wr;
      if (!value(root.node, dst, nullptr)) return false;
      frames_.pop_back();
    }
    std::uint32_t heap_count = 0;
    if (!in_.heap_count(heap_count)) return false;
    if (mode_ == Mode::Check) heap_.reserve(heap_count);
    for (std::uint32_t h = 0; h < heap_count; ++h) {
      std::uint32_t type = 0;
      std::uint8_t owner = 0;
      if (!in_.heap_object(h, type, owner)) return false;
      if (mode_ == Mode::Check) {
        if (!plan_.heap_nodes[type]) {
          return corrupt("heap object %u of type %s, which no pointer points to", h,
                         w_.types[type].name).ok();
        }
        heap_.push_back(HeapRecord{type, owner, plan_.heap_nodes[type]});
      }
      frames_.push_back({PathFrame::Kind::Heap, w_.types[type].name, h});
      counter_ = heap_counter_;
      current_object_ = w_.root_count + h;
      std::uint8_t* dst = mode_ == Mode::Apply ? static_cast<std::uint8_t*>(heap_live_[h]) : nullptr;
      if (!value(heap_[h].node, dst, nullptr)) return false;
      frames_.pop_back();
    }
    return true;
  }

  // ---- values --------------------------------------------------------------------------
  bool value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field) {
    return n->validated ? validated_value(n, dst, field) : plain_value(n, dst, field);
  }

  // Only containers and unique_ptrs nest without a bound in the schema (struct nesting is
  // bounded when the schema is parsed); the save side refuses the same depth.
  bool nested(const PlanNode* n, std::uint8_t* dst) {
    if (!in_.nest(++depth_)) {
      --depth_;
      return false;
    }
    const bool ok = value(n, dst, nullptr);
    --depth_;
    return ok;
  }

  bool validated_value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field) {
    if (mode_ != Mode::Check) {
      const bool passed = verdicts_[verdict_cursor_++] != 0;
      return plain_value(n, passed ? dst : nullptr, field);
    }
    const std::size_t verdict = verdicts_.size();
    verdicts_.push_back(1);
    const std::uint8_t* start = in_.position();
    const std::size_t first_slot = slots_.size();
    const std::uint32_t container_mark = container_ordinal_;
    const std::uint32_t slot_mark = slot_ordinal_;
    if (!plain_value(n, dst, field)) return false;
    const std::uint8_t* end = in_.position();

    const TypeInfo& type = r_.types[n->reader];
    bool passed = false;
    const char* why = "failed its symcr_validate";
    std::vector<std::max_align_t> flat;
    void* staged = nullptr;
    if (type.lifecycle) {
      staged = type.lifecycle->create();
    } else if (n->flat_reader) {
      flat.resize((type.size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t) + 1);
      staged = flat.data();
      if (dst) std::memcpy(staged, dst, type.size);
      else std::memset(staged, 0, type.size);
    } else {
      why = "has a symcr_validate but no lifecycle to check a staged copy";
    }
    if (staged) {
      // Decode the same bytes again into the staged copy, replaying the counters.
      const std::uint32_t after_containers = container_ordinal_, after_slots = slot_ordinal_;
      const std::size_t after_cursor = verdict_cursor_;
      in_.seek(start);
      mode_ = Mode::Stage;
      container_ordinal_ = container_mark;
      slot_ordinal_ = slot_mark;
      verdict_cursor_ = verdict + 1;
      const bool decoded = plain_value(n, static_cast<std::uint8_t*>(staged), field);
      mode_ = Mode::Check;
      in_.seek(end);
      container_ordinal_ = after_containers;
      slot_ordinal_ = after_slots;
      verdict_cursor_ = after_cursor;
      passed = decoded && type.validate(staged);
      if (type.lifecycle) type.lifecycle->destroy(staged);
    }
    verdicts_[verdict] = passed ? 1 : 0;
    if (!passed) {
      for (std::size_t s = first_slot; s < slots_.size(); ++s) slots_[s].node = nullptr;
      reject_value(field ? field->counter : counter_, "%s %s", type.name, why);
    }
    return true;
  }

  bool plain_value(const PlanNode* n, std::uint8_t* dst, const FieldPlan* field) {
    if (n->action == Action::Reject) return value(n->skip, nullptr, nullptr);
    if (n->copy_only && !(field && (field->bit_width || field->has_range)) && copy(n, dst)) {
      return true;
    }
    const TypeInfo& wt = w_.types[n->writer];
    switch (wt.kind) {
      case Kind::Bool: case Kind::Int: case Kind::UInt: case Kind::Float: case Kind::Enum:
        return scalar(n, wt, dst, field);
      case Kind::Struct: {
        const std::uint32_t saved = counter_;
        const std::uint8_t* start = in_.position();
        // One path frame for all the fields, renamed per field.
        const std::size_t frame = frames_.size();
        frames_.push_back({PathFrame::Kind::Name, "", 0});
        for (const FieldPlan& child : n->fields) {
          frames_[frame].name = child.name;
          counter_ = child.counter;
          std::uint8_t* at = dst && child.reader_field != kNoType ? dst + child.reader_offset : nullptr;
          if (!value(child.node, at, &child)) return false;
        }
        frames_.pop_back();
        counter_ = saved;
        // The migration hook, once the mechanical rules wrote the object and everything in it
        // (so nested objects' hooks ran first). Also on a validator's staged copy, so that
        // symcr_validate judges the migrated value. Pointers are fixed up after all objects.
        if (n->migrate && dst && writing()) {
          n->migrate(dst, old_values_view(w_, plan_.wire_sizes, n->writer, start,
                                          static_cast<std::size_t>(in_.position() - start)));
        }
        return true;
      }
      case Kind::Union: {
        const std::uint8_t* bytes = nullptr;
        if (!in_.scalar(wt, bytes)) return false;
        if (n->action == Action::Union && dst && writing()) std::memcpy(dst, bytes, wt.size);
        return true;
      }
      case Kind::Array: return array(n, wt, dst);
      case Kind::String: return string(n, wt, dst);
      case Kind::Container: return container(n, wt, dst);
      case Kind::Optional: {
        bool engaged = false;
        if (!in_.presence(wt, engaged)) return false;
        const bool to_reader = n->action == Action::Optional && dst;
        const auto* ops = to_reader ? static_cast<const OptionalOps*>(r_.types[n->reader].ops) : nullptr;
        if (!engaged) {
          if (to_reader && writing()) ops->reset(dst);
          return true;
        }
        std::uint8_t* inner = nullptr;
        if (to_reader) {
          inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
          if (!inner && writing()) inner = static_cast<std::uint8_t*>(ops->emplace(dst));
        }
        return value(n->element, inner, nullptr);
      }
      case Kind::UniquePtr: {
        bool present = false;
        if (!in_.presence(wt, present)) return false;
        const bool to_reader = n->action == Action::UniquePtr && dst;
        const auto* ops = to_reader ? static_cast<const UniquePtrOps*>(r_.types[n->reader].ops) : nullptr;
        if (!present) {
          if (to_reader && writing()) ops->reset(dst);
          return true;
        }
        std::uint8_t* inner = nullptr;
        if (to_reader) {
          // An object the new build already owns is filled in place (its address may be known).
          inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
          if (!inner && writing()) inner = static_cast<std::uint8_t*>(ops->make(dst));
        }
        return nested(n->element, inner);
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
                       w_.types[wt.alternatives[index]].name);
          return value(alternative, nullptr, nullptr);
        }
        std::uint8_t* inner = nullptr;
        if (dst) {
          const auto* ops = static_cast<const VariantOps*>(r_.types[n->reader].ops);
          if (ops->index(dst) == reader_index) {
            inner = static_cast<std::uint8_t*>(const_cast<void*>(ops->get(dst)));
          } else if (writing()) {
            inner = static_cast<std::uint8_t*>(ops->emplace(dst, reader_index));
          }
        }
        return value(alternative, inner, nullptr);
      }
      case Kind::Pointer:
      case Kind::SharedPtr:
        return pointer(n, wt, dst);
    }
    return corrupt("unknown kind").ok();
  }

  // A copy-only value in one step: check it (pass 1), copy it (writing passes). False,
  // consuming nothing, when the bytes are short or a bool or bit-field value is invalid: the
  // general path then finds and reports the same error at its place.
  __attribute__((noinline)) bool copy(const PlanNode* n, std::uint8_t* dst) {
    if (in_.remaining() < n->copy_wire) return false;
    const std::uint8_t* base = in_.position();
    // Checked in every pass: a value the first pass sent to the general path (a rejected
    // bit-field value) must take it in the second too.
    if (!copy_only_valid(*n, base)) return false;
    if (dst && writing()) copy_only_write(*n, base, dst);
    in_.seek(base + n->copy_wire);
    return true;
  }

  __attribute__((noinline)) bool scalar(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst, const FieldPlan* field) {
    const std::uint8_t* bytes = nullptr;
    if (!in_.scalar(wt, bytes)) return false;
    if (n->action != Action::Scalar) return true;
    const bool bit_field = field && field->bit_width;
    const bool ranged = field && field->has_range;
    const TypeInfo& rt = r_.types[n->reader];
    if (n->identical && !bit_field && !ranged) {
      if (dst && writing()) std::memcpy(dst, bytes, wt.kind == Kind::Float && wt.size == 16 ? 10 : wt.size);
      return true;
    }
    const std::uint32_t counter = field ? field->counter : counter_;
    Number in;
    read_number(w_, wt, bytes, in);
    if (wt.kind == Kind::Enum && rt.kind == Kind::Enum && !n->identical) {
      const std::int64_t value = in.tag == Number::Tag::Signed ? in.s : static_cast<std::int64_t>(in.u);
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
        reject_value(counter, "enum %s not in this build", mapping->name);
        return true;
      }
      in.tag = Number::Tag::Signed;
      in.s = mapping->reader_value;
      if (r_.types[rt.element].kind == Kind::UInt) {
        in.tag = Number::Tag::Unsigned;
        in.u = static_cast<std::uint64_t>(mapping->reader_value);
      }
    }
    Number out;
    char why[160];
    if (!convert_number(r_, rt, in, out, why, sizeof why)) {
      reject_value(counter, "%s", why);
      return true;
    }
    if (bit_field) {
      const TypeInfo& integer = rt.kind == Kind::Enum ? r_.types[rt.element] : rt;
      if (!fits_bits(out, field->bit_width, integer.kind == Kind::Int)) {
        char text[64];
        format_number(out, text, sizeof text);
        reject_value(counter, "%s does not fit in %u bits", text, field->bit_width);
        return true;
      }
    }
    if (ranged) {
      const long double v = out.as_long_double();
      if (std::isnan(v) || v < field->range_min || v > field->range_max) {
        char text[64];
        format_number(out, text, sizeof text);
        reject_value(counter, "%s outside [%g, %g]", text, field->range_min, field->range_max);
        return true;
      }
    }
    if (dst && writing()) {
      if (bit_field) store_bits(dst, field->bit_offset, field->bit_width, out);
      else store_number(r_, rt, out, dst);
    }
    return true;
  }

  bool array(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
    const bool to_reader = n->action == Action::Array;
    const TypeInfo& we = w_.types[wt.element];
    const PlanNode* e = n->element;
    // Identical packed scalars: one bounds check and one copy.
    if (to_reader && e->identical && we.kind != Kind::Bool && !(we.kind == Kind::Float && we.size == 16)) {
      const std::uint8_t* bytes = nullptr;
      if (!in_.scalar_run(we, wt.count, bytes)) return false;
      const std::uint64_t common = wt.count < n->reader_count ? wt.count : n->reader_count;
      if (dst && writing()) std::memcpy(dst, bytes, common * we.size);
      return true;
    }
    // Elements that encode to nothing would let a few bytes of schema drive billions of
    // iterations: such arrays are bounded like containers.
    if (!in_.array(wt)) return false;
    const std::size_t frame = frames_.size();
    frames_.push_back({PathFrame::Kind::Index, nullptr, 0});
    for (std::uint64_t i = 0; i < wt.count; ++i) {
      const bool kept = to_reader && i < n->reader_count;
      frames_[frame].index = i;
      std::uint8_t* at = kept && dst ? dst + i * n->reader_stride : nullptr;
      if (!value(kept ? e : n->element_skip, at, nullptr)) return false;
    }
    frames_.pop_back();
    return true;
  }

  __attribute__((noinline)) bool string(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
    std::uint32_t length = 0;
    const std::uint8_t* bytes = nullptr;
    if (!in_.string(wt, bytes, length)) return false;
    const std::uint32_t width = w_.types[wt.element].size;
    if (n->action != Action::String) return true;
    const TypeInfo& rt = r_.types[n->reader];
    const std::uint32_t reader_width = r_.types[rt.element].size;
    const void* chars = bytes;
    std::uint32_t reader_length = length;
    if (reader_width != width) {
      // Another character width: re-encoded (UTF-8/16/32), both passes alike; a string not
      // valid in its encoding is rejected and keeps this build's value.
      char why[160];
      if (!transcode_string(bytes, length, width, reader_width, string_scratch_, reader_length,
                            why, sizeof why)) {
        reject_value(counter_, "%s", why);
        return true;
      }
      chars = string_scratch_.data();
    } else if (reinterpret_cast<std::uintptr_t>(bytes) % width != 0) {
      string_scratch_.assign(bytes, bytes + std::size_t{length} * width);
      chars = string_scratch_.data();
    }
    if (!dst || !writing()) return true;
    static_cast<const StringOps*>(rt.ops)->assign(dst, chars, reader_length);
    return true;
  }

  bool container(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
    std::uint32_t count = 0;
    if (!in_.container(wt, count)) return false;
    const std::uint32_t ordinal = container_ordinal_++;
    const bool to_reader = n->action == Action::Container;
    const PlanNode* e = n->element;
    if (to_reader && mode_ == Mode::Check && !allocation_justified(count, n->reader)) {
      return corrupt("container of %u elements would need %" PRIu64
                     " bytes in this build, more than the checkpoint can justify",
                     count, std::uint64_t{count} * r_.types[r_.types[n->reader].element].size)
          .ok();
    }
    if (mode_ == Mode::Check) containers_.push_back(ContainerRecord{count, e, current_object_});
    std::vector<void*>* addresses = nullptr;
    if (mode_ == Mode::Apply && ordinal < element_slots_.size() && element_slots_[ordinal] != kNoType) {
      addresses = &element_addresses_[element_slots_[ordinal]];
    }
    // Identical fixed-width scalars (not bool: its bytes need checking) need no per-element
    // decoding: one bounds check, and into a contiguous reader container one copy.
    const TypeInfo& we = w_.types[wt.element];
    const bool packed = e->action == Action::Scalar && e->identical && !e->validated &&
                        we.kind != Kind::Bool && !(we.kind == Kind::Float && we.size == 16) &&
                        count > 0 && depth_ < kMaxValueNesting;
    if (packed && (!to_reader || !dst || !writing())) {
      const std::uint8_t* bytes = nullptr;
      return in_.scalar_run(we, count, bytes);
    }
    if (!to_reader || !dst || !writing()) {
      for (std::uint32_t i = 0; i < count; ++i) {
        frames_.push_back({PathFrame::Kind::Index, nullptr, i});
        if (!nested(e, nullptr)) return false;
        frames_.pop_back();
      }
      return true;
    }
    const TypeInfo& rt = r_.types[n->reader];
    const auto* ops = static_cast<const ContainerOps*>(rt.ops);
    if (packed && ops->resize_default && r_.types[rt.element].size == we.size) {
      // Resized, not cleared first: the elements it keeps are overwritten below, so only
      // the new ones are value-initialised.
      const std::uint8_t* bytes = nullptr;
      if (!in_.scalar_run(we, count, bytes)) return false;
      auto* elements = static_cast<std::uint8_t*>(ops->resize_default(dst, count));
      std::memcpy(elements, bytes, std::size_t{count} * we.size);
      if (addresses) {
        for (std::uint32_t i = 0; i < count; ++i) addresses->push_back(elements + std::size_t{i} * we.size);
      }
      return true;
    }
    ops->clear(dst);
    if (ops->append) {
      ops->reserve(dst, count);  // vectors: element addresses stay valid while we append
      for (std::uint32_t i = 0; i < count; ++i) {
        frames_.push_back({PathFrame::Kind::Index, nullptr, i});
        if (refused_by_validator(e)) {  // not appended: the container holds what passed
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
    const Lifecycle* lifecycle = r_.types[rt.element].lifecycle;
    for (std::uint32_t i = 0; i < count; ++i) {
      frames_.push_back({PathFrame::Kind::Index, nullptr, i});
      alignas(16) std::uint64_t scalar_buffer[2] = {0, 0};  // a scalar element without a lifecycle
      auto* staged = lifecycle ? static_cast<std::uint8_t*>(lifecycle->create())
                               : reinterpret_cast<std::uint8_t*>(scalar_buffer);
      const std::size_t first_slot = applied_slots_.size();
      const bool refused = refused_by_validator(e);
      if (!nested(e, staged)) {
        if (lifecycle) lifecycle->destroy(staged);
        return false;
      }
      auto* inserted = refused ? nullptr : static_cast<std::uint8_t*>(ops->insert(dst, staged));
      if (inserted) {
        // Slots in the staged element's own bytes moved with it; slots in storage it owns
        // (a vector's buffer, a unique_ptr's pointee) were moved by pointer and stay put.
        const std::size_t element_size = r_.types[rt.element].size;
        for (std::size_t s = first_slot; s < applied_slots_.size(); ++s) {
          std::uint8_t* at = applied_slots_[s].address;
          if (at >= staged && at < staged + element_size) {
            applied_slots_[s].address = inserted + (at - staged);
          }
        }
      } else if (refused) {
        applied_slots_.resize(first_slot);
      } else {
        applied_slots_.resize(first_slot);
        if (mode_ == Mode::Apply) {
          report_.add(render_path(frames_.data(), frames_.size()), Decision::Rejected,
                      "duplicate key: element not inserted", true);
        }
      }
      if (addresses) addresses->push_back(inserted);
      if (lifecycle) lifecycle->destroy(staged);
      frames_.pop_back();
    }
    return true;
  }

  // Pass 2: whether the next element, validated as a whole, failed its validator in pass 1.
  // Such an element is left out of its container (reported and lossy in pass 1), never
  // inserted value-initialised.
  bool refused_by_validator(const PlanNode* e) const {
    return e->validated && mode_ == Mode::Apply && verdicts_[verdict_cursor_] == 0;
  }

  // A hostile (or merely old) checkpoint must not make restore allocate more than its own size
  // justifies: a 4-byte count of empty writer elements must not become 2^20 elements of a
  // reader type that grew to 64 KiB. Allowed: a fixed 64 MiB, or 16 bytes of this build's
  // memory per payload byte, whichever is larger (a 256 MiB vector<double> restores).
  bool allocation_justified(std::uint32_t count, std::uint32_t reader_container) const {
    constexpr std::uint64_t kAlwaysAllowed = std::uint64_t{64} << 20;
    constexpr std::uint64_t kBytesPerPayloadByte = 16;
    const std::uint64_t element_size = r_.types[r_.types[reader_container].element].size;
    const std::uint64_t needed = std::uint64_t{count} * element_size;
    return needed <= kAlwaysAllowed || needed / kBytesPerPayloadByte <= size_;
  }

  __attribute__((noinline)) bool pointer(const PlanNode* n, const TypeInfo& wt, std::uint8_t* dst) {
    std::uint32_t code = 0;
    if (!in_.pointer(wt, code)) return false;
    const bool shared = wt.kind == Kind::SharedPtr;
    const std::uint32_t ordinal = slot_ordinal_++;
    const bool to_reader = n->action == Action::Pointer || n->action == Action::SharedPtr;
    if (mode_ == Mode::Check) {
      SlotRecord record{};
      record.code = code;
      record.pointer_type = n->writer;
      record.node = to_reader ? n : nullptr;
      record.shared = shared;
      if (to_reader && dst && !shared) std::memcpy(&record.live, dst, sizeof(void*));
      record.counter = counter_;
      record.object = current_object_;
      record.outcome = SlotOutcome::Skip;
      slots_.push_back(record);
    } else if (mode_ == Mode::Apply && to_reader && dst) {
      applied_slots_.push_back(AppliedSlot{ordinal, dst});
    } else if (mode_ == Mode::Explain) {
      auto wanted = explained_.find(ordinal);
      if (wanted != explained_.end()) wanted->second = render_path(frames_.data(), frames_.size());
    }
    return true;
  }

  // ---- references ----------------------------------------------------------------------
  bool decode_references() {
    std::uint32_t count = 0;
    if (!in_.reference_count(count)) return false;
    refs_.resize(count);
    const std::uint32_t object_count = w_.root_count + static_cast<std::uint32_t>(heap_.size());
    auto object_type = [&](std::uint32_t a, std::uint32_t& type) {
      if (a >= object_count) return false;
      type = a < w_.root_count ? w_.roots[a].type : heap_[a - w_.root_count].type;
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
      if (!in_.reference(i, ref, object_type, element_type, on_step)) return false;
    }
    return true;
  }

  bool check_slots() {
    for (const SlotRecord& slot : slots_) {
      if (slot.code < 2) continue;
      const std::uint32_t index = slot.code - 2;
      if (index >= refs_.size()) return corrupt("pointer to reference %u of %zu", index, refs_.size()).ok();
      const RefRecord& ref = refs_[index];
      if (ref.target != w_.types[slot.pointer_type].element) {
        return corrupt("a %s refers to a %s", w_.types[slot.pointer_type].name, w_.types[ref.target].name).ok();
      }
      if (slot.shared && (ref.base != 0 || ref.a < w_.root_count || ref.step_count != 0 ||
                          heap_[ref.a - w_.root_count].owner != 1)) {
        return corrupt("a shared_ptr refers to something other than a shared heap object").ok();
      }
    }
    return true;
  }

  bool inside_reader_root(std::uintptr_t address) const {
    for (std::uint32_t r = 0; r < r_.root_count; ++r) {
      const auto start = reinterpret_cast<std::uintptr_t>(r_.roots[r].address);
      if (address >= start && address < start + r_.types[r_.roots[r].type].size) return true;
    }
    return false;
  }

  // docs/resolution.md, pointers: a non-null pointer the new build already holds, of the pointee's type,
  // lends its object to the heap object it now refers to (once; never an object in a root).
  void claim_live_objects() {
    claimed_.assign(heap_.size(), nullptr);
    std::unordered_set<std::uintptr_t> taken;
    for (const SlotRecord& slot : slots_) {
      if (!slot.node || slot.shared || slot.code < 2 || !slot.live) continue;
      const RefRecord& ref = refs_[slot.code - 2];
      if (ref.base != 0 || ref.a < w_.root_count || ref.step_count != 0) continue;
      const std::uint32_t h = ref.a - w_.root_count;
      if (heap_[h].owner != 0 || claimed_[h]) continue;
      if (heap_[h].node->reader == kNoType || heap_[h].node->reader != slot.node->element->reader) continue;
      if (inside_reader_root(slot.live) || !taken.insert(slot.live).second) continue;
      claimed_[h] = reinterpret_cast<void*>(slot.live);
    }
  }

  // A heap object is created (or claimed) only when the new build can make it and a pointer
  // that will really be restored reaches it from a restored root, so nothing is allocated for
  // pointers in dropped fields. A shared_ptr object must be reached through a shared_ptr: with
  // no restored owner it would die at once and leave raw pointers to it dangling.
  void decide_materialisation() {
    const std::uint32_t roots = w_.root_count;
    const std::size_t objects = roots + heap_.size();
    std::vector<bool> creatable(heap_.size(), false);
    for (std::size_t h = 0; h < heap_.size(); ++h) {
      const PlanNode* node = heap_[h].node;
      if (node->reader == kNoType || node->action == Action::Reject) continue;
      const TypeInfo& type = r_.types[node->reader];
      const bool can_create =
          type.lifecycle != nullptr || (dry_run_ && (type.flags & kTypeCreatable) != 0);
      creatable[h] = claimed_[h] || (heap_[h].owner == 0 && can_create) ||
                     (heap_[h].owner == 1 && plan_.shared_types[node->reader] != kNoType);
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
      if (slot.code < 2) continue;
      everything_restorable = slot.node != nullptr;
      if (everything_restorable && slot.shared) {  // shared targets are whole heap objects
        const std::uint32_t h = refs_[slot.code - 2].a - roots;
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
        if (!slot.node || slot.code < 2) continue;
        const RefRecord& ref = refs_[slot.code - 2];
        const std::uint32_t target = ref.base == 0 ? ref.a : containers_[ref.a].object;
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

  // Maps a reference's writer steps onto reader steps by name (via the plan), never offsets.
  void map_reference(RefRecord& ref) {
    const PlanNode* node = nullptr;
    if (ref.base == 0 && ref.a < w_.root_count) {
      const RootPlan& root = plan_.roots[ref.a];
      if (root.reader_root == kNoType) {
        ref.why = std::string("root ") + w_.roots[ref.a].name + " not in this build";
        return;
      }
      node = root.node;
    } else if (ref.base == 0) {
      const std::uint32_t h = ref.a - w_.root_count;
      if (!materialisable_[h]) {
        ref.why = std::string("heap object of type ") + w_.types[heap_[h].type].name +
                  (heap_[h].owner == 1 ? " has no shared_ptr owner restored in this build"
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
          mapped_.push_back({MappedStep::Kind::Offset, node->reader, std::uint64_t{step} * node->reader_stride});
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
          if (w_.types[w_.types[node->writer].element].size !=
              r_.types[r_.types[node->reader].element].size) {
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
      ref.why = std::string("target's type ") + w_.types[ref.target].name + " changed incompatibly";
      return;
    }
    ref.mapped_count = static_cast<std::uint32_t>(mapped_.size()) - ref.mapped_at;
    ref.reader_type = node->reader;
    ref.resolved = true;
  }

  // Decides every pointer slot; the concrete paths of the few reported ones are rendered by a
  // third walk rather than remembered for every pointer of a large graph.
  void decide_slots() {
    struct Pending {
      std::uint32_t ordinal;
      Decision decision;
      std::string detail;
    };
    std::vector<Pending> pending;
    for (std::size_t ordinal = 0; ordinal < slots_.size(); ++ordinal) {
      SlotRecord& slot = slots_[ordinal];
      if (!slot.node) continue;
      auto reject = [&](const std::string& why) {
        slot.outcome = SlotOutcome::Rejected;
        ++value_rejections_;
        if (++rejection_counts_[slot.counter] > kMaxConcretePerField) return;
        pending.push_back({static_cast<std::uint32_t>(ordinal), Decision::Rejected,
                           "pointer not restored: " + why});
      };
      if (slot.code == 0) {
        slot.outcome = SlotOutcome::Null;
      } else if (slot.code == 1) {
        slot.outcome = SlotOutcome::Outside;
        if (++outside_count_ <= kMaxConcretePerField) {
          pending.push_back({static_cast<std::uint32_t>(ordinal), Decision::Kept,
                             "pointed outside the checkpointed state: kept this build's value"});
        }
      } else {
        const RefRecord& ref = refs_[slot.code - 2];
        if (!ref.resolved) {
          reject(ref.why);
        } else if (ref.reader_type != slot.node->element->reader) {
          reject(std::string("target is a ") + r_.types[ref.reader_type].name + " in this build, not a " +
                 r_.types[slot.node->element->reader].name);
        } else {
          slot.outcome = SlotOutcome::Target;
        }
      }
    }
    if (!pending.empty()) {
      for (const Pending& entry : pending) explained_[entry.ordinal];
      mode_ = Mode::Explain;
      in_.start(payload_, size_);
      container_ordinal_ = 0;
      slot_ordinal_ = 0;
      verdict_cursor_ = 0;
      frames_.clear();
      decode_objects();  // cannot fail: the same bytes decoded in pass 1
      mode_ = Mode::Check;
      for (Pending& entry : pending) {
        report_.add(explained_[entry.ordinal], entry.decision, std::move(entry.detail),
                    entry.decision == Decision::Rejected);
      }
    }
    if (outside_count_ > kMaxConcretePerField) {
      report_.add("pointers", Decision::Kept,
                  "and " + std::to_string(outside_count_ - kMaxConcretePerField) +
                      " more pointed outside the checkpointed state",
                  false);
    }
  }

  // ---- pass 2 --------------------------------------------------------------------------
  void create_heap_objects() {
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
        heap_live_[h] = r_.types[reader].lifecycle->create();
      } else {
        const auto* ops = static_cast<const SharedPtrOps*>(r_.types[plan_.shared_types[reader]].ops);
        holders_[h] = ops->make_holder();
        heap_live_[h] = ops->holder_get(holders_[h]);
      }
    }
    element_slots_.assign(containers_.size(), kNoType);
    for (std::uint32_t ordinal : element_needed_) {
      if (element_slots_[ordinal] != kNoType) continue;
      element_slots_[ordinal] = static_cast<std::uint32_t>(element_addresses_.size());
      element_addresses_.emplace_back();
      element_addresses_.back().reserve(containers_[ordinal].count);
    }
  }

  void* target_of(const RefRecord& ref) {
    std::uint8_t* at = nullptr;
    if (ref.base == 0 && ref.a < w_.root_count) {
      at = static_cast<std::uint8_t*>(r_.roots[plan_.roots[ref.a].reader_root].address);
    } else if (ref.base == 0) {
      at = static_cast<std::uint8_t*>(heap_live_[ref.a - w_.root_count]);
    } else {
      const std::uint32_t slot = element_slots_[ref.a];
      const std::vector<void*>& addresses = element_addresses_[slot];
      if (ref.b < addresses.size()) at = static_cast<std::uint8_t*>(addresses[ref.b]);
    }
    for (std::uint32_t s = 0; s < ref.mapped_count && at; ++s) {
      const MappedStep& step = mapped_[ref.mapped_at + s];
      const void* ops = r_.types[step.holder_type].ops;
      switch (step.kind) {
        case MappedStep::Kind::Offset: at += step.value; break;
        case MappedStep::Kind::Optional:
          at = static_cast<std::uint8_t*>(const_cast<void*>(static_cast<const OptionalOps*>(ops)->get(at)));
          break;
        case MappedStep::Kind::Unique:
          at = static_cast<std::uint8_t*>(const_cast<void*>(static_cast<const UniquePtrOps*>(ops)->get(at)));
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
          const std::uint32_t width = r_.types[r_.types[step.holder_type].element].size;
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

  void fix_up_slots() {
    for (const AppliedSlot& applied : applied_slots_) {
      const SlotRecord& slot = slots_[applied.ordinal];
      const auto* shared_ops = slot.shared ? static_cast<const SharedPtrOps*>(r_.types[slot.node->reader].ops) : nullptr;
      switch (slot.outcome) {
        case SlotOutcome::Null:
          if (shared_ops) shared_ops->reset(applied.address);
          else std::memset(applied.address, 0, sizeof(void*));
          break;
        case SlotOutcome::Target: {
          const RefRecord& ref = refs_[slot.code - 2];
          if (shared_ops) {
            shared_ops->assign_from_holder(applied.address, holders_[ref.a - w_.root_count]);
            break;
          }
          void* target = target_of(ref);
          if (!target) {
            report_.add(counter_path(slot.counter), Decision::Rejected,
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

  const Plan& plan_;
  const Schema& w_;
  const Schema& r_;
  Status error_;
  PayloadReader in_;
  const std::uint8_t* payload_;
  std::size_t size_;
  Report& report_;
  const bool dry_run_;

  Mode mode_ = Mode::Check;
  int depth_ = 0;
  std::vector<PathFrame> frames_;
  std::uint32_t counter_ = 0;
  std::uint32_t heap_counter_ = 0;
  std::uint32_t current_object_ = 0;
  std::vector<std::uint32_t> rejection_counts_;
  std::size_t value_rejections_ = 0;
  std::size_t outside_count_ = 0;

  std::uint32_t container_ordinal_ = 0;
  std::uint32_t slot_ordinal_ = 0;
  std::vector<std::uint8_t> verdicts_;
  std::size_t verdict_cursor_ = 0;

  std::vector<SlotRecord> slots_;
  std::unordered_map<std::uint32_t, std::string> explained_;  // slot ordinal -> path
  std::vector<ContainerRecord> containers_;
  std::vector<HeapRecord> heap_;
  std::vector<RefRecord> refs_;
  std::vector<std::uint32_t> steps_;
  std::vector<MappedStep> mapped_;
  std::vector<void*> claimed_;
  std::vector<bool> materialisable_;
  std::vector<std::uint32_t> element_needed_;

  std::vector<void*> heap_live_;
  std::vector<void*> holders_;
  std::vector<AppliedSlot> applied_slots_;
  std::vector<std::uint32_t> element_slots_;
  std::vector<std::vector<void*>> element_addresses_;
  std::vector<std::uint8_t> string_scratch_;
};

}  // namespace

namespace {

// The fast path for a copy-only plan (the same build, or changes that only move fields): true
// when the payload is exactly the roots' copy programs and two empty sections, every bool 0 or
// 1 and every bit-field value within its width, after copying (if `apply`). False for anything else, leaving the general decoder to
// find and name the fault; nothing is written then.
bool restore_copy_only(const Plan& plan, const std::uint8_t* payload, std::size_t size,
                       bool apply) {
  if (payload == nullptr || size != plan.copy_only_payload_size) return false;
  const Schema& reader = *plan.reader;
  const std::uint8_t* at = payload;
  for (const RootPlan& root : plan.roots) {
    if (!copy_only_valid(*root.node, at)) return false;
    at += root.node->copy_wire;
  }
  std::uint32_t heap_count = 0, reference_count = 0;
  std::memcpy(&heap_count, at, sizeof heap_count);  // zero in any byte order
  std::memcpy(&reference_count, at + sizeof heap_count, sizeof reference_count);
  if (heap_count != 0 || reference_count != 0) return false;
  if (!apply) return true;
  at = payload;
  for (const RootPlan& root : plan.roots) {
    copy_only_write(*root.node, at, static_cast<std::uint8_t*>(reader.roots[root.reader_root].address));
    at += root.node->copy_wire;
  }
  return true;
}

Report run_restore(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                   std::size_t size, const Schema& reader, const RestoreOptions& options,
                   bool plan_only, bool apply) {
  Report report;
  Status status;
  std::shared_ptr<const Plan> plan = plan_for(writer, writer_hash, reader, status);
  if (!plan) {
    report.set_status(status);
    return report;
  }
  // The schema-level entries depend only on the plan: shared with it, copied only if a
  // value-level entry is added.
  report.set_shared_entries(
      std::shared_ptr<const std::vector<ReportEntry>>(plan, &plan->entries));
  if (!plan->status.ok()) {
    report.set_status(plan->status);
    return report;
  }
  if (!payload && size) {
    report.set_status(Status(Error::Corrupt, "invalid payload: no bytes"));
    return report;
  }
  const bool strict_refusal = options.strict && plan->any_lossy;
  if (!plan_only && !strict_refusal && plan->copy_only_payload &&
      restore_copy_only(*plan, payload, size, apply)) {
    last_restore_scratch = 0;  // no decoding tables
    return report;
  }
  std::size_t value_rejections = 0;
  Restorer restorer(*plan, payload, size, report, /*dry_run=*/!apply);
  if (!plan_only) {
    status = restorer.check();
    if (!status.ok()) {
      report.set_status(status);
      return report;
    }
    value_rejections = restorer.value_rejections();
  }
  if (options.strict && (plan->any_lossy || value_rejections > 0)) {
    const ReportEntry* first = nullptr;
    for (const ReportEntry& entry : report.entries()) {
      if (entry.lossy) {
        first = &entry;
        break;
      }
    }
    report.set_status(Status(Error::Strict, "strict mode: lossy restore refused (first: %s: %s %s)",
                             first ? first->path.c_str() : "?",
                             first ? decision_name(first->decision) : "",
                             first ? first->detail.c_str() : ""));
    return report;
  }
  if (apply) restorer.apply();
  last_restore_scratch = restorer.scratch_bytes();
  return report;
}

}  // namespace

ScratchBytes thread_scratch_bytes() {
  ScratchBytes bytes;
  bytes.checkpoint = encode_scratch_bytes();
  bytes.restore = last_restore_scratch;
  return bytes;
}

Report restore_payload(const Schema& writer, std::uint64_t writer_hash,
                       const std::uint8_t* payload, std::size_t size, const Schema& reader,
                       const RestoreOptions& options) {
  return run_restore(writer, writer_hash, payload, size, reader, options, false, true);
}

Report plan_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                    std::size_t size, const Schema& reader, const RestoreOptions& options) {
  const bool plan_only = payload == nullptr && size == 0;
  return run_restore(writer, writer_hash, payload, size, reader, options, plan_only, false);
}

}  // namespace symcr::detail
