// Re-encoding strings whose character width changes (unicode.hpp): UTF-8, UTF-16 and UTF-32
// by code point, and every kind of invalid input refused with its position.
#include "unicode.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

using symcr::detail::transcode_string;

// Little-endian code units of `width` bytes, as the wire has them.
std::vector<std::uint8_t> units(const std::vector<std::uint32_t>& values, unsigned width) {
  std::vector<std::uint8_t> bytes;
  for (std::uint32_t v : values) {
    for (unsigned b = 0; b < width; ++b) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
  }
  return bytes;
}

struct Result {
  bool ok;
  std::vector<std::uint8_t> bytes;
  std::uint32_t length;
  std::string why;
};

Result transcode(const std::vector<std::uint32_t>& in, unsigned from, unsigned to) {
  const std::vector<std::uint8_t> bytes = units(in, from);
  Result result{};
  char why[160] = {};
  result.ok = transcode_string(bytes.data(), static_cast<std::uint32_t>(in.size()), from, to,
                               result.bytes, result.length, why, sizeof why);
  result.why = why;
  return result;
}

// "é", "中", "🚁" (U+1F681) in each encoding.
const std::vector<std::uint32_t> kUtf8 = {0xC3, 0xA9, 0xE4, 0xB8, 0xAD, 0xF0, 0x9F, 0x9A, 0x81};
const std::vector<std::uint32_t> kUtf16 = {0xE9, 0x4E2D, 0xD83D, 0xDE81};
const std::vector<std::uint32_t> kUtf32 = {0xE9, 0x4E2D, 0x1F681};

TEST(Unicode, EveryPairOfEncodingsRoundTripsByCodePoint) {
  const std::vector<std::uint32_t>* forms[] = {&kUtf8, &kUtf16, nullptr, &kUtf32};
  for (unsigned from : {1u, 2u, 4u}) {
    for (unsigned to : {1u, 2u, 4u}) {
      const Result result = transcode(*forms[from - 1], from, to);
      ASSERT_TRUE(result.ok) << from << " -> " << to << ": " << result.why;
      EXPECT_EQ(result.length, forms[to - 1]->size()) << from << " -> " << to;
      EXPECT_EQ(result.bytes, units(*forms[to - 1], to)) << from << " -> " << to;
    }
  }
}

TEST(Unicode, AnEmptyStringStaysEmpty) {
  const Result result = transcode({}, 1, 4);
  EXPECT_TRUE(result.ok);
  EXPECT_EQ(result.length, 0u);
}

TEST(Unicode, InvalidUtf8IsRefusedWithItsPosition) {
  struct Case {
    std::vector<std::uint32_t> input;
    const char* why;
  } cases[] = {
      {{'a', 0xFF}, "character 1"},               // never a UTF-8 byte
      {{'a', 'b', 0x80}, "character 2"},          // a continuation byte first
      {{0xC3}, "character 0"},                    // cut off
      {{0xC0, 0x80}, "character 0"},              // overlong NUL
      {{0xE0, 0x80, 0x80}, "character 0"},        // overlong
      {{0xED, 0xA0, 0x80}, "character 0"},        // a surrogate encoded in UTF-8
      {{0xF4, 0x90, 0x80, 0x80}, "character 0"},  // past U+10FFFF
      {{0xC3, 0x28}, "character 0"},              // a bad continuation
  };
  for (const Case& c : cases) {
    const Result result = transcode(c.input, 1, 2);
    EXPECT_FALSE(result.ok);
    EXPECT_NE(result.why.find(c.why), std::string::npos) << result.why;
    EXPECT_NE(result.why.find("not valid UTF-8"), std::string::npos) << result.why;
  }
}

TEST(Unicode, UnpairedSurrogatesAndOutOfRangeCodePointsAreRefused) {
  EXPECT_FALSE(transcode({'a', 0xD800}, 2, 1).ok);          // a high surrogate at the end
  EXPECT_FALSE(transcode({0xD800, 'a'}, 2, 1).ok);          // not followed by a low one
  EXPECT_FALSE(transcode({0xDC00, 0xD800}, 2, 4).ok);       // a low surrogate first
  EXPECT_FALSE(transcode({0x110000}, 4, 1).ok);             // past U+10FFFF
  EXPECT_FALSE(transcode({0xDFFF}, 4, 2).ok);               // a surrogate as a code point
  EXPECT_TRUE(transcode({0x10FFFF}, 4, 2).ok);              // the last code point
}

}  // namespace
