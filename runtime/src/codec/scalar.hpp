// Scalar values in flight between a writer type and a reader type: read from wire bytes,
// converted with per-value range checks (docs/resolution.md), written at the reader's width.
#ifndef SYMCR_SRC_SCALAR_HPP
#define SYMCR_SRC_SCALAR_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/generated.hpp"

namespace symcr::detail {

struct Number {
  enum class Tag : std::uint8_t { Signed, Unsigned, Floating } tag = Tag::Signed;
  std::int64_t s = 0;
  std::uint64_t u = 0;
  long double f = 0;
  long double as_long_double() const;
};

// `type` is Bool/Int/UInt/Float/Enum of `schema`; `bytes` holds `type.size` wire bytes.
// False when the bytes are not a valid value (a bool other than 0/1).
bool read_number(const Schema& schema, const TypeInfo& type, const std::uint8_t* bytes,
                 Number& out);

// Converts `in` to the reader scalar `type` (an Enum converts to its underlying integer);
// false with a reason when the value does not fit. Integer to floating must round-trip
// exactly; floating to integer must be integral and in range; floating narrowing rounds but
// rejects values beyond the narrower type's range.
bool convert_number(const Schema& schema, const TypeInfo& type, const Number& in, Number& out,
                    char* why, std::size_t why_size);

// Whether an integer value fits in a bit-field of `width` bits.
bool fits_bits(const Number& value, unsigned width, bool is_signed);

// Stores `value` (already converted for `type`) as `type.size` little-endian bytes.
void store_number(const Schema& schema, const TypeInfo& type, const Number& value,
                  std::uint8_t* dst);
// Stores the low `width` bits of an integer value into a bit-field.
void store_bits(std::uint8_t* unit, unsigned bit_offset, unsigned width, const Number& value);

void format_number(const Number& value, char* buffer, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCALAR_HPP
