// Per-value scalar conversions (docs/resolution.md: convert; a value that does not fit is rejected).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "handwritten_schemas.hpp"
#include "scalar.hpp"

namespace engine_tests {
namespace {

using symcr::detail::Number;

const symcr::EnumeratorInfo kColours[] = {{"RED", 1}, {"BLUE", 4}};
const TypeInfo kTypes[] = {
    scalar("bool", Kind::Bool, 1),      scalar("int8", Kind::Int, 1),
    scalar("uint8", Kind::UInt, 1),     scalar("int64", Kind::Int, 8),
    scalar("uint64", Kind::UInt, 8),    scalar("float32", Kind::Float, 4),
    scalar("float64", Kind::Float, 8),  enumeration("Colour", 1, 2, kColours, 2),
    scalar("float80", Kind::Float, 16),
};
const symcr::Schema kSchema{kTypes, 9, nullptr, 0, nullptr};
enum { kBool, kInt8, kUInt8, kInt64, kUInt64, kFloat32, kFloat64, kColour, kFloat80 };

Number integer(std::int64_t v) {
  Number n;
  n.tag = Number::Tag::Signed;
  n.s = v;
  return n;
}
Number unsigned_integer(std::uint64_t v) {
  Number n;
  n.tag = Number::Tag::Unsigned;
  n.u = v;
  return n;
}
Number floating(long double v) {
  Number n;
  n.tag = Number::Tag::Floating;
  n.f = v;
  return n;
}

bool converts(const Number& in, int to, Number* out = nullptr) {
  Number result;
  char why[160];
  const bool ok = symcr::detail::convert_number(kSchema, kTypes[to], in, result, why, sizeof why);
  if (out) *out = result;
  return ok;
}

TEST(EngineScalar, IntegerRanges) {
  EXPECT_TRUE(converts(integer(-128), kInt8));
  EXPECT_FALSE(converts(integer(-129), kInt8));
  EXPECT_FALSE(converts(integer(-1), kUInt8));
  EXPECT_TRUE(converts(integer(255), kUInt8));
  EXPECT_FALSE(converts(integer(256), kUInt8));
  EXPECT_FALSE(converts(unsigned_integer(std::numeric_limits<std::uint64_t>::max()), kInt64));
  EXPECT_TRUE(converts(integer(std::numeric_limits<std::int64_t>::min()), kInt64));
  EXPECT_TRUE(converts(integer(1), kBool));
  EXPECT_FALSE(converts(integer(2), kBool));
}

TEST(EngineScalar, FloatingConversions) {
  Number out;
  EXPECT_TRUE(converts(floating(3.0L), kInt8, &out));
  EXPECT_EQ(out.s, 3);
  EXPECT_FALSE(converts(floating(3.5L), kInt8));
  EXPECT_FALSE(converts(floating(-1.0L), kUInt64));
  EXPECT_FALSE(converts(floating(NAN), kInt64));
  EXPECT_FALSE(converts(floating(0x1p64L), kUInt64));
  EXPECT_TRUE(converts(floating(0x1p63L), kUInt64));
  EXPECT_FALSE(converts(floating(0x1p63L), kInt64));
  EXPECT_FALSE(converts(floating(1e300L), kFloat32));
  EXPECT_TRUE(converts(floating(INFINITY), kFloat32));  // infinities and NaN stay what they are
  EXPECT_TRUE(converts(floating(0.1L), kFloat32, &out));
  EXPECT_EQ(static_cast<float>(out.f), 0.1f);
  EXPECT_TRUE(converts(integer((std::int64_t{1} << 53) + 0), kFloat64));
  EXPECT_FALSE(converts(integer((std::int64_t{1} << 53) + 1), kFloat64));
  EXPECT_TRUE(converts(integer((std::int64_t{1} << 53) + 1), kFloat80));
  EXPECT_FALSE(converts(unsigned_integer(std::numeric_limits<std::uint64_t>::max()), kFloat64));
}

TEST(EngineScalar, EnumsAcceptOnlyTheirEnumerators) {
  EXPECT_TRUE(converts(integer(4), kColour));
  EXPECT_FALSE(converts(integer(2), kColour));
}

TEST(EngineScalar, BitFieldsAndStorage) {
  EXPECT_TRUE(symcr::detail::fits_bits(integer(-4), 3, true));
  EXPECT_FALSE(symcr::detail::fits_bits(integer(-5), 3, true));
  EXPECT_TRUE(symcr::detail::fits_bits(unsigned_integer(7), 3, false));
  EXPECT_FALSE(symcr::detail::fits_bits(unsigned_integer(8), 3, false));
  EXPECT_FALSE(symcr::detail::fits_bits(integer(-1), 3, false));
  std::uint8_t unit[4] = {0xFF, 0xFF, 0xFF, 0xFF};
  symcr::detail::store_bits(unit, 5, 6, unsigned_integer(0));
  std::uint32_t word;
  std::memcpy(&word, unit, 4);
  EXPECT_EQ(word, 0xFFFFF81Fu);
  std::uint8_t bytes[8] = {};
  symcr::detail::store_number(kSchema, kTypes[kInt8], integer(-2), bytes);
  EXPECT_EQ(bytes[0], 0xFE);
  EXPECT_EQ(bytes[1], 0);
  Number read;
  ASSERT_TRUE(symcr::detail::read_number(kSchema, kTypes[kInt8], bytes, read));
  EXPECT_EQ(read.s, -2);
  const std::uint8_t bad_bool = 2;
  EXPECT_FALSE(symcr::detail::read_number(kSchema, kTypes[kBool], &bad_bool, read));
}

}  // namespace
}  // namespace engine_tests
