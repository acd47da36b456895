// What the device profile's save and restore share besides the format core (runtime/format):
// which schemas it holds, each type's fixed wire size, the schema's clocks, and where the roots'
// staged copies lie in the scratch. Internal to the device profile.
#ifndef SYMCR_DEVICE_FORMAT_HPP
#define SYMCR_DEVICE_FORMAT_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/device.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/format/payload.hpp"
#include "symcr/format/record.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the device profile copies values in memory order: a little-endian target is required"
#endif

namespace symcr {
namespace device {
namespace detail {

// What the device reads of a type and of a field, from a schema's TypeInfo tables or from a
// DeviceSchema's compact ones (generated.hpp) alike: every read of the tables goes through
// type_at() and field_at().
struct TypeView {
  Kind kind;
  std::uint32_t size;
  std::uint32_t element;       // Enum, Array, Pointer; else kNoType
  std::size_t count;           // Array (first_unheld_type() refuses a count beyond std::size_t)
  std::uint32_t field_count;   // Struct: its fields...
  std::uint32_t member_count;  // ...and after them its reference members (a pointer's targets)
  bool (*validate)(const void* object);
};
struct FieldView {
  std::uint32_t type;
  std::uint32_t offset;
  std::uint32_t bit_offset;
  std::uint32_t bit_width;  // 0: not a bit-field
  const FieldRange* range;  // its SYMCR_RANGE, or null
  const FieldTime* time;    // the clock of its times, or null
};
// The compact tables `schema` heads, or null for TypeInfo tables.
inline const DeviceSchema* compact(const Schema& schema) {
  return schema.types == nullptr && schema.type_count != 0
             ? reinterpret_cast<const DeviceSchema*>(&schema)
             : nullptr;
}
static_assert(offsetof(DeviceSchema, schema) == 0, "a DeviceSchema begins with its Schema");

// Built for size (-Os, a microcontroller's flash) the decoder keeps one copy of each step;
// built for speed it inlines the two accessors below, so that a walk reads only the members it
// uses, and takes shortcuts for plain numbers: a host's first restore in a fresh process walks
// every field, and the calls were most of its instructions. Both builds are tested (the
// Cortex-M4 tests at -Os, the host's at -O2).
#if defined(__OPTIMIZE_SIZE__)
constexpr bool kBuiltForSize = true;
#define SYMCR_DEVICE_ACCESSOR inline __attribute__((noinline))
#else
constexpr bool kBuiltForSize = false;
#define SYMCR_DEVICE_ACCESSOR inline __attribute__((always_inline))
#endif

// `t` < schema.type_count; `f` < type_at(schema, t).member_count.
SYMCR_DEVICE_ACCESSOR TypeView type_at(const Schema& schema, std::uint32_t t) {
  TypeView view;
  if (const DeviceSchema* device = compact(schema)) {
    const DeviceTypeInfo& type = device->types[t];
    view.kind = static_cast<Kind>(type.kind);
    view.size = type.size;
    const bool is_struct = view.kind == Kind::Struct;
    view.element = is_struct || type.element == kDeviceNoType ? kNoType : type.element;
    view.count = is_struct ? 0 : type.count;
    view.field_count = is_struct ? type.count & 0xFFFFu : 0;
    view.member_count = view.field_count + (is_struct ? type.count >> 16 : 0);
    view.validate = type.validator != 0 ? device->validators[type.validator - 1] : nullptr;
    return view;
  }
  const TypeInfo& type = schema.types[t];
  view.kind = type.kind;
  view.size = type.size;
  view.element = type.element;
  view.count = type.count;
  view.field_count = type.field_count;
  view.member_count = type.field_count + type.reference_member_count;
  view.validate = type.validate;
  return view;
}

SYMCR_DEVICE_ACCESSOR FieldView field_at(const Schema& schema, std::uint32_t t, std::uint32_t f) {
  FieldView view;
  if (const DeviceSchema* device = compact(schema)) {
    const std::uint32_t index = device->types[t].first_field + f;
    view.type = device->field_types[index];
    view.offset = device->field_offsets[index];
    view.bit_offset = 0;
    view.bit_width = 0;
    view.range = nullptr;
    view.time = nullptr;
    for (std::uint32_t i = 0; i < device->bit_field_count; ++i) {
      if (device->bit_fields[i].field == index) {
        view.bit_offset = device->bit_fields[i].bit_offset;
        view.bit_width = device->bit_fields[i].bit_width;
      }
    }
    for (std::uint32_t i = 0; i < device->range_count; ++i) {
      if (device->ranges[i].field == index) view.range = &device->ranges[i].range;
    }
    for (std::uint32_t i = 0; i < device->time_count; ++i) {
      if (device->times[i].field == index && device->times[i].time.clock != nullptr) {
        view.time = &device->times[i].time;
      }
    }
    return view;
  }
  const TypeInfo& type = schema.types[t];
  const FieldInfo& field =
      f < type.field_count ? type.fields[f] : type.reference_members[f - type.field_count];
  view.type = field.type;
  view.offset = field.offset;
  view.bit_offset = field.bit_offset;
  view.bit_width = field.bit_width;
  view.range = (field.flags & kFieldHasRange) ? field.range : nullptr;
  view.time = format::field_clock(field) != nullptr ? field.time : nullptr;
  return view;
}
inline std::uint32_t root_size(const Schema& schema, std::uint32_t root) {
  return type_at(schema, schema.roots[root].type).size;
}

// The first type reachable from the roots that the device profile cannot hold, or kNoType.
std::uint32_t first_unheld_type(const Schema& schema);
// Bytes `type` takes in the payload (fixed: the profile has no variable-length kind), and the
// bytes of all roots' values. Only for schemas first_unheld_type() accepts.
std::size_t wire_size(const Schema& schema, std::uint32_t type);
std::size_t values_size(const Schema& schema);
struct HeldStep;
// What every payload of a schema holds before and after its reference table: the values'
// bytes (values_size()) and the clocks whose readings end it (clock_count()); and, kept by a
// host that wrote them, the steps of the walk over its values (held_steps()).
struct PayloadShape {
  std::size_t values;
  std::uint32_t clocks;
  const HeldStep* steps;  // null: the decoder walks the types itself
  std::size_t step_count;
};
PayloadShape payload_shape(const Schema& schema);
// One step of the walk of a schema's values, from the first value to the last, as the decoder
// takes it: `size` wire bytes copied to `stage` (the offset in the roots' staged copies, each
// stage_size() apart) when `type` is kNoType; else a value of `type` staged at `stage` decoded
// on its own (a bool, a pointer); else, `field` not kNoType, that field of the struct `type`
// staged at `stage` (a bit-field, or a field with a range). A host's first restore in a fresh
// process runs the steps a store's open wrote: most values are runs of bytes, and a walk
// decoding each of them cost that restore most of its instructions.
struct HeldStep {
  std::size_t stage;
  std::size_t size;
  std::uint32_t type;
  std::uint32_t field;
};
// Writes the first `capacity` steps of `schema` (its TypeInfo tables) into `steps`, returning
// how many there are; once they pass `limit`, some more than `limit` without counting further.
// 0 when the schema has a validator or a clock, which the steps do not take: its walk runs
// itself.
std::size_t held_steps(const Schema& schema, HeldStep* steps, std::size_t capacity,
                       std::size_t limit);
// restore_payload() for a schema first_unheld_type() already accepted. `shape`: its
// payload_shape(), found once per schema by a host, or null to find it here. `as_host`: refuse
// (Rejected) a pointer to something outside the roots, which a host's general decoder restores
// and reports as kept.
Result restore_held_payload(const Schema& schema, const std::uint8_t* payload, std::size_t size,
                            std::uint8_t* scratch, std::size_t scratch_capacity,
                            const PayloadShape* shape = nullptr, bool as_host = false);
// The cross-version executor (device_plan.cpp), weak: null unless the firmware links it (see
// Build). The plan image `build` embeds for checkpoints of the build whose schema hashes to
// `writer_hash` (device_plan.hpp), or null.
const PlannedSchema* plan_for_writer(const Build& build, std::uint64_t writer_hash)
    __attribute__((weak));
// restore_held_payload() for a payload of the plan's writer: each value through the plan.
// `as_host` also refuses a reference no pointer used, which a host's general decoder checks.
Result restore_planned_payload(const Schema& reader, const PlannedSchema& planned,
                               const std::uint8_t* payload, std::size_t size, std::uint8_t* scratch,
                               std::size_t scratch_capacity, bool as_host = false)
    __attribute__((weak));
// The clocks the schema's time fields name (kFieldClockTime): their count (one more than the
// greatest ClockInfo::index), and the clock of an index (null when no field names it). A
// payload of a schema with clocks ends with an epoch and one reading per clock (format §3).
std::uint32_t clock_count(const Schema& schema);
const ClockInfo* clock_at(const Schema& schema, std::uint32_t index);
// Pointers among the values of `type` (each may need a reference).
std::size_t pointer_count(const Schema& schema, std::uint32_t type);
// The most bytes one reference takes: base, object, step count, steps, target type.
constexpr std::size_t kMaxReferenceSize = format::kObjectReferenceStepsOffset +
                                          format::kReferenceStepSize * kMaxPathSteps +
                                          format::kReferenceTargetSize;

// The `width` bits (1 to 64) of `raw` from bit `offset` (offset + width at most 64), zero- or,
// when `is_signed`, sign-extended to 64 bits. Out of line: each 64-bit shift by a variable count
// is a dozen instructions on a Cortex-M4, and bit-fields, ranges and wire values all need them.
std::uint64_t bits_at(std::uint64_t raw, unsigned offset, unsigned width, bool is_signed);

// Staged copies of the roots in the scratch: each at a multiple of kStageAlign.
constexpr std::size_t kStageAlign = 16;
inline std::size_t stage_size(std::size_t size) {
  return (size + kStageAlign - 1) / kStageAlign * kStageAlign;
}

// Where the value of a reference's path lies: from root `root`'s start, `steps` through
// fields and array elements; the type reached in `*type`. False if a step leaves its type.
bool follow_path(const Schema& schema, std::uint32_t root, const std::uint32_t* steps,
                 std::size_t step_count, std::size_t* offset, std::uint32_t* type);

}  // namespace detail
}  // namespace device
}  // namespace symcr

#endif  // SYMCR_DEVICE_FORMAT_HPP
