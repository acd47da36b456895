// libFuzzer target (f): the format core's record header codec (runtime/format) on arbitrary
// bytes, and its checksum, against the host's own implementations.
//
// Input: the bytes a record would start with (any length).
//
// Checked beyond the sanitizers: a header decode_record_header accepts re-encodes to the same
// 56 bytes, and decoding those again gives the same fields; a refused one is refused for the
// first rule it breaks, in the documented order; the format core's small CRC-32C (the device
// profile's) equals the host's fast one over the input, and the record checksum read through
// either equals the CRC of the bytes with the checksum field zeroed.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "crc32c.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/format/record.hpp"

namespace {

namespace format = symcr::format;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "symcr fuzz: record header: %s\n", what);
  std::abort();
}

bool same_fields(const format::RecordHeader& a, const format::RecordHeader& b) {
  return a.format_version == b.format_version && a.header_size == b.header_size &&
         a.flags == b.flags && a.sequence == b.sequence && a.timestamp_ns == b.timestamp_ns &&
         a.schema_hash == b.schema_hash && a.schema_size == b.schema_size &&
         a.payload_size == b.payload_size && a.checksum == b.checksum &&
         a.program_id == b.program_id;
}

// The fault the documented order gives for `data`: magic, length, version, header size.
format::HeaderFault expected_fault(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return format::HeaderFault::Empty;
  const std::size_t compared = size < format::kRecordMagicSize ? size : format::kRecordMagicSize;
  if (std::memcmp(data, format::kRecordMagic, compared) != 0) return format::HeaderFault::BadMagic;
  if (size < format::kRecordHeaderSize) return format::HeaderFault::Truncated;
  const std::uint16_t version = format::load16(data + format::kRecordVersionOffset);
  if (version > format::kRecordFormatVersion) return format::HeaderFault::FutureVersion;
  if (version == 0) return format::HeaderFault::ZeroVersion;
  if (format::load16(data + format::kRecordHeaderSizeOffset) < format::kRecordHeaderSize) {
    return format::HeaderFault::ShortHeader;
  }
  return format::HeaderFault::None;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The CRC: the device's nibble table and the host's slicing or SSE4.2 code agree.
  if (format::crc32c_extend_small(0, data, size) != symcr::detail::crc32c(data, size)) {
    fail("the small CRC-32C differs from the host's");
  }

  format::RecordHeader header;
  const format::HeaderFault fault = format::decode_record_header(data, size, &header);
  if (fault != expected_fault(data, size)) fail("refused for another rule than the first broken");
  if (fault != format::HeaderFault::None) return 0;

  // Accepted: the fields are the bytes' and re-encode to them.
  std::uint8_t encoded[format::kRecordHeaderSize];
  format::encode_record_header(header, encoded);
  if (std::memcmp(encoded, data, format::kRecordHeaderSize) != 0) fail("re-encoded differently");
  format::RecordHeader again;
  if (format::decode_record_header(encoded, sizeof encoded, &again) != format::HeaderFault::None ||
      !same_fields(header, again)) {
    fail("the re-encoded header decodes differently");
  }
  if (format::claimed_record_size(header) !=
      std::uint64_t{header.header_size} + header.schema_size + header.payload_size) {
    fail("claimed size is not the sum of the sizes");
  }

  // The record checksum over the input, through either CRC, is the CRC of a copy whose
  // checksum field is zero.
  std::vector<std::uint8_t> zeroed(data, data + size);
  format::store32(zeroed.data() + format::kRecordChecksumOffset, 0);
  const std::uint32_t expected = symcr::detail::crc32c(zeroed.data(), zeroed.size());
  if (format::record_checksum(data, size, format::crc32c_extend_small) != expected ||
      format::record_checksum(data, size, symcr::detail::crc32c_extend) != expected) {
    fail("record checksum differs from the CRC of the zeroed record");
  }
  return 0;
}
