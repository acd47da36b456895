// The device profile's cross-version restore: a record of a previous build restored through the
// plan image symcr-gen embedded for it (device_plan.hpp). Table-driven, no heap, no names: the
// image's ops move each of the writer's values into a staged copy of the reader's roots,
// converting, range-checking, mapping enums and rebasing times; references are followed by
// their writer path translated to the reader's. Any failure refuses the whole checkpoint.
#include "device_plan.hpp"

#include <cstring>

#include "device_format.hpp"

namespace symcr {
namespace device {
namespace {

using format::load16;
using format::load32;
using format::load64;
namespace p = plan;
constexpr double kFloatMax = 3.40282346638528859811704183484516925440e+38;

class PlanRunner {
 public:
  PlanRunner(const Schema& reader, const std::uint8_t* image, std::size_t image_size,
             const std::uint8_t* payload, std::size_t payload_size, std::uint8_t* stage,
             bool as_host)
      : reader_(reader),
        image_(image),
        image_size_(image_size),
        payload_(payload),
        payload_size_(payload_size),
        stage_(stage),
        as_host_(as_host) {}

  Result run() {
    Result result = read_image();
    if (result != Result::Ok) return result;
    result = read_trailer();
    if (result != Result::Ok) return result;
    result = ops(0, op_count_, 0, 0, 0);
    // A host's general decoder checks every reference, used or not: one no pointer used goes
    // that way (a writer saves only references its pointers use).
    if (result == Result::Ok && as_host_ && used_references_ != reference_count_) {
      return Result::Rejected;
    }
    return result;
  }

 private:
  // The header and the bounds of the ops, table and path tables, checked against the image.
  Result read_image() {
    if (image_size_ < p::kPlanHeaderSize) return Result::Corrupt;
    op_count_ = load16(image_ + 6);
    values_ = load32(image_ + 24);
    writer_clocks_ = load16(image_ + 28);
    table_count_ = load16(image_ + 30);
    writer_roots_ = load16(image_ + 32);
    writer_types_ = load16(image_ + 34);
    path_fields_ = load32(image_ + 36);
    ops_ = image_ + p::kPlanHeaderSize;
    table_ = ops_ + op_count_ * p::kOpSize;
    paths_ = table_ + table_count_ * std::size_t{8};
    const std::size_t paths =
        (std::size_t{writer_roots_} + writer_types_ + path_fields_) * p::kPathEntrySize;
    if (path_fields_ > image_size_ || writer_clocks_ > kMaxClocks ||
        static_cast<std::size_t>(paths_ - image_) + paths != image_size_) {
      return Result::Corrupt;
    }
    return Result::Ok;
  }

  // After the values: no heap objects, the reference table (each reference well-formed), and
  // the writer's clock readings ending the payload.
  Result read_trailer() {
    const std::size_t readings = format::clock_readings_size(writer_clocks_);
    const std::size_t counts = format::kHeapCountSize + format::kReferenceCountSize;
    if (payload_size_ < values_ + counts + readings) return Result::Truncated;
    if (load32(payload_ + values_) != 0) return Result::Corrupt;
    reference_count_ = load32(payload_ + values_ + format::kHeapCountSize);
    references_ = values_ + counts;
    references_end_ = payload_size_ - readings;
    std::size_t at = references_;
    for (std::uint32_t i = 0; i < reference_count_; ++i) {
      if (references_end_ - at < format::kObjectReferenceStepsOffset) return Result::Corrupt;
      const std::size_t steps = load16(payload_ + at + format::kObjectReferenceStepCountOffset);
      if (steps > kMaxPathSteps || references_end_ - at < format::object_reference_size(steps)) {
        return Result::Corrupt;
      }
      at += format::object_reference_size(steps);
    }
    return at == references_end_ ? Result::Ok : Result::Corrupt;
  }

  std::uint64_t entry(std::size_t index) const { return load64(table_ + 8 * index); }
  bool has_entries(std::size_t index, std::size_t n) const {
    return index <= table_count_ && n <= table_count_ - index;
  }

  // Runs ops [first, end) with the given bases; `depth` loops enclose them.
  Result ops(std::size_t first, std::size_t end, std::size_t wire_base, std::size_t dst_base,
             std::size_t depth) {
    for (std::size_t i = first; i < end; ++i) {
      const std::uint8_t* op = ops_ + i * p::kOpSize;
      const std::uint8_t code = op[0], a = op[1];
      const std::uint16_t b = load16(op + 2);
      const std::size_t wire = wire_base + load32(op + 4);
      const std::size_t dst = dst_base + load32(op + 8);
      Result result = Result::Ok;
      switch (code) {
        case p::kOpRoot:
          result = root(load32(op + 8), &dst_base);
          wire_base = 0;
          break;
        case p::kOpCopy:
          if (!fits(wire, b, dst, b)) return Result::Corrupt;
          std::memcpy(stage_root_ + dst, payload_ + wire, b);
          break;
        case p::kOpScalar:
          result = scalar(a, b, wire, dst);
          break;
        case p::kOpPointer:
          result = pointer(b, wire, dst);
          break;
        case p::kOpTime:
          result = time(a, b, dst);
          break;
        case p::kOpValidate: {
          if (!has_entries(b, 1) || entry(b) >= reader_.type_count || stage_root_ == nullptr) {
            return Result::Corrupt;
          }
          const detail::TypeView type =
              detail::type_at(reader_, static_cast<std::uint32_t>(entry(b)));
          if (dst > root_size_ || type.size > root_size_ - dst) return Result::Corrupt;
          if (type.validate != nullptr && !type.validate(stage_root_ + dst)) {
            return Result::Rejected;
          }
          break;
        }
        case p::kOpLoop: {
          if (depth >= p::kMaxLoopDepth || !has_entries(b, 2)) return Result::Corrupt;
          const std::uint64_t count = entry(b) & 0xFFFFFFFFu, body = entry(b) >> 32;
          const std::uint64_t wire_stride = entry(b + 1) & 0xFFFFFFFFu;
          const std::uint64_t dst_stride = entry(b + 1) >> 32;
          if (body > end - i - 1) return Result::Corrupt;
          // Every element's offsets stay inside: the last element's base bounds them all. Each
          // writer element takes wire bytes, so a loop never runs longer than the values.
          if (count != 0 && (wire_stride == 0 || wire > values_ || dst > root_size_ ||
                             count - 1 > (values_ - wire) / wire_stride ||
                             (dst_stride != 0 && count - 1 > (root_size_ - dst) / dst_stride))) {
            return Result::Corrupt;
          }
          for (std::uint64_t e = 0; e < count; ++e) {
            result =
                ops(i + 1, i + 1 + body, wire + e * wire_stride, dst + e * dst_stride, depth + 1);
            if (result != Result::Ok) return result;
          }
          i += body;
          break;
        }
        default:
          return Result::Corrupt;
      }
      if (result != Result::Ok) return result;
    }
    return Result::Ok;
  }

  // The staged copy of reader root `index` (the roots are staged in order, each aligned).
  Result root(std::uint32_t index, std::size_t* dst_base) {
    if (index >= reader_.root_count) return Result::Corrupt;
    std::uint8_t* stage = stage_;
    for (std::uint32_t r = 0; r < index; ++r) {
      stage += detail::stage_size(detail::root_size(reader_, r));
    }
    stage_root_ = stage;
    root_size_ = detail::root_size(reader_, index);
    *dst_base = 0;
    return Result::Ok;
  }

  bool fits(std::size_t wire, std::size_t wire_n, std::size_t dst, std::size_t dst_n) const {
    return stage_root_ != nullptr && wire <= values_ && wire_n <= values_ - wire &&
           dst <= root_size_ && dst_n <= root_size_ - dst;
  }

  // A writer scalar converted into the reader's: widened or narrowed with its range checked,
  // an enum mapped by name (the pairs), a bool kept 0 or 1, a bit-field kept within its width.
  Result scalar(std::uint8_t from, std::uint16_t target_index, std::size_t wire, std::size_t dst) {
    if (!has_entries(target_index, 1)) return Result::Corrupt;
    const std::uint64_t target = entry(target_index);
    const std::size_t from_size = from & 0xF, to_size = target & 0xF;
    const unsigned from_kind = from >> 4, to_kind = (target >> 4) & 0xF;
    const unsigned width = (target >> 8) & 0xFF, bit_offset = (target >> 16) & 0xFF;
    const std::size_t unit = (target >> 24) & 0xFF;
    const std::size_t pairs = (target >> 32) & 0xFFFF;
    const bool ranged = (target & p::kTargetHasRange) != 0;
    const std::size_t stored = width != 0 ? unit : to_size;
    if (from_size == 0 || from_size > 8 || to_size == 0 || to_size > 8 || stored > 8 ||
        (width != 0 && (width > 64 || bit_offset + width > 8 * unit)) ||
        !has_entries(target_index + 1, (ranged ? 2 : 0) + 2 * pairs) ||
        !fits(wire, from_size, dst, stored)) {
      return Result::Corrupt;
    }
    // The writer's value: an integer (as its 64 bits, sign-extended) or a double.
    std::uint64_t raw = 0;
    std::memcpy(&raw, payload_ + wire, from_size);
    double real = 0;
    const bool from_float = from_kind == p::kFloat;
    if (from_float) {
      if (from_size == 4) {
        float f;
        std::memcpy(&f, &raw, 4);
        real = f;
      } else if (from_size == 8) {
        std::memcpy(&real, &raw, 8);
      } else {
        return Result::Corrupt;
      }
    } else if (from_kind == p::kSigned && from_size < 8 && ((raw >> (8 * from_size - 1)) & 1u)) {
      raw |= ~std::uint64_t{0} << (8 * from_size);
    }
    if (from_kind == p::kBoolean && raw > 1) return Result::Corrupt;
    std::size_t next = target_index + 1 + (ranged ? 2 : 0);
    if (pairs != 0) {  // an enum: its writer value's reader value, by name
      bool mapped = false;
      for (std::size_t e = 0; e < pairs && !mapped; ++e, next += 2) {
        if (entry(next) == raw) {
          raw = entry(next + 1);
          mapped = true;
        }
      }
      if (!mapped) return Result::Rejected;
    }
    bool is_signed = from_kind == p::kSigned || (pairs != 0 && to_kind == p::kSigned);
    const double as_real = from_float  ? real
                           : is_signed ? static_cast<double>(static_cast<std::int64_t>(raw))
                                       : static_cast<double>(raw);
    if (ranged) {
      double low, high;
      const std::uint64_t low_bits = entry(target_index + 1), high_bits = entry(target_index + 2);
      std::memcpy(&low, &low_bits, 8);
      std::memcpy(&high, &high_bits, 8);
      // Built for size, an integer is compared as a double too (see in_range, device_restore).
      const bool inside = from_float || detail::kBuiltForSize
                              ? as_real >= low && as_real <= high  // NaN is outside
                              : format::integer_in_range(raw, is_signed, low, high);
      if (!inside) return Result::Rejected;
    }
    std::uint64_t out = 0;
    if (to_kind == p::kFloat) {
      // An integer must come back exactly; a double narrowed is rounded, within float's range.
      const double value = as_real;
      if (to_size == 4) {
        const float f = static_cast<float>(value);
        if (value == value && (value > kFloatMax || value < -kFloatMax) &&
            value != value * 2) {  // finite, beyond float: not rounded to infinity
          return Result::Rejected;
        }
        if (!from_float && !same_integer(static_cast<double>(f), raw, is_signed)) {
          return Result::Rejected;
        }
        std::memcpy(&out, &f, 4);
      } else if (to_size == 8) {
        if (!from_float && !same_integer(value, raw, is_signed)) return Result::Rejected;
        std::memcpy(&out, &value, 8);
      } else {
        return Result::Corrupt;
      }
    } else {
      if (from_float) {  // to an integer: integral, then checked as one
        if (!(real >= -9223372036854775808.0 && real < 18446744073709551616.0)) {
          return Result::Rejected;
        }
        is_signed = real < 0;
        raw = is_signed ? static_cast<std::uint64_t>(static_cast<std::int64_t>(real))
                        : static_cast<std::uint64_t>(real);
        if (!same_integer(real, raw, is_signed)) return Result::Rejected;
      }
      // The value must survive the reader's integer (or bit-field) width.
      const unsigned bits = width != 0 ? width : static_cast<unsigned>(8 * to_size);
      const bool to_signed = to_kind == p::kSigned;
      if (bits < 64) {
        const std::int64_t value = static_cast<std::int64_t>(raw);
        const bool fits_width =
            to_signed ? (is_signed ? value >= -(std::int64_t{1} << (bits - 1)) &&
                                         value < (std::int64_t{1} << (bits - 1))
                                   : raw < (std::uint64_t{1} << (bits - 1)))
                      : (!is_signed || value >= 0) && raw < (std::uint64_t{1} << bits);
        if (!fits_width) return Result::Rejected;
      } else if (to_signed != is_signed && (raw >> 63) != 0) {
        return Result::Rejected;
      }
      if (to_kind == p::kBoolean && raw > 1) return Result::Rejected;
      out = raw;
    }
    std::uint8_t* at = stage_root_ + dst;
    if (width == 0) {
      std::memcpy(at, &out, to_size);
      return Result::Ok;
    }
    const std::uint64_t mask = width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
    std::uint64_t bits = 0;
    std::memcpy(&bits, at, unit);
    bits = (bits & ~(mask << bit_offset)) | ((out & mask) << bit_offset);
    std::memcpy(at, &bits, unit);
    return Result::Ok;
  }

  // Whether `value` is exactly the integer `raw` (signed or not).
  static bool same_integer(double value, std::uint64_t raw, bool is_signed) {
    if (is_signed) {
      if (!(value >= -9223372036854775808.0 && value < 9223372036854775808.0)) return false;
      return static_cast<std::int64_t>(value) == static_cast<std::int64_t>(raw) &&
             static_cast<double>(static_cast<std::int64_t>(value)) == value;
    }
    if (!(value >= 0 && value < 18446744073709551616.0)) return false;
    return static_cast<std::uint64_t>(value) == raw &&
           static_cast<double>(static_cast<std::uint64_t>(value)) == value;
  }

  // A pointer: null, outside the roots (the running build's value stays), or a reference whose
  // writer path is translated to the reader's and must end at the pointer's reader pointee.
  Result pointer(std::uint16_t pointee_index, std::size_t wire, std::size_t dst) {
    if (!has_entries(pointee_index, 1) ||
        !fits(wire, format::kPointerCodeSize, dst, sizeof(std::uintptr_t))) {
      return Result::Corrupt;
    }
    const std::uint32_t code = load32(payload_ + wire);
    // The running build's value stays; a host reports that, so it takes its general way.
    if (code == format::kOutsideCode) return as_host_ ? Result::Rejected : Result::Ok;
    std::uintptr_t target = 0;
    if (code != format::kNullCode) {
      if (code - format::kFirstReference >= reference_count_) return Result::Corrupt;
      if (as_host_) {
        const std::uint32_t index = code - format::kFirstReference;
        if (index >= 32) return Result::Rejected;  // more than the mask below counts
        const std::uint32_t bit = std::uint32_t{1} << index;
        if ((used_mask_ & bit) == 0) ++used_references_;
        used_mask_ |= bit;
      }
      const Result result =
          reference(code - format::kFirstReference, entry(pointee_index), &target);
      if (result != Result::Ok) return result;
    }
    std::memcpy(stage_root_ + dst, &target, sizeof target);
    return Result::Ok;
  }

  Result reference(std::uint32_t index, std::uint64_t pointee, std::uintptr_t* address) const {
    std::size_t at = references_;
    for (std::uint32_t i = 0; i < index; ++i) {
      at += format::object_reference_size(
          load16(payload_ + at + format::kObjectReferenceStepCountOffset));
    }
    if (payload_[at] != format::kBaseObject) return Result::Corrupt;
    const std::uint32_t writer_root = load32(payload_ + at + format::kReferenceObjectOffset);
    const std::size_t step_count = load16(payload_ + at + format::kObjectReferenceStepCountOffset);
    const std::uint8_t* const steps_at = payload_ + at + format::kObjectReferenceStepsOffset;
    if (writer_root >= writer_roots_) return Result::Corrupt;
    // Each table's entries: two u16, the first at `entry`, the second 2 bytes on.
    const std::uint8_t* roots = paths_;
    const std::uint8_t* types = roots + p::kPathEntrySize * writer_roots_;
    const std::uint8_t* fields = types + p::kPathEntrySize * writer_types_;
    std::uint32_t writer_type = load16(roots + p::kPathEntrySize * writer_root);
    const std::uint32_t reader_root = load16(roots + p::kPathEntrySize * writer_root + 2);
    if (reader_root == p::kNoPathIndex) return Result::Rejected;  // its root was removed
    std::uint32_t steps[kMaxPathSteps];
    for (std::size_t s = 0; s < step_count; ++s) {
      const std::uint32_t step = load32(steps_at + format::kReferenceStepSize * s);
      if (writer_type >= writer_types_) return Result::Corrupt;
      const std::uint32_t kind = load16(types + p::kPathEntrySize * writer_type);
      const std::uint32_t next = load16(types + p::kPathEntrySize * writer_type + 2);
      if ((kind & 3) == p::kPathStruct) {
        if (step >= (kind >> 2) || next > path_fields_ || step >= path_fields_ - next) {
          return Result::Corrupt;
        }
        writer_type = load16(fields + p::kPathEntrySize * (next + step));
        steps[s] = load16(fields + p::kPathEntrySize * (next + step) + 2);
        if (steps[s] == p::kNoPathIndex) return Result::Rejected;  // its member was removed
      } else if ((kind & 3) == p::kPathArray) {
        writer_type = next;
        steps[s] = step;  // an element beyond the reader's count fails the path below
      } else {
        return Result::Corrupt;
      }
    }
    // The writer's type the steps end at is the one the reference names, as the host checks.
    if (load32(steps_at + format::kReferenceStepSize * step_count) != writer_type) {
      return Result::Corrupt;
    }
    std::size_t offset = 0;
    std::uint32_t reached = kNoType;
    if (!detail::follow_path(reader_, reader_root, steps, step_count, &offset, &reached)) {
      return Result::Rejected;  // an element the reader's array no longer has
    }
    if (reached != pointee) return Result::Rejected;
    *address = reinterpret_cast<std::uintptr_t>(reader_.roots[reader_root].address) + offset;
    return Result::Ok;
  }

  // A restored time moved as far as its clock moved since the writer's reading of it.
  Result time(std::uint8_t size, std::uint16_t index, std::size_t dst) {
    if (!has_entries(index, 2) || size == 0 || size > 8 || !fits(0, 0, dst, size)) {
      return Result::Corrupt;
    }
    const std::int64_t never = static_cast<std::int64_t>(entry(index));
    const std::uint32_t writer_clock = static_cast<std::uint32_t>(entry(index + 1) >> 32);
    const std::uint32_t reader_clock = static_cast<std::uint32_t>(entry(index + 1));
    if (writer_clock >= writer_clocks_) return Result::Corrupt;
    const ClockInfo* clock = detail::clock_at(reader_, reader_clock);
    const std::uint64_t saved =
        static_cast<std::uint64_t>(format::clock_reading(payload_ + references_end_, writer_clock));
    const std::uint64_t delta = clock != nullptr && clock->read != nullptr
                                    ? static_cast<std::uint64_t>(clock->read()) - saved
                                    : 0;
    format::rebase_time(stage_root_ + dst, size, never, delta);
    return Result::Ok;
  }

  const Schema& reader_;
  const std::uint8_t* image_;
  std::size_t image_size_;
  const std::uint8_t* payload_;
  std::size_t payload_size_;
  std::uint8_t* stage_;
  const std::uint8_t* ops_ = nullptr;
  const std::uint8_t* table_ = nullptr;
  const std::uint8_t* paths_ = nullptr;
  std::size_t op_count_ = 0, values_ = 0, table_count_ = 0;
  std::uint32_t writer_clocks_ = 0, writer_roots_ = 0, writer_types_ = 0, path_fields_ = 0;
  std::uint8_t* stage_root_ = nullptr;
  std::size_t root_size_ = 0;
  std::uint32_t reference_count_ = 0;
  std::size_t references_ = 0, references_end_ = 0;
  bool as_host_;
  std::uint32_t used_mask_ = 0, used_references_ = 0;  // references pointers used (as_host_)
};

}  // namespace

// What a build's generated code references when it carries plans, so that the linker takes
// this file (the executor) into the firmware; others leave it out.
extern "C" const char symcr_device_plan_executor = 1;

Build::Build(const Schema* own_schema, std::uint64_t own_schema_hash,
             const PlannedSchema* previous_plans, std::uint32_t previous_plan_count)
    : schema(own_schema),
      schema_hash(own_schema_hash),
      plans(previous_plans),
      plan_count(previous_plan_count) {}

const PlannedSchema* detail::plan_for_writer(const Build& build, std::uint64_t writer_hash) {
  for (std::uint32_t i = 0; build.plans != nullptr && i < build.plan_count; ++i) {
    const PlannedSchema& planned = build.plans[i];
    if (planned.writer_hash == writer_hash && planned.image != nullptr &&
        planned.size >= plan::kPlanHeaderSize &&
        std::memcmp(planned.image, plan::kPlanMagic, sizeof plan::kPlanMagic) == 0 &&
        load16(planned.image + 4) == plan::kPlanVersion &&
        load64(planned.image + 8) == writer_hash &&
        load64(planned.image + 16) == build.schema_hash) {
      return &planned;
    }
  }
  return nullptr;
}

Result detail::restore_planned_payload(const Schema& reader, const PlannedSchema& planned,
                                       const std::uint8_t* payload, std::size_t size,
                                       std::uint8_t* scratch, std::size_t scratch_capacity,
                                       bool as_host) {
  if (payload == nullptr && size != 0) return Result::Corrupt;
  if (scratch == nullptr || scratch_capacity < scratch_size(reader)) return Result::NoSpace;
  const std::uintptr_t misalignment =
      reinterpret_cast<std::uintptr_t>(scratch) % detail::kStageAlign;
  std::uint8_t* const first = scratch + (misalignment ? detail::kStageAlign - misalignment : 0);
  // What the record does not hold (a member added since) keeps the running build's value.
  std::uint8_t* stage = first;
  for (std::uint32_t r = 0; r < reader.root_count; ++r) {
    const std::size_t root_size = detail::root_size(reader, r);
    std::memcpy(stage, reader.roots[r].address, root_size);
    stage += detail::stage_size(root_size);
  }
  const Result result =
      PlanRunner(reader, planned.image, planned.size, payload, size, first, as_host).run();
  if (result != Result::Ok) return result;
  stage = first;
  for (std::uint32_t r = 0; r < reader.root_count; ++r) {
    const std::size_t root_size = detail::root_size(reader, r);
    std::memcpy(reader.roots[r].address, stage, root_size);
    stage += detail::stage_size(root_size);
  }
  return Result::Ok;
}

}  // namespace device
}  // namespace symcr
