// What the device profile's save and restore share: the record header's fields (docs/format.md
// §1), CRC-32C, little-endian bytes, each type's fixed wire size, and where the roots' staged
// copies lie in the scratch. Internal to the device profile.
#ifndef SYMCR_DEVICE_FORMAT_HPP
#define SYMCR_DEVICE_FORMAT_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/device.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the device profile copies values in memory order: a little-endian target is required"
#endif

namespace symcr {
namespace device {
namespace detail {

// Record header (docs/format.md §1).
constexpr std::size_t kHeaderSize = 56;
constexpr std::uint16_t kFormatVersion = 1;
constexpr std::size_t kOffsetVersion = 8, kOffsetHeaderSize = 10, kOffsetFlags = 12,
                      kOffsetSequence = 16, kOffsetSchemaHash = 32, kOffsetSchemaSize = 40,
                      kOffsetPayloadSize = 44, kOffsetChecksum = 48, kOffsetProgramId = 52;
constexpr std::uint32_t kFlagInlineSchema = 1;
extern const char kMagic[8];

// Pointer codes and reference bases of the payload (docs/format.md §3).
constexpr std::uint32_t kNullCode = 0, kOutsideCode = 1, kFirstReference = 2;
constexpr std::uint8_t kBaseObject = 0;

std::uint32_t crc32c(std::uint32_t crc, const std::uint8_t* data, std::size_t size);
std::uint32_t program_id(const char* program);  // FNV-1a 32, never 0; 0 for no name
std::uint64_t fnv1a64(const std::uint8_t* data, std::size_t size);  // the schema hash

inline void store16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void store32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline void store64(std::uint8_t* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline std::uint16_t load16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t load32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline std::uint64_t load64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

// Moves the time held in the `size`-byte little-endian integer at `p` by `delta`, in the
// integer's own wrapping arithmetic (a 32-bit millisecond time wraps as the program expects),
// unless it holds `never` (compared in the same width). Both runtimes rebase with it.
inline void rebase_time(std::uint8_t* p, std::size_t size, std::int64_t never,
                        std::uint64_t delta) {
  std::uint64_t value = 0;
  for (std::size_t i = size; i-- > 0;) value = (value << 8) | p[i];
  const std::uint64_t mask =
      size >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * size)) - 1;
  if (value == (static_cast<std::uint64_t>(never) & mask)) return;
  value = (value + delta) & mask;
  for (std::size_t i = 0; i < size; ++i) p[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

// The first type reachable from the roots that the device profile cannot hold, or kNoType.
std::uint32_t first_unheld_type(const Schema& schema);
// Bytes `type` takes in the payload (fixed: the profile has no variable-length kind), and the
// bytes of all roots' values. Only for schemas first_unheld_type() accepts.
std::size_t wire_size(const Schema& schema, std::uint32_t type);
std::size_t values_size(const Schema& schema);
// restore_payload() for a schema first_unheld_type() already accepted (the host checks that
// once per schema, not once per restore).
Result restore_held_payload(const Schema& schema, const std::uint8_t* payload, std::size_t size,
                            std::uint8_t* scratch, std::size_t scratch_capacity);
// The cross-version executor (device_plan.cpp), weak: null unless the firmware links it (see
// Build). The plan image `build` embeds for checkpoints of the build whose schema hashes to
// `writer_hash` (device_plan.hpp), or null.
const PlannedSchema* plan_for_writer(const Build& build, std::uint64_t writer_hash)
    __attribute__((weak));
// restore_held_payload() for a payload of the plan's writer: each value through the plan.
Result restore_planned_payload(const Schema& reader, const PlannedSchema& planned,
                               const std::uint8_t* payload, std::size_t size,
                               std::uint8_t* scratch, std::size_t scratch_capacity)
    __attribute__((weak));
// The clocks the schema's time fields name (kFieldClockTime): their count (one more than the
// greatest ClockInfo::index), and the clock of an index (null when no field names it). A
// payload of a schema with clocks ends with an epoch and one reading per clock (format §3).
std::uint32_t clock_count(const Schema& schema);
const ClockInfo* clock_at(const Schema& schema, std::uint32_t index);
inline std::size_t clock_readings_size(std::uint32_t clocks) {
  return clocks != 0 ? 8 + 8 * std::size_t{clocks} : 0;
}
// Pointers among the values of `type` (each may need a reference).
std::size_t pointer_count(const Schema& schema, std::uint32_t type);
// The most bytes one reference takes: base, object, step count, steps, target type.
constexpr std::size_t kMaxReferenceSize = 1 + 4 + 2 + 4 * kMaxPathSteps + 4;

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
