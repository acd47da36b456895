// The format core (runtime/format): the record header codec on a real record and on each fault
// in the spec's order, its small CRC-32C against the host's, and the one wire-size rule as the
// host's WireSizes and the device profile's wire_size both apply it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "crc32c.hpp"
#include "device_format.hpp"
#include "encode.hpp"
#include "handwritten_schemas.hpp"
#include "payload_grammar.hpp"
#include "record.hpp"
#include "symcr/device.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/format/payload.hpp"
#include "symcr/format/record.hpp"
#include "symcr/symcr.hpp"

namespace {

namespace format = symcr::format;
namespace engine = ::engine_tests;

std::vector<std::uint8_t> record_of(const symcr::Schema& schema, std::uint64_t sequence) {
  std::vector<std::uint8_t> record;
  EXPECT_TRUE(symcr::checkpoint_to_buffer(schema, record, sequence).ok());
  return record;
}

TEST(FormatCore, HeaderCodecReadsTheHostsRecordAsTheHostDoes) {
  const std::vector<std::uint8_t> record = record_of(engine::p::schema(), 42);
  format::RecordHeader header;
  ASSERT_EQ(format::decode_record_header(record.data(), record.size(), &header),
            format::HeaderFault::None);
  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), record.size(), view).ok());
  EXPECT_EQ(header.format_version, 1u);
  EXPECT_EQ(header.header_size, 56u);
  EXPECT_EQ(header.flags, format::kRecordSchemaInline);
  EXPECT_EQ(header.sequence, 42u);
  EXPECT_EQ(header.schema_hash, view.header.schema_hash);
  EXPECT_EQ(header.schema_hash, format::fnv1a64(view.schema, header.schema_size));
  EXPECT_EQ(header.payload_size, view.payload_size);
  EXPECT_EQ(header.program_id, format::program_id(engine::p::schema().program));
  EXPECT_EQ(format::claimed_record_size(header), record.size());
  // The checksum through the device's small CRC is the host's.
  EXPECT_EQ(format::record_checksum(record.data(), record.size(), format::crc32c_extend_small),
            header.checksum);
  EXPECT_EQ(format::record_checksum(record.data(), record.size(), symcr::detail::crc32c_extend),
            header.checksum);
  // Encoding the fields gives the header's bytes back.
  std::uint8_t encoded[format::kRecordHeaderSize];
  format::encode_record_header(header, encoded);
  EXPECT_EQ(std::memcmp(encoded, record.data(), sizeof encoded), 0);
}

TEST(FormatCore, HeaderCodecRefusesInTheSpecsOrder) {
  std::vector<std::uint8_t> record = record_of(engine::p::schema(), 1);
  format::RecordHeader header;
  EXPECT_EQ(format::decode_record_header(record.data(), 0, &header), format::HeaderFault::Empty);
  // A short prefix of the magic is still a record cut short; a wrong byte is not a record.
  EXPECT_EQ(format::decode_record_header(record.data(), 5, &header),
            format::HeaderFault::Truncated);
  EXPECT_EQ(format::decode_record_header(record.data(), 55, &header),
            format::HeaderFault::Truncated);
  std::vector<std::uint8_t> bad = record;
  bad[3] ^= 0x20;
  EXPECT_EQ(format::decode_record_header(bad.data(), 5, &header), format::HeaderFault::BadMagic);
  // The version before the header size: a newer version may lay the rest out anew.
  bad = record;
  format::store16(bad.data() + format::kRecordVersionOffset, 2);
  format::store16(bad.data() + format::kRecordHeaderSizeOffset, 8);
  EXPECT_EQ(format::decode_record_header(bad.data(), bad.size(), &header),
            format::HeaderFault::FutureVersion);
  EXPECT_EQ(header.format_version, 2u);
  format::store16(bad.data() + format::kRecordVersionOffset, 0);
  EXPECT_EQ(format::decode_record_header(bad.data(), bad.size(), &header),
            format::HeaderFault::ZeroVersion);
  format::store16(bad.data() + format::kRecordVersionOffset, 1);
  EXPECT_EQ(format::decode_record_header(bad.data(), bad.size(), &header),
            format::HeaderFault::ShortHeader);
  EXPECT_EQ(header.header_size, 8u);
}

TEST(FormatCore, SmallCrcEqualsTheHostsAtEveryLength) {
  std::mt19937 random(7);
  std::vector<std::uint8_t> bytes(1100);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(random());
  for (std::size_t n = 0; n <= bytes.size(); ++n) {
    ASSERT_EQ(format::crc32c_extend_small(0x12345678u, bytes.data(), n),
              symcr::detail::crc32c_extend(0x12345678u, bytes.data(), n))
        << n << " bytes";
  }
  const char* check = "123456789";
  EXPECT_EQ(format::crc32c_extend_small(0, reinterpret_cast<const std::uint8_t*>(check), 9),
            0xE3069283u);
}

TEST(FormatCore, HashesOfTheSpec) {
  const std::uint8_t foobar[] = {'f', 'o', 'o', 'b', 'a', 'r'};
  EXPECT_EQ(format::fnv1a64(foobar, sizeof foobar), 0x85944171f73967e8ull);
  EXPECT_EQ(format::program_id(nullptr), 0u);
  EXPECT_EQ(format::program_id(""), 0u);
  EXPECT_EQ(format::program_id("a"), 0xe40c292cu);  // FNV-1a 32 of "a"
}

// The host sizes a writer schema's values by WireSizes, the device by wire_size: both by the
// format core's rule, so for every schema the device holds they agree, with each other and with
// the bytes the host writes.
TEST(FormatCore, WireSizeRuleIsTheSameOnHostAndDevice) {
  const symcr::Schema* schemas[] = {
      &engine::a0::schema(), &engine::a1::schema(), &engine::c0::schema(), &engine::c1::schema(),
      &engine::d0::schema(), &engine::d1::schema(), &engine::e0::schema(), &engine::e1::schema(),
      &engine::g::schema(),  &engine::p::schema()};
  int held = 0;
  for (const symcr::Schema* schema : schemas) {
    if (symcr::device::check_schema(*schema) != symcr::device::Result::Ok) continue;
    ++held;
    const symcr::detail::WireSizes sizes = symcr::detail::wire_sizes(*schema);
    std::uint64_t roots = 0;
    for (std::uint32_t t = 0; t < schema->type_count; ++t) {
      ASSERT_NE(sizes.fixed[t], symcr::detail::WireSizes::kVariable) << schema->types[t].name;
      EXPECT_EQ(sizes.fixed[t], symcr::device::detail::wire_size(*schema, t))
          << schema->types[t].name;
      EXPECT_EQ(sizes.least[t], sizes.fixed[t]) << schema->types[t].name;
    }
    for (std::uint32_t r = 0; r < schema->root_count; ++r) {
      roots += sizes.fixed[schema->roots[r].type];
    }
    EXPECT_EQ(roots, symcr::device::detail::values_size(*schema)) << schema->program;
    std::vector<std::uint8_t> payload;
    ASSERT_TRUE(symcr::detail::encode_payload(*schema, payload).ok());
    // The values, then the heap and reference counts; then references and clock readings.
    ASSERT_GE(payload.size(), roots + format::kHeapCountSize + format::kReferenceCountSize);
    EXPECT_EQ(format::load32(payload.data() + roots), 0u);  // no heap objects
  }
  EXPECT_GT(held, 0);
}

TEST(FormatCore, ClockReadingsTrailer) {
  EXPECT_EQ(format::clock_readings_size(0), 0u);
  EXPECT_EQ(format::clock_readings_size(2), 24u);
  std::uint8_t trailer[24];
  format::store64(trailer, 99);  // the epoch
  format::store64(trailer + 8, 5);
  format::store64(trailer + 16, static_cast<std::uint64_t>(-7));
  EXPECT_EQ(format::clock_reading(trailer, 0), 5);
  EXPECT_EQ(format::clock_reading(trailer, 1), -7);
  // A 16-bit time wraps as the program's does; `never` stays.
  std::uint8_t time[2];
  format::store16(time, 0xFFF0);
  format::rebase_time(time, 2, 0, 0x20);
  EXPECT_EQ(format::load16(time), 0x0010);
  format::store16(time, 0);
  format::rebase_time(time, 2, 0, 0x20);
  EXPECT_EQ(format::load16(time), 0);
}

// Integers meet SYMCR_RANGE's double bounds exactly: 2^53 + 1 would round onto a bound of 2^53
// as a double. Non-integral bounds, bounds past the integer's range and NaN bounds too.
TEST(FormatCore, IntegersAreComparedWithTheirRangeExactly) {
  using symcr::format::integer_in_range;
  const double two53 = 9007199254740992.0;
  const std::uint64_t above = (std::uint64_t{1} << 53) + 1;
  EXPECT_TRUE(integer_in_range(above - 1, false, 0, two53));
  EXPECT_FALSE(integer_in_range(above, false, 0, two53));
  EXPECT_FALSE(integer_in_range(above, true, 0, two53));
  const std::int64_t below = -static_cast<std::int64_t>(above);
  EXPECT_FALSE(integer_in_range(static_cast<std::uint64_t>(below), true, -two53, 0));
  EXPECT_TRUE(integer_in_range(static_cast<std::uint64_t>(below + 1), true, -two53, 0));
  // Non-integral bounds: [-2.5, 3.5] holds -2 .. 3.
  for (std::int64_t v = -4; v <= 5; ++v) {
    EXPECT_EQ(integer_in_range(static_cast<std::uint64_t>(v), true, -2.5, 3.5), v >= -2 && v <= 3)
        << v;
  }
  for (std::uint64_t v = 0; v <= 5; ++v) {
    EXPECT_EQ(integer_in_range(v, false, 0.5, 3.5), v >= 1 && v <= 3) << v;
  }
  // Bounds past the integer's range.
  const std::uint64_t max_u64 = ~std::uint64_t{0};
  EXPECT_TRUE(integer_in_range(max_u64, false, -1e300, 1e300));
  EXPECT_FALSE(integer_in_range(max_u64, false, 0, 18446744073709549568.0));  // 2^64 - 2048
  EXPECT_TRUE(integer_in_range(max_u64, true, -1e300, 1e300));                // -1
  EXPECT_TRUE(integer_in_range(std::uint64_t{1} << 63, true, -9223372036854775808.0, 0));
  EXPECT_FALSE(integer_in_range(0, true, 9223372036854775808.0, 1e300));
  EXPECT_FALSE(integer_in_range(0, false, -5, -1));
  // Zeros of both signs, fractions below one, subnormals, infinities.
  using symcr::format::compare_integer;
  EXPECT_EQ(compare_integer(0, true, -0.0), 0);
  EXPECT_EQ(compare_integer(0, false, 0.0), 0);
  EXPECT_EQ(compare_integer(0, true, 0.25), -1);
  EXPECT_EQ(compare_integer(0, true, -0.25), 1);
  EXPECT_EQ(compare_integer(static_cast<std::uint64_t>(-1), true, -0.25), -1);
  EXPECT_EQ(compare_integer(1, false, 4.9e-324), 1);
  EXPECT_EQ(compare_integer(0, false, 4.9e-324), -1);
  EXPECT_EQ(compare_integer(max_u64, false, HUGE_VAL), -1);
  EXPECT_EQ(compare_integer(std::uint64_t{1} << 63, true, -HUGE_VAL), 1);
  EXPECT_EQ(compare_integer(std::uint64_t{1} << 63, true, -9223372036854775808.0), 0);
  EXPECT_EQ(compare_integer(std::uint64_t{1} << 63, false, 9223372036854775808.0), 0);
  EXPECT_EQ(compare_integer(5, true, -5.0), 1);
  EXPECT_EQ(compare_integer(static_cast<std::uint64_t>(-5), true, 5.0), -1);
  EXPECT_EQ(compare_integer(3, false, std::nan("")), 2);
  // NaN bounds and an empty range hold nothing.
  EXPECT_FALSE(integer_in_range(0, true, std::nan(""), 1));
  EXPECT_FALSE(integer_in_range(0, false, 0, std::nan("")));
  EXPECT_FALSE(integer_in_range(1, false, 2, 1));
}

}  // namespace
