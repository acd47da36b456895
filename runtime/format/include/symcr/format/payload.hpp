// The payload's codes and fixed sizes (docs/format.md §3), written once: the pointer codes, the
// reference layout, the prefixes of variable values, the wire-size rule, the clock readings
// that end a payload and the rebasing of times. How a payload is walked and checked is each
// runtime's (the host's payload_grammar.hpp, the device's decoders); what the bytes mean is
// here.
#ifndef SYMCR_FORMAT_PAYLOAD_HPP
#define SYMCR_FORMAT_PAYLOAD_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "symcr/format/bytes.hpp"
#include "symcr/generated.hpp"

namespace symcr {
namespace format {

// A Pointer's or SharedPtr's u32 code: null, outside the saved state (raw pointers only), or
// kFirstReference + the index of its target in the reference table.
constexpr std::uint32_t kNullCode = 0;
constexpr std::uint32_t kOutsideCode = 1;
constexpr std::uint32_t kFirstReference = 2;

// A Variant's u32 alternative index for a variant saved valueless.
constexpr std::uint32_t kValuelessIndex = 0xFFFFFFFFu;
static_assert(kValuelessIndex == kNoType, "decoders compare the index with kNoType");

// Bytes of the prefixes: a String's length and a Container's count, a Variant's index, an
// Optional's or UniquePtr's presence flag (0 or 1), a pointer's code.
constexpr std::uint32_t kCountSize = 4;
constexpr std::uint32_t kVariantIndexSize = 4;
constexpr std::uint32_t kPresenceSize = 1;
constexpr std::uint32_t kPointerCodeSize = 4;
constexpr std::uint32_t kBoolSize = 1;

// After the root values: u32 heap_count and the heap objects (each u32 type, u8 owner, value),
// then u32 ref_count and the references.
constexpr std::size_t kHeapCountSize = 4;
constexpr std::size_t kReferenceCountSize = 4;
constexpr std::uint8_t kHeapOwnerRaw = 0, kHeapOwnerShared = 1;

// A reference: u8 base, then for kBaseObject u32 object, for kBaseElement u32 container ordinal
// and u32 element index; u16 step_count, step_count u32 steps, u32 target type.
enum ReferenceBase : std::uint8_t { kBaseObject = 0, kBaseElement = 1 };
constexpr std::size_t kReferenceObjectOffset = 1;
constexpr std::size_t kObjectReferenceStepCountOffset = 5;  // after base and object
constexpr std::size_t kObjectReferenceStepsOffset = 7;
constexpr std::size_t kReferenceStepSize = 4;
constexpr std::size_t kReferenceTargetSize = 4;
// The bytes of an object reference (kBaseObject) of `steps` steps.
inline std::size_t object_reference_size(std::size_t steps) {
  return kObjectReferenceStepsOffset + kReferenceStepSize * steps + kReferenceTargetSize;
}

static_assert(kNullCode == 0 && kOutsideCode == 1 && kFirstReference == 2,
              "pointer codes of docs/format.md §3");
static_assert(kBaseObject == 0 && kBaseElement == 1, "reference bases of docs/format.md §3");
static_assert(kObjectReferenceStepCountOffset == kReferenceObjectOffset + 4 &&
                  kObjectReferenceStepsOffset == kObjectReferenceStepCountOffset + 2,
              "u8 base, u32 object, u16 step count");

// The wire-size rule (docs/format.md §3), the one every encoder and decoder sizes values by.
//
// The bytes a value of `type` takes on the wire by itself: all of a scalar's, a union's or a
// pointer's code; the prefix of a String, Container, Variant, Optional or UniquePtr, whose
// characters, elements, alternative or pointee follow; none for a Struct or an Array, whose
// bytes are their members'. `Type`: a TypeInfo, or anything with its `kind` and `size` (the
// device profile's view of its compact tables).
template <typename Type>
inline std::uint32_t own_wire_size(const Type& type) {
  switch (type.kind) {
    case Kind::Struct:
    case Kind::Array:
      return 0;
    case Kind::Bool:  // kBoolSize
    case Kind::Optional:
    case Kind::UniquePtr:
      return kPresenceSize;
    default:  // from String on, a code, count or index; before, a scalar's or union's bytes
      return type.kind >= Kind::String ? kVariantIndexSize : type.size;
  }
}
// own_wire_size groups the kinds by their sizes and by Kind's values (generated.hpp).
static_assert(kBoolSize == kPresenceSize && kPointerCodeSize == kVariantIndexSize &&
                  kCountSize == kVariantIndexSize,
              "own_wire_size groups the prefixes by their size");
static_assert(Kind::Union < Kind::String && Kind::Array < Kind::String &&
                  Kind::String < Kind::Container && Kind::Container < Kind::Optional &&
                  Kind::Optional < Kind::Variant && Kind::Variant < Kind::Pointer &&
                  Kind::Pointer < Kind::UniquePtr && Kind::UniquePtr < Kind::SharedPtr,
              "the kinds from String on have a prefix or code, the ones before do not");

// Whether the values of `kind` take the same bytes whatever their value, when their members
// (a struct's fields, an array's element) do.
inline bool fixed_wire_kind(Kind kind) {
  return kind != Kind::String && kind != Kind::Container && kind != Kind::Variant &&
         kind != Kind::Optional && kind != Kind::UniquePtr;
}

// The least bytes a value of `type` takes (all its bytes for a fixed_wire_kind whose members are
// fixed): its own, plus each field's for a Struct and `count` elements' for an Array, a
// member's bytes coming from `member(member_type)`. `Size` is the arithmetic (an array's count
// is converted to it): the device's std::size_t, or the host's saturating sizes for untrusted
// schemas.
template <typename Size, typename Member>
Size wire_size_of(const TypeInfo& type, Member member) {
  if (type.kind == Kind::Struct) {
    Size total = Size(0);
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      total = total + member(type.fields[f].type);
    }
    return total;
  }
  if (type.kind == Kind::Array) return member(type.element) * Size(type.count);
  return Size(own_wire_size(type));
}

// The clock whose times a struct's field holds (kFieldClockTime; docs/format.md §2), or null.
inline const ClockInfo* field_clock(const FieldInfo& field) {
  return (field.flags & kFieldClockTime) && field.time ? field.time->clock : nullptr;
}

// Calls `on_clock` with the clock of each time field of `schema`'s structs, once per field.
template <typename OnClock>
void for_each_field_clock(const Schema& schema, OnClock on_clock) {
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    if (type.kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      if (const ClockInfo* clock = field_clock(type.fields[f])) on_clock(*clock);
    }
  }
}

// The clock readings that end the payload of a schema with `clocks` clocks: u64 epoch, then one
// i64 reading per clock, by clock index; nothing without clocks.
constexpr std::size_t kClockEpochSize = 8;
constexpr std::size_t kClockReadingSize = 8;
inline std::size_t clock_readings_size(std::uint32_t clocks) {
  return clocks != 0 ? kClockEpochSize + kClockReadingSize * std::size_t{clocks} : 0;
}
// Where clock `clock`'s reading lies in the readings (from the epoch on), and the reading.
inline std::size_t clock_reading_offset(std::uint32_t clock) {
  return kClockEpochSize + kClockReadingSize * std::size_t{clock};
}
inline std::int64_t clock_reading(const std::uint8_t* readings, std::uint32_t clock) {
  return static_cast<std::int64_t>(load64(readings + clock_reading_offset(clock)));
}

// Moves the time held in the `size`-byte little-endian integer at `p` by `delta`, in the
// integer's own wrapping arithmetic (a 32-bit millisecond time wraps as the program expects),
// unless it holds `never` (compared in the same width). Both runtimes rebase with it.
inline void rebase_time(std::uint8_t* p, std::size_t size, std::int64_t never,
                        std::uint64_t delta) {
  // Byte by byte, low byte first: no 64-bit shift by a variable count (a dozen instructions each
  // on a 32-bit microcontroller).
  std::uint64_t n = static_cast<std::uint64_t>(never);
  bool is_never = true;
  for (std::size_t i = 0; i < size; ++i, n >>= 8) is_never &= p[i] == static_cast<std::uint8_t>(n);
  if (is_never) return;
  unsigned carry = 0;
  for (std::size_t i = 0; i < size; ++i, delta >>= 8) {
    carry += p[i] + static_cast<std::uint8_t>(delta);
    p[i] = static_cast<std::uint8_t>(carry);
    carry >>= 8;
  }
}

// How the integer `raw` (two's complement when `is_signed`) compares with `d`: -1, 0 or 1,
// exactly (as a double, 2^53 + 1 would round onto 2^53), or 2 when `d` is NaN. By `d`'s bits
// and integer operations alone: a microcontroller without a double-precision unit would call a
// library routine for each conversion.
inline int compare_integer(std::uint64_t raw, bool is_signed, double d) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &d, sizeof bits);
  const bool d_negative = (bits >> 63) != 0;
  const unsigned exponent = static_cast<unsigned>(bits >> 52) & 0x7FFu;
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  if (exponent == 0x7FFu && fraction != 0) return 2;
  const bool negative = is_signed && (raw >> 63) != 0;
  const std::uint64_t magnitude = negative ? 0 - raw : raw;  // 2^63 for the least int64
  const bool d_zero = exponent == 0 && fraction == 0;
  if (negative != d_negative) {
    if (magnitude == 0 && d_zero) return 0;  // 0 and -0.0
    return negative ? -1 : 1;
  }
  int order;  // |raw| against |d|
  if (exponent == 0x7FFu) {
    order = -1;                  // infinity
  } else if (exponent < 1023) {  // |d| < 1
    order = magnitude != 0 ? 1 : d_zero ? 0 : -1;
  } else {
    const unsigned e = exponent - 1023;  // |d| = (2^52 + fraction) * 2^(e - 52)
    const std::uint64_t m = fraction | (std::uint64_t{1} << 52);
    if (e >= 64) {
      order = -1;
    } else {
      const std::uint64_t whole = e >= 52 ? m << (e - 52) : m >> (52 - e);
      const bool part = e < 52 && (m & ((std::uint64_t{1} << (52 - e)) - 1)) != 0;
      order = magnitude < whole ? -1 : magnitude > whole ? 1 : part ? -1 : 0;
    }
  }
  return negative ? -order : order;
}

// Whether the integer `raw` lies in SYMCR_RANGE's [low, high], exactly (compare_integer). A NaN
// bound holds nothing. Both runtimes check integers with it.
inline bool integer_in_range(std::uint64_t raw, bool is_signed, double low, double high) {
  const int from_low = compare_integer(raw, is_signed, low);
  return from_low >= 0 && from_low != 2 && compare_integer(raw, is_signed, high) <= 0;
}

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_PAYLOAD_HPP
