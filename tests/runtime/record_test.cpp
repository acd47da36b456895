// Records (docs/format.md §1): the header's byte layout, and every way parse_record refuses
// bytes that are not a whole, intact, current-version record.
#include "record.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "crc32c.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "schema_blob.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {
namespace {

using symcr::Error;

std::vector<std::uint8_t> encoded_a(std::uint64_t sequence = 0) {
  fill_a(3);
  std::vector<std::uint8_t> bytes;
  const symcr::Status status = symcr::checkpoint_to_buffer(schema_a, bytes, sequence);
  EXPECT_TRUE(status.ok()) << status.message();
  return bytes;
}

// Recomputes the checksum after a deliberate edit, so the test reaches the check after it.
void reseal(std::vector<std::uint8_t>& record) {
  symcr::format::store32(record.data() + 48, 0);
  symcr::format::store32(record.data() + 48, symcr::detail::crc32c(record.data(), record.size()));
}

symcr::Status parse(const std::vector<std::uint8_t>& bytes) {
  symcr::detail::RecordView view;
  return symcr::detail::parse_record(bytes.data(), bytes.size(), view);
}

TEST(Record, HeaderLayoutMatchesTheFormat) {
  const std::vector<std::uint8_t> record = encoded_a(42);
  const symcr::detail::SchemaBlob& blob = symcr::detail::schema_blob(schema_a);
  ASSERT_GE(record.size(), 56u + blob.size);
  EXPECT_EQ(std::memcmp(record.data(), "SYMCRCKP", 8), 0);
  EXPECT_EQ(symcr::format::load16(record.data() + 8), 1u);    // format_version
  EXPECT_EQ(symcr::format::load16(record.data() + 10), 56u);  // header_size
  EXPECT_EQ(symcr::format::load32(record.data() + 12), 1u);   // flags: schema inline
  EXPECT_EQ(symcr::format::load64(record.data() + 16), 42u);  // sequence
  EXPECT_GT(symcr::format::load64(record.data() + 24),
            1600000000ull * 1000000000ull);  // timestamp_ns
  EXPECT_EQ(symcr::format::load64(record.data() + 32), blob.hash);
  EXPECT_EQ(symcr::format::load32(record.data() + 40), blob.size);
  EXPECT_EQ(symcr::format::load32(record.data() + 44), record.size() - 56 - blob.size);
  EXPECT_EQ(symcr::format::load32(record.data() + 52), 0u);  // reserved
  EXPECT_EQ(std::memcmp(record.data() + 56, blob.data, blob.size), 0);
  // The checksum is the CRC-32C of the whole record with the checksum field zero.
  std::vector<std::uint8_t> zeroed = record;
  symcr::format::store32(zeroed.data() + 48, 0);
  EXPECT_EQ(symcr::format::load32(record.data() + 48),
            symcr::detail::crc32c(zeroed.data(), zeroed.size()));

  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), record.size(), view).ok());
  EXPECT_EQ(view.record_size, record.size());
  EXPECT_EQ(view.header.sequence, 42u);
  EXPECT_EQ(view.schema, record.data() + 56);
  EXPECT_EQ(view.payload, record.data() + 56 + blob.size);
}

TEST(Record, ALargeValueChecksummedAsItIsCopiedGivesTheWholeRecordsCrc) {
  // 2 MiB of doubles: saving computes their CRC while copying them, then combines it with the
  // header's and the schema's.
  static std::vector<double> samples(std::size_t{1} << 18);
  static const symcr::TypeInfo types[] = {
      schema_tables::scalar("float64", symcr::Kind::Float, 8),
      schema_tables::array("float64[262144]", 0, samples.size(),
                           static_cast<std::uint32_t>(samples.size() * sizeof(double)),
                           alignof(double))};
  static const symcr::RootInfo roots[] = {{"samples", 1, samples.data(), 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = static_cast<double>(i) * 0.25;
  const std::vector<double> expected = samples;
  std::vector<std::uint8_t> record;
  // The first save grows the buffer; the second reuses its capacity (the steady state).
  for (int save = 0; save < 2; ++save) {
    ASSERT_TRUE(symcr::checkpoint_to_buffer(schema, record).ok());
    std::vector<std::uint8_t> zeroed = record;
    symcr::format::store32(zeroed.data() + 48, 0);
    EXPECT_EQ(symcr::format::load32(record.data() + 48),
              symcr::detail::crc32c(zeroed.data(), zeroed.size()))
        << save;
  }
  std::fill(samples.begin(), samples.end(), -1.0);
  const symcr::Report report = symcr::restore_from_buffer(schema, record.data(), record.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(samples, expected);
}

TEST(Record, StoreRecordsReferenceTheirSchemaByHash) {
  fill_a(1);
  std::vector<std::uint8_t> record;
  ASSERT_TRUE(symcr::detail::encode_record(schema_a, /*inline_schema=*/false, 9, record).ok());
  EXPECT_EQ(symcr::format::load32(record.data() + 12), 0u);  // flags: schema by hash
  EXPECT_EQ(symcr::format::load32(record.data() + 40), 0u);  // schema_size
  EXPECT_EQ(symcr::format::load64(record.data() + 32), symcr::detail::schema_blob(schema_a).hash);
  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), record.size(), view).ok());
  EXPECT_EQ(view.schema, nullptr);
  EXPECT_EQ(view.payload, record.data() + 56);
  EXPECT_EQ(view.payload_size, record.size() - 56);
}

TEST(Record, EmptyAndMagicPrefixesAreTruncated) {
  EXPECT_EQ(parse({}).error(), Error::Truncated);
  EXPECT_EQ(parse({'S', 'Y', 'M'}).error(), Error::Truncated);
}

TEST(Record, WrongMagicIsNotACheckpoint) {
  std::vector<std::uint8_t> record = encoded_a();
  record[3] = 'X';
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::NotACheckpoint);
  const std::string text = "just some text, long enough to fill a whole record header....";
  EXPECT_EQ(parse(std::vector<std::uint8_t>(text.begin(), text.end())).error(),
            Error::NotACheckpoint);
}

TEST(Record, FutureVersionIsRefusedNamingBothVersions) {
  std::vector<std::uint8_t> record = encoded_a();
  symcr::format::store16(record.data() + 8, 2);
  reseal(record);
  const symcr::Status status = parse(record);
  EXPECT_EQ(status.error(), Error::FutureVersion);
  EXPECT_NE(std::string(status.message()).find("version 2"), std::string::npos)
      << status.message();
  EXPECT_NE(std::string(status.message()).find("version 1"), std::string::npos)
      << status.message();
  // Refused before the checksum: a future version may checksum differently.
  symcr::format::store16(record.data() + 8, 7);
  EXPECT_EQ(parse(record).error(), Error::FutureVersion);
}

TEST(Record, VersionZeroAndShortHeaderSizeAreCorrupt) {
  std::vector<std::uint8_t> record = encoded_a();
  symcr::format::store16(record.data() + 8, 0);
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Corrupt);
  record = encoded_a();
  symcr::format::store16(record.data() + 10, 40);
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Corrupt);
}

TEST(Record, SizesBeyondTheAvailableBytesAreTruncated) {
  std::vector<std::uint8_t> record = encoded_a();
  symcr::format::store32(record.data() + 44, 0xFFFFFFFFu);  // payload_size
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Truncated);
  record = encoded_a();
  symcr::format::store32(record.data() + 40, 0xFFFFFFF0u);  // schema_size
  EXPECT_EQ(parse(record).error(), Error::Truncated);
  record = encoded_a();
  record.pop_back();
  EXPECT_EQ(parse(record).error(), Error::Truncated);
}

TEST(Record, ChecksumMismatchIsDetected) {
  std::vector<std::uint8_t> record = encoded_a();
  record.back() ^= 0x10;
  EXPECT_EQ(parse(record).error(), Error::Checksum);
  record = encoded_a();
  record[52] = 1;  // reserved bytes are covered too
  EXPECT_EQ(parse(record).error(), Error::Checksum);
}

// Given the reader's schema and its share of the CRC, the inline schema's bytes are not read for
// the checksum: every byte of the record is still covered, with the same verdict as a full read.
TEST(Record, AKnownInlineSchemasShareOfTheChecksumCoversEveryByte) {
  const symcr::detail::SchemaBlob& own = symcr::detail::schema_blob(schema_a);
  const symcr::detail::Crc32cSpan share = symcr::detail::crc32c_span(own.data, own.size);
  const std::vector<std::uint8_t> intact = encoded_a();
  symcr::detail::RecordView view;
  ASSERT_TRUE(
      symcr::detail::parse_record(intact.data(), intact.size(), view, &own, &share).ok());
  EXPECT_TRUE(view.schema_is_known);
  for (std::size_t i = 0; i < intact.size(); ++i) {
    std::vector<std::uint8_t> record = intact;
    record[i] ^= 0x04;
    const symcr::Status full = parse(record);
    const symcr::Status shared =
        symcr::detail::parse_record(record.data(), record.size(), view, &own, &share);
    ASSERT_FALSE(shared.ok()) << "byte " << i;
    EXPECT_EQ(shared.error(), full.error()) << "byte " << i;
    EXPECT_STREQ(shared.message(), full.message()) << "byte " << i;
  }
}

TEST(Record, UnknownFlagsAndInconsistentSchemaFlagAreCorrupt) {
  std::vector<std::uint8_t> record = encoded_a();
  symcr::format::store32(record.data() + 12, 0x3);
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Corrupt);
  record = encoded_a();
  symcr::format::store32(record.data() + 12, 0);  // says "by hash" but carries a schema
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Corrupt);
}

TEST(Record, InlineSchemaMustMatchItsHash) {
  std::vector<std::uint8_t> record = encoded_a();
  record[32] ^= 1;  // schema_hash
  reseal(record);
  EXPECT_EQ(parse(record).error(), Error::Corrupt);
}

TEST(Record, LongerHeaderOfTheSameVersionIsSkipped) {
  // A same-version writer may append header fields this reader does not know.
  std::vector<std::uint8_t> record = encoded_a(5);
  record.insert(record.begin() + 56, 8, 0xAB);
  symcr::format::store16(record.data() + 10, 64);
  reseal(record);
  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), record.size(), view).ok());
  EXPECT_EQ(view.schema, record.data() + 64);
  scramble_a();
  const symcr::Report report = symcr::restore_from_buffer(schema_a, record.data(), record.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 5u);
  EXPECT_EQ(copter_a.ticks, 1003);
}

TEST(Record, BytesAfterAStandaloneRecordAreCorrupt) {
  std::vector<std::uint8_t> record = encoded_a();
  record.push_back(0);
  scramble_a();
  const auto before = snapshot(copter_a);
  const symcr::Report report = symcr::restore_from_buffer(schema_a, record.data(), record.size());
  EXPECT_EQ(report.status().error(), Error::Corrupt);
  EXPECT_EQ(snapshot(copter_a), before);
}

TEST(Record, AStoreRecordIsNotAStandaloneCheckpoint) {
  fill_a(1);
  std::vector<std::uint8_t> record;
  ASSERT_TRUE(symcr::detail::encode_record(schema_a, /*inline_schema=*/false, 9, record).ok());
  const symcr::Report report = symcr::restore_from_buffer(schema_a, record.data(), record.size());
  EXPECT_EQ(report.status().error(), Error::SchemaUnknown);
}

}  // namespace
}  // namespace file_tests
