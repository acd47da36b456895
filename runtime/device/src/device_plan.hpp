// A device plan image: how the device profile restores a checkpoint of a previous build (the
// writer) into this one (the reader), resolved by symcr-gen at build time from the host's plan
// (docs/resolution.md) and executed by the device without a heap or names. Shared by the
// device's executor (device_plan.cpp) and the host's encoder
// (runtime/src/plan/device_plan_encode.cpp).
//
// Layout, little-endian:
//   header (kPlanHeaderSize bytes): magic "SYDP", u16 version, u16 op count, u64 writer hash,
//     u64 reader hash, u32 writer values size, u16 writer clock count, u16 table entries,
//     u16 writer roots, u16 writer types, u32 path fields
//   ops: op count x 12 bytes (Op)
//   table: table entries x 8 bytes (i64, doubles by their bits): what an op needs beyond its 12
//   references by path, present when the writer had pointers (writer roots > 0), u16 pairs:
//     per writer root: writer type, reader root (kNoPathIndex: removed)
//     per writer type: kind (kPathStruct, kPathArray, or 0) | field count << 2, its first path
//       field (struct) or its element type (array)
//     path fields: writer field type, reader field index (kNoPathIndex: removed)
//
// The writer's payload holds fixed-size values only (the device profile's kinds): every value
// the plan reads is at a wire offset known at build time.
#ifndef SYMCR_DEVICE_PLAN_HPP
#define SYMCR_DEVICE_PLAN_HPP

#include <cstddef>
#include <cstdint>

namespace symcr {
namespace device {
namespace plan {

constexpr char kPlanMagic[4] = {'S', 'Y', 'D', 'P'};
constexpr std::uint16_t kPlanVersion = 1;
constexpr std::size_t kPlanHeaderSize = 40;
constexpr std::size_t kOpSize = 12;
constexpr std::uint32_t kNone = 0xFFFFFFFFu;
// Loops nest at most this deep (arrays of arrays of structs...).
constexpr std::size_t kMaxLoopDepth = 8;

// An op: code, a, b, wire (offset in the writer's values, from the loop's base), dst (offset in
// the reader root's staged copy, from the loop's base).
enum OpCode : std::uint8_t {
  kOpRoot = 1,      // dst: reader root; bases reset to its staged copy and the values' start
  kOpCopy = 2,      // b: bytes copied as they are
  kOpScalar = 3,    // a: writer scalar (scalar()); b: table index of the reader's side
  kOpPointer = 4,   // b: table index of the reader pointee type
  kOpTime = 5,      // a: the time's bytes; b: table index of never, (writer, reader clock)
  kOpValidate = 6,  // b: table index of the reader type whose validator judges the value at dst
  kOpLoop = 7,      // b: table index of (count, body ops), then (wire stride, dst stride)
};

// A scalar's representation: size in bytes (1-8) in the low nibble, its kind above.
enum ScalarKind : std::uint8_t { kUnsigned = 0, kSigned = 1, kFloat = 2, kBoolean = 3 };
inline std::uint8_t scalar(ScalarKind kind, unsigned size) {
  return static_cast<std::uint8_t>(kind << 4 | size);
}

// The reader's side of a kOpScalar, in its table entry: bits 0-7 the scalar (as above), 8-15 a
// bit-field's width (0: none), 16-23 its bit offset, 24-31 its storage unit's bytes, 32-47 the
// number of enum pairs that follow, bit 48 a range follows (min, max as doubles) before them.
// The enum pairs are (writer value, reader value): a writer value not among them is refused.
constexpr std::uint64_t kTargetHasRange = std::uint64_t{1} << 48;

// Path kinds of writer types (references by path), in a type entry's low two bits.
constexpr std::uint16_t kPathStruct = 1, kPathArray = 2;
constexpr std::uint16_t kNoPathIndex = 0xFFFF;
constexpr std::size_t kPathEntrySize = 4;

}  // namespace plan
}  // namespace device
}  // namespace symcr

#endif  // SYMCR_DEVICE_PLAN_HPP
