// The device profile's restore: the record checked whole (header, CRC, schema hash, program),
// every value decoded into a staged copy of the roots with its range and validator checked, the
// reference table checked to its end, and only then the roots written.
#include <cstring>

#include "device_format.hpp"

namespace symcr {
namespace device {
namespace {

using format::load16;
using format::load32;

// Kinds whose wire bytes are their memory bytes (Bool is checked, Pointer translated).
bool is_bytes(Kind kind) {
  return kind == Kind::Int || kind == Kind::UInt || kind == Kind::Enum || kind == Kind::Float ||
         kind == Kind::Union;
}

class Restorer {
 public:
  Restorer(const Schema& schema, const std::uint8_t* payload, std::size_t size, std::uint8_t* stage,
           bool as_host)
      : schema_(schema), payload_(payload), size_(size), stage_(stage), as_host_(as_host) {}

  Result run(const detail::PayloadShape* shape) {
    // The values have a fixed size: the tables behind them can be found, and checked, first.
    // Built for size (a device, which has no shape kept), the walks are the only code.
    const bool kept = !detail::kBuiltForSize && shape != nullptr;
    const std::size_t values = kept ? shape->values : detail::values_size(schema_);
    const std::uint32_t clocks = kept ? shape->clocks : detail::clock_count(schema_);
    if (clocks > kMaxClocks) return Result::Unsupported;
    const std::size_t readings = format::clock_readings_size(clocks);
    const std::size_t counts = format::kHeapCountSize + format::kReferenceCountSize;
    if (size_ < values + counts + readings) return Result::Truncated;
    if (load32(payload_ + values) != 0) return Result::Corrupt;  // heap objects
    reference_count_ = load32(payload_ + values + format::kHeapCountSize);
    references_ = values + counts;
    references_end_ = size_ - readings;
    Result result = check_references();
    if (result != Result::Ok) return result;
    decide_clock_deltas(clocks);
    const bool stepped = kept && shape->steps != nullptr;
    std::uint8_t* stage = stage_;
    for (std::uint32_t r = 0; r < schema_.root_count; ++r) {
      const RootInfo& root = schema_.roots[r];
      const std::size_t size = detail::root_size(schema_, r);
      std::memcpy(stage, root.address, size);  // what the record does not hold stays as is
      if (!stepped) {
        result = value(root.type, stage, nullptr);
        if (result != Result::Ok) return result;
      }
      stage += detail::stage_size(size);
    }
    return stepped ? run_steps(shape->steps, shape->step_count) : Result::Ok;
  }

 private:
  // Every reference well-formed, ending at its target type, and nothing after the table.
  Result check_references() {
    std::size_t at = references_;
    for (std::uint32_t i = 0; i < reference_count_; ++i) {
      std::uintptr_t ignored;
      std::uint32_t type;
      const Result result = reference_at(&at, &ignored, &type);
      if (result != Result::Ok) return result;
    }
    return at == references_end_ ? Result::Ok : Result::Corrupt;
  }

  // How far each clock moved since the checkpoint: its times move as far (a device restores
  // after a reset, in a process other than the one that saved).
  void decide_clock_deltas(std::uint32_t clocks) {
    for (std::uint32_t c = 0; c < clocks; ++c) {
      const ClockInfo* clock = detail::clock_at(schema_, c);
      const std::uint64_t saved =
          static_cast<std::uint64_t>(format::clock_reading(payload_ + references_end_, c));
      deltas_[c] = clock && clock->read ? static_cast<std::uint64_t>(clock->read()) - saved : 0;
    }
  }

  // Reads the reference at `*at` (advancing it): its target's address in the live roots.
  Result reference_at(std::size_t* at, std::uintptr_t* address, std::uint32_t* type) const {
    std::size_t p = *at;
    if (size_ - p < format::kObjectReferenceStepsOffset) return Result::Truncated;
    if (payload_[p] != format::kBaseObject) return Result::Corrupt;  // no containers here
    const std::uint32_t root = load32(payload_ + p + format::kReferenceObjectOffset);
    const std::size_t step_count = load16(payload_ + p + format::kObjectReferenceStepCountOffset);
    if (step_count > kMaxPathSteps) return Result::Corrupt;
    if (size_ - p < format::object_reference_size(step_count)) return Result::Truncated;
    const std::uint8_t* step = payload_ + p + format::kObjectReferenceStepsOffset;
    std::uint32_t steps[kMaxPathSteps];
    for (std::size_t s = 0; s < step_count; ++s, step += format::kReferenceStepSize) {
      steps[s] = load32(step);
    }
    const std::uint32_t target_type = load32(step);
    p += format::object_reference_size(step_count);
    std::size_t offset = 0;
    if (!detail::follow_path(schema_, root, steps, step_count, &offset, type) ||
        *type != target_type) {
      return Result::Corrupt;
    }
    *address = reinterpret_cast<std::uintptr_t>(schema_.roots[root].address) + offset;
    *at = p;
    return Result::Ok;
  }

  // The target of reference `index` (already checked), for a pointer to `pointee`.
  Result reference(std::uint32_t index, std::uint32_t pointee, std::uintptr_t* address) const {
    if (index >= reference_count_) return Result::Corrupt;
    std::size_t at = references_;
    std::uint32_t type = kNoType;
    for (std::uint32_t i = 0; i <= index; ++i) {
      const Result result = reference_at(&at, address, &type);
      if (result != Result::Ok) return result;
    }
    return type == pointee ? Result::Ok : Result::Corrupt;
  }

  const std::uint8_t* take(std::size_t n) {
    const std::uint8_t* bytes = payload_ + at_;
    at_ += n;
    return bytes;
  }

  // Decodes a value of type `t` into `stage` (the staged copy). `time`: the clock of the times
  // it holds (a time field: an integer, or an array of them), each moved by its clock's advance.
  Result value(std::uint32_t t, std::uint8_t* stage, const FieldTime* time) {
    const detail::TypeView type = detail::type_at(schema_, t);
    switch (type.kind) {
      case Kind::Bool: {
        const std::uint8_t b = *take(1);
        if (b > 1) return Result::Corrupt;
        *stage = b;
        return Result::Ok;
      }
      case Kind::Pointer:
        return pointer(type, stage);
      case Kind::Array: {
        const detail::TypeView element = detail::type_at(schema_, type.element);
        const std::size_t stride = element.size;
        // Values that are their bytes, with no time to move: in one copy.
        if (!detail::kBuiltForSize && time == nullptr && is_bytes(element.kind)) {
          std::memcpy(stage, take(stride * type.count), stride * type.count);
          return Result::Ok;
        }
        // Structs of plain numbers: each element by the same few copies.
        CopyRun runs[kMaxCopyRuns];
        std::size_t run_count = 0;
        if (!detail::kBuiltForSize && time == nullptr && element.kind == Kind::Struct &&
            plain_runs(type.element, runs, &run_count)) {
          const std::uint8_t* wire = payload_ + at_;
          for (std::size_t i = 0; i < type.count; ++i) {
            std::uint8_t* to = stage + i * stride;
            for (std::size_t r = 0; r < run_count; ++r) {
              copy_value(to + runs[r].offset, wire, runs[r].size);
              wire += runs[r].size;
            }
          }
          at_ = static_cast<std::size_t>(wire - payload_);
          return Result::Ok;
        }
        for (std::size_t i = 0; i < type.count; ++i) {
          const Result result = value(type.element, stage + i * stride, time);
          if (result != Result::Ok) return result;
        }
        return Result::Ok;
      }
      case Kind::Struct: {
        for (std::uint32_t f = 0; f < type.field_count; ++f) {
          if (!detail::kBuiltForSize) {
            f = plain_fields(t, f, type.field_count, stage);
            if (f == type.field_count) break;
          }
          const Result result = field_value(t, f, stage);
          if (result != Result::Ok) return result;
        }
        // The validator sees the staged value, whose pointers already point at live objects.
        return type.validate != nullptr && !type.validate(stage) ? Result::Rejected : Result::Ok;
      }
      default:  // Int, UInt, Enum, Float, Union: their bytes
        bytes(type, stage, time);
        return Result::Ok;
    }
  }

  // Decodes field `f` of struct `t` into the struct's staged copy at `stage`, and checks its
  // range.
  Result field_value(std::uint32_t t, std::uint32_t f, std::uint8_t* stage) {
    const detail::FieldView field = detail::field_at(schema_, t, f);
    const std::uint8_t* wire = payload_ + at_;  // a scalar's value, bit-fields' too
    if (field.bit_width != 0) {
      const Result result = bit_field(field, stage + field.offset);
      if (result != Result::Ok) return result;
    } else if (!detail::kBuiltForSize && is_bytes(detail::type_at(schema_, field.type).kind)) {
      // Decoded here rather than by a call (the accessors inlined, one type read): most fields
      // are numbers.
      bytes(detail::type_at(schema_, field.type), stage + field.offset, field.time);
    } else {
      const Result result = value(field.type, stage + field.offset, field.time);
      if (result != Result::Ok) return result;
    }
    return field.range != nullptr && !in_range(field, wire) ? Result::Rejected : Result::Ok;
  }

  // The walk as held_steps() wrote it: each run of wire bytes in one copy, each other value
  // decoded as the walk decodes it, in the walk's order (so the first fault found is the same).
  Result run_steps(const detail::HeldStep* steps, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      const detail::HeldStep& step = steps[i];
      std::uint8_t* stage = stage_ + step.stage;
      Result result = Result::Ok;
      if (step.type == kNoType) {
        copy_value(stage, take(step.size), step.size);
      } else if (step.field == kNoType) {
        result = value(step.type, stage, nullptr);
      } else {
        result = field_value(step.type, step.field, stage);
      }
      if (result != Result::Ok) return result;
    }
    return Result::Ok;
  }

  // A plain number is a field that plain_fields() copies as it is.
  static bool is_plain(const FieldInfo& field, const TypeInfo& member) {
    return is_bytes(member.kind) && field.bit_width == 0 &&
           (field.flags & (kFieldHasRange | kFieldClockTime)) == 0;
  }

  // Bytes of a struct that are its wire bytes in one copy: `size` at `offset` in the value.
  struct CopyRun {
    std::uint32_t offset;
    std::uint32_t size;
  };
  static constexpr std::size_t kMaxCopyRuns = 8;

  // Built for speed, over a host's TypeInfo tables: struct `t` as at most kMaxCopyRuns runs of
  // bytes, in its fields' order, when every field is a plain number and no validator checks it
  // (fields adjacent in memory share a run). False otherwise.
  bool plain_runs(std::uint32_t t, CopyRun* runs, std::size_t* run_count) const {
    const TypeInfo* const types = schema_.types;
    if (types == nullptr || types[t].validate != nullptr) return false;
    std::size_t count = 0;
    for (std::uint32_t f = 0; f < types[t].field_count; ++f) {
      const FieldInfo& field = types[t].fields[f];
      const TypeInfo& member = types[field.type];
      if (!is_plain(field, member)) return false;
      if (count != 0 && runs[count - 1].offset + runs[count - 1].size == field.offset) {
        runs[count - 1].size += member.size;
        continue;
      }
      if (count == kMaxCopyRuns) return false;
      runs[count++] = CopyRun{field.offset, member.size};
    }
    *run_count = count;
    return true;
  }

  // Built for speed, over a host's TypeInfo tables: the fields of struct `t` from `f` on that
  // are numbers with no bit-field, range or time, each copied straight from the tables and the
  // payload held in locals (a store through `stage` may alias any member, which the compiler
  // would otherwise load again). Returns the first field it did not decode. A first restore in a
  // fresh process decodes every field: most of its instructions were these fields' steps.
  std::uint32_t plain_fields(std::uint32_t t, std::uint32_t f, std::uint32_t count,
                             std::uint8_t* stage) {
    const TypeInfo* const types = schema_.types;
    if (types == nullptr) return f;  // compact tables: the general steps
    const FieldInfo* const fields = types[t].fields;
    const std::uint8_t* wire = payload_ + at_;
    for (; f < count; ++f) {
      const FieldInfo& field = fields[f];
      const TypeInfo& member = types[field.type];
      if (!is_plain(field, member)) break;
      copy_value(stage + field.offset, wire, member.size);
      wire += member.size;
    }
    at_ = static_cast<std::size_t>(wire - payload_);
    return f;
  }

  // Built for size, one memcpy; built for speed, a small copy takes no call.
  static void copy_value(std::uint8_t* to, const std::uint8_t* from, std::size_t size) {
    if (detail::kBuiltForSize) {
      std::memcpy(to, from, size);
    } else {
      format::copy_bytes(to, from, size);
    }
  }

  // A value that is its bytes (is_bytes()), an integer time moved by its clock's advance.
  void bytes(const detail::TypeView& type, std::uint8_t* stage, const FieldTime* time) {
    copy_value(stage, take(type.size), type.size);
    if (time != nullptr && (type.kind == Kind::Int || type.kind == Kind::UInt)) {
      format::rebase_time(stage, type.size, time->never, deltas_[time->clock->index]);
    }
  }

  Result pointer(const detail::TypeView& type, std::uint8_t* stage) {
    const std::uint32_t code = load32(take(format::kPointerCodeSize));
    std::uintptr_t target = 0;
    if (code == format::kOutsideCode) {                 // the running build's value stays
      return as_host_ ? Result::Rejected : Result::Ok;  // a host reports it: its general way
    }
    if (code != format::kNullCode) {
      const Result result = reference(code - format::kFirstReference, type.element, &target);
      if (result != Result::Ok) return result;
    }
    std::memcpy(stage, &target, sizeof target);
    return Result::Ok;
  }

  Result bit_field(const detail::FieldView& field, std::uint8_t* unit) {
    const detail::TypeView type = detail::type_at(schema_, field.type);
    const Kind integer =
        type.kind == Kind::Enum ? detail::type_at(schema_, type.element).kind : type.kind;
    const unsigned bytes = (field.bit_offset + field.bit_width + 7u) / 8u;
    const std::size_t width = type.size > 8 ? 8 : type.size;
    if (bytes > 8) return Result::Unsupported;  // also a width above 64
    const bool is_signed = integer == Kind::Int;
    std::uint64_t v = 0;
    std::memcpy(&v, take(width), width);
    if (is_signed) v = detail::bits_at(v, 0, 8 * width, true);  // sign-extend the wire value
    if (type.kind == Kind::Bool && v > 1) return Result::Corrupt;
    // The value must survive the field's width: as written, it did.
    if (detail::bits_at(v, 0, field.bit_width, is_signed) != v) return Result::Corrupt;
    const std::uint64_t mask = detail::bits_at(~std::uint64_t{0}, 0, field.bit_width, false)
                               << field.bit_offset;
    std::uint64_t raw = 0;
    std::memcpy(&raw, unit, bytes);
    raw = (raw & ~mask) | ((v << field.bit_offset) & mask);
    std::memcpy(unit, &raw, bytes);
    return Result::Ok;
  }

  // `p`: the value's wire bytes (a bit-field's value sign-extended to its type's width).
  bool in_range(const detail::FieldView& field, const std::uint8_t* p) const {
    const detail::TypeView type = detail::type_at(schema_, field.type);
    const detail::TypeView number =
        type.kind == Kind::Enum ? detail::type_at(schema_, type.element) : type;
    double v = 0;
    if (number.kind == Kind::Float) {
      if (number.size == 4) {
        float f;
        std::memcpy(&f, p, 4);
        v = f;
      } else {
        std::memcpy(&v, p, 8);
      }
    } else if (number.kind == Kind::Int || number.kind == Kind::UInt || number.kind == Kind::Bool) {
      std::uint64_t raw = 0;
      std::memcpy(&raw, p, number.size);
      if (number.kind == Kind::Int && number.size < 8) {
        raw = detail::bits_at(raw, 0, 8 * number.size, true);  // sign-extended
      }
      // Built for size, compared as a double: exact because symcr-gen refuses, under the device
      // profile, a 64-bit integer's bound of 2^53 or more in magnitude (the exact comparison takes
      // 400 bytes of Thumb code).
      if (detail::kBuiltForSize) {
        v = number.kind == Kind::Int ? static_cast<double>(static_cast<std::int64_t>(raw))
                                     : static_cast<double>(raw);
      } else {
        return format::integer_in_range(raw, number.kind == Kind::Int, field.range->min,
                                        field.range->max);
      }
    } else {
      return true;  // a range on anything else is not the generator's
    }
    return v == v && v >= field.range->min && v <= field.range->max;  // NaN is outside
  }

  const Schema& schema_;
  const std::uint8_t* payload_;
  std::size_t size_;
  std::uint8_t* stage_;
  bool as_host_;  // detail::restore_held_payload
  std::size_t at_ = 0;
  std::size_t references_ = 0;
  std::uint32_t reference_count_ = 0;
  std::size_t references_end_ = 0;  // where the clock readings begin (or the payload ends)
  std::uint64_t deltas_[kMaxClocks] = {};
};

// The record's header checked against this build; the payload's bounds in `*payload`, the
// record's sequence in `*sequence`.
// `*planned`: the plan of the record's previous build, or null for this build's own record.
Result check_record(const Build& build, const std::uint8_t* bytes, std::size_t size,
                    std::size_t* payload_offset, std::size_t* payload_size, std::uint64_t* sequence,
                    const PlannedSchema** planned) {
  format::RecordHeader h;
  const format::HeaderFault fault = format::decode_record_header(bytes, size, &h);
  if (fault == format::HeaderFault::FutureVersion) return Result::FutureVersion;
  // Too short for a header, whatever its first bytes: truncated; else not a valid record.
  if (fault != format::HeaderFault::None) {
    return size < format::kRecordHeaderSize ? Result::Truncated : Result::Corrupt;
  }
  const std::uint64_t record = format::claimed_record_size(h);
  if (record > size) return Result::Truncated;
  const std::uint32_t crc =
      format::record_checksum(bytes, static_cast<std::size_t>(record), format::crc32c_extend_small);
  if (crc != h.checksum) return Result::Corrupt;
  if ((h.flags & ~format::kRecordSchemaInline) != 0) return Result::Corrupt;
  if (((h.flags & format::kRecordSchemaInline) != 0) != (h.schema_size != 0)) {
    return Result::Corrupt;
  }
  // An inline schema (a host's single-file checkpoint) must be the one its hash names.
  if (h.schema_size != 0 &&
      format::fnv1a64(bytes + h.header_size, h.schema_size) != h.schema_hash) {
    return Result::Corrupt;
  }
  const std::uint64_t schema_hash = h.schema_hash;
  *planned = nullptr;
  if (schema_hash != build.schema_hash) {
    if (detail::plan_for_writer != nullptr) *planned = detail::plan_for_writer(build, schema_hash);
    if (*planned == nullptr) return Result::OtherSchema;
  }
  const std::uint32_t reader = format::program_id(build.schema->program);
  if (h.program_id != 0 && reader != 0 && h.program_id != reader) return Result::OtherProgram;
  *payload_offset = std::size_t{h.header_size} + h.schema_size;  // an inline schema: skipped
  *payload_size = h.payload_size;
  *sequence = h.sequence;
  return Result::Ok;
}

// Writes held_steps(): the walk of Restorer::value() over a schema's types, with no payload.
class StepWriter {
 public:
  StepWriter(const Schema& schema, detail::HeldStep* steps, std::size_t capacity)
      : schema_(schema), steps_(steps), capacity_(capacity) {}

  // The values of type `t` staged at `stage`. Stops once the steps pass `limit`. Run once per
  // schema, at open: built small rather than fast.
  __attribute__((cold, noinline)) void walk(std::uint32_t t, std::size_t stage, std::size_t limit) {
    if (count_ > limit) return;
    const TypeInfo& type = schema_.types[t];
    switch (type.kind) {
      case Kind::Bool:
      case Kind::Pointer:
        push(detail::HeldStep{stage, 0, t, kNoType});
        return;
      case Kind::Array: {
        const TypeInfo& element = schema_.types[type.element];
        if (is_bytes(element.kind)) {
          copy(stage, std::size_t{element.size} * type.count);
          return;
        }
        for (std::size_t i = 0; i < type.count && count_ <= limit; ++i) {
          walk(type.element, stage + i * element.size, limit);
        }
        return;
      }
      case Kind::Struct:
        for (std::uint32_t f = 0; f < type.field_count; ++f) {
          const FieldInfo& field = type.fields[f];
          if (field.bit_width != 0 || (field.flags & kFieldHasRange) != 0) {
            push(detail::HeldStep{stage, 0, t, f});
          } else {
            walk(field.type, stage + field.offset, limit);
          }
        }
        return;
      default:  // Int, UInt, Enum, Float, Union: their bytes
        copy(stage, type.size);
    }
  }
  // The steps the walk took, of which the first `capacity` are written.
  std::size_t count() const { return count_; }

 private:
  // Bytes next in both the wire and the stage extend the copy before them.
  void copy(std::size_t stage, std::size_t size) {
    if (size == 0) return;
    if (count_ != 0 && last_.type == kNoType && last_.stage + last_.size == stage) {
      last_.size += size;
      if (count_ <= capacity_) steps_[count_ - 1] = last_;
      return;
    }
    push(detail::HeldStep{stage, size, kNoType, kNoType});
  }
  void push(const detail::HeldStep& step) {
    last_ = step;
    if (count_ < capacity_) steps_[count_] = step;
    ++count_;
  }

  const Schema& schema_;
  detail::HeldStep* steps_;
  std::size_t capacity_;
  std::size_t count_ = 0;
  detail::HeldStep last_{};
};

}  // namespace

std::size_t detail::held_steps(const Schema& schema, HeldStep* steps, std::size_t capacity,
                               std::size_t limit) {
  if (schema.types == nullptr || clock_count(schema) != 0) return 0;
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    if (schema.types[t].validate != nullptr) return 0;
  }
  StepWriter writer(schema, steps, capacity);
  std::size_t stage = 0;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    writer.walk(schema.roots[r].type, stage, limit);
    stage += stage_size(root_size(schema, r));
  }
  return writer.count();
}

Result restore_payload(const Schema& schema, const std::uint8_t* payload, std::size_t size,
                       std::uint8_t* scratch, std::size_t scratch_capacity) {
  if (detail::first_unheld_type(schema) != kNoType) return Result::Unsupported;
  return detail::restore_held_payload(schema, payload, size, scratch, scratch_capacity);
}

Result detail::restore_held_payload(const Schema& schema, const std::uint8_t* payload,
                                    std::size_t size, std::uint8_t* scratch,
                                    std::size_t scratch_capacity, const PayloadShape* shape,
                                    bool as_host) {
  if (payload == nullptr && size != 0) return Result::Corrupt;
  if (scratch == nullptr || scratch_capacity < scratch_size(schema)) return Result::NoSpace;
  const std::uintptr_t misalignment =
      reinterpret_cast<std::uintptr_t>(scratch) % detail::kStageAlign;
  std::uint8_t* stage = scratch + (misalignment ? detail::kStageAlign - misalignment : 0);
  const Result result = Restorer(schema, payload, size, stage, as_host).run(shape);
  if (result != Result::Ok) return result;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    const std::size_t root_size = detail::root_size(schema, r);
    std::memcpy(schema.roots[r].address, stage, root_size);
    stage += detail::stage_size(root_size);
  }
  return Result::Ok;
}

Result restore(const Build& build, const std::uint8_t* bytes, std::size_t size,
               std::uint8_t* scratch, std::size_t scratch_capacity, std::uint64_t* sequence) {
  if (build.schema == nullptr || bytes == nullptr) return Result::Unsupported;
  const Schema& schema = *build.schema;
  if (detail::first_unheld_type(schema) != kNoType) return Result::Unsupported;
  if (scratch == nullptr || scratch_capacity < scratch_size(schema)) return Result::NoSpace;
  std::size_t payload = 0, payload_size = 0;
  std::uint64_t record_sequence = 0;
  const PlannedSchema* planned = nullptr;
  Result result =
      check_record(build, bytes, size, &payload, &payload_size, &record_sequence, &planned);
  if (result != Result::Ok) return result;
  result = planned != nullptr
               ? detail::restore_planned_payload(schema, *planned, bytes + payload, payload_size,
                                                 scratch, scratch_capacity)
               : detail::restore_held_payload(schema, bytes + payload, payload_size, scratch,
                                              scratch_capacity);
  if (result == Result::Ok && sequence != nullptr) *sequence = record_sequence;
  return result;
}

}  // namespace device
}  // namespace symcr
