// The record header (docs/format.md §1): its layout, written once, and its codec. Host and
// device records share it; the fields after the 56 bytes of an authenticated record are here
// too, its MAC is the host's (runtime/src/api/authentication.cpp).
#ifndef SYMCR_FORMAT_RECORD_HPP
#define SYMCR_FORMAT_RECORD_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"

namespace symcr {
namespace format {

constexpr std::uint8_t kRecordMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'C', 'K', 'P'};
constexpr std::size_t kRecordMagicSize = sizeof kRecordMagic;
constexpr std::uint16_t kRecordFormatVersion = 1;
constexpr std::uint16_t kRecordHeaderSize = 56;

// Where each field of the header lies.
constexpr std::size_t kRecordVersionOffset = 8;       // u16 format_version
constexpr std::size_t kRecordHeaderSizeOffset = 10;   // u16 header_size
constexpr std::size_t kRecordFlagsOffset = 12;        // u32 flags
constexpr std::size_t kRecordSequenceOffset = 16;     // u64 sequence
constexpr std::size_t kRecordTimestampOffset = 24;    // u64 timestamp_ns
constexpr std::size_t kRecordSchemaHashOffset = 32;   // u64 schema_hash
constexpr std::size_t kRecordSchemaSizeOffset = 40;   // u32 schema_size
constexpr std::size_t kRecordPayloadSizeOffset = 44;  // u32 payload_size
constexpr std::size_t kRecordChecksumOffset = 48;     // u32 checksum
constexpr std::size_t kRecordProgramIdOffset = 52;    // u32 program_id

// Flags.
constexpr std::uint32_t kRecordSchemaInline = 1u << 0;
constexpr std::uint32_t kRecordAuthenticated = 1u << 1;
constexpr std::uint32_t kRecordKnownFlags = kRecordSchemaInline | kRecordAuthenticated;

// An authenticated record's header goes on: u32 key_id, u32 MAC version, the 32-byte MAC, u64
// journal freshness (a store's: the freshness value of its restore journal when the record
// was saved; 0 elsewhere), u64 reserved (0). Version 0 (96-byte headers of earlier builds)
// bound neither store, slot nor schema digest, and is refused.
constexpr std::uint16_t kRecordAuthenticatedHeaderSize = 112;
constexpr std::uint16_t kRecordLegacyAuthenticatedHeaderSize = 96;
constexpr std::size_t kRecordKeyIdOffset = 56;
constexpr std::size_t kRecordMacVersionOffset = 60;
constexpr std::size_t kRecordMacOffset = 64;
constexpr std::size_t kRecordMacSize = 32;
constexpr std::size_t kRecordJournalFreshnessOffset = 96;
constexpr std::uint32_t kRecordMacVersion = 2;

// Sequences of a store never reach 2^63 (one save a nanosecond would take 292 years): a record
// above is damage or forgery, and the numbering can never wrap.
constexpr std::uint64_t kMaxRecordSequence = (std::uint64_t{1} << 63) - 1;

// The layout docs/format.md §1 specifies.
static_assert(kRecordMagicSize == 8 && kRecordVersionOffset == kRecordMagicSize,
              "the version follows the 8-byte magic");
static_assert(kRecordHeaderSizeOffset == 10 && kRecordFlagsOffset == 12 &&
                  kRecordSequenceOffset == 16 && kRecordTimestampOffset == 24 &&
                  kRecordSchemaHashOffset == 32 && kRecordSchemaSizeOffset == 40 &&
                  kRecordPayloadSizeOffset == 44 && kRecordChecksumOffset == 48 &&
                  kRecordProgramIdOffset == 52,
              "record header offsets of docs/format.md §1");
static_assert(kRecordProgramIdOffset + 4 == kRecordHeaderSize, "the header is 56 bytes");
static_assert(kRecordSchemaInline == 1 && kRecordAuthenticated == 2, "flag bits 0 and 1");
static_assert(kRecordKeyIdOffset == kRecordHeaderSize && kRecordMacVersionOffset == 60 &&
                  kRecordMacOffset == 64 && kRecordMacOffset + kRecordMacSize == 96 &&
                  kRecordJournalFreshnessOffset == 96 &&
                  kRecordJournalFreshnessOffset + 16 == kRecordAuthenticatedHeaderSize,
              "authenticated header fields of docs/format.md §1, 8 reserved bytes last");

// The 56-byte header's fields.
struct RecordHeader {
  std::uint16_t format_version = 0;
  std::uint16_t header_size = 0;
  std::uint32_t flags = 0;
  std::uint64_t sequence = 0;
  std::uint64_t timestamp_ns = 0;
  std::uint64_t schema_hash = 0;
  std::uint32_t schema_size = 0;
  std::uint32_t payload_size = 0;
  std::uint32_t checksum = 0;
  std::uint32_t program_id = 0;  // the writing program (format::program_id), 0 when anonymous
};

// Writes the magic and `h` into the kRecordHeaderSize bytes at `out`.
inline void encode_record_header(const RecordHeader& h, std::uint8_t* out) {
  std::memcpy(out, kRecordMagic, kRecordMagicSize);
  store16(out + kRecordVersionOffset, h.format_version);
  store16(out + kRecordHeaderSizeOffset, h.header_size);
  store32(out + kRecordFlagsOffset, h.flags);
  store64(out + kRecordSequenceOffset, h.sequence);
  store64(out + kRecordTimestampOffset, h.timestamp_ns);
  store64(out + kRecordSchemaHashOffset, h.schema_hash);
  store32(out + kRecordSchemaSizeOffset, h.schema_size);
  store32(out + kRecordPayloadSizeOffset, h.payload_size);
  store32(out + kRecordChecksumOffset, h.checksum);
  store32(out + kRecordProgramIdOffset, h.program_id);
}

// Whether the first `size` bytes (at most the magic's) are the record magic's. Never inlined: a
// device's ring and restore both ask.
__attribute__((noinline)) inline bool starts_like_record(const std::uint8_t* data,
                                                         std::size_t size) {
  const std::size_t n = size < kRecordMagicSize ? size : kRecordMagicSize;
  for (std::size_t i = 0; i < n; ++i) {
    if (data[i] != kRecordMagic[i]) return false;
  }
  return true;
}

// What decode_record_header found wrong, in the order it checks: the magic, the bytes for a
// header, then the version (before anything else: a newer version may lay out the rest anew),
// then the header size.
enum class HeaderFault : std::uint8_t {
  None,
  Empty,          // no bytes
  BadMagic,       // the bytes there are not the magic's
  Truncated,      // fewer than kRecordHeaderSize bytes
  FutureVersion,  // format_version above kRecordFormatVersion
  ZeroVersion,    // format_version 0
  ShortHeader,    // header_size below kRecordHeaderSize
};

// Reads the 56-byte header at `data` (`size` bytes available) into `*out`. Checks only what
// the header alone tells (HeaderFault); sizes against the bytes, flags and the checksum are the
// caller's, who knows what follows.
inline HeaderFault decode_record_header(const std::uint8_t* data, std::size_t size,
                                        RecordHeader* out) {
  if (size == 0) return HeaderFault::Empty;
  if (!starts_like_record(data, size)) return HeaderFault::BadMagic;
  if (size < kRecordHeaderSize) return HeaderFault::Truncated;
  out->format_version = load16(data + kRecordVersionOffset);
  out->header_size = load16(data + kRecordHeaderSizeOffset);
  out->flags = load32(data + kRecordFlagsOffset);
  out->sequence = load64(data + kRecordSequenceOffset);
  out->timestamp_ns = load64(data + kRecordTimestampOffset);
  out->schema_hash = load64(data + kRecordSchemaHashOffset);
  out->schema_size = load32(data + kRecordSchemaSizeOffset);
  out->payload_size = load32(data + kRecordPayloadSizeOffset);
  out->checksum = load32(data + kRecordChecksumOffset);
  out->program_id = load32(data + kRecordProgramIdOffset);
  if (out->format_version > kRecordFormatVersion) return HeaderFault::FutureVersion;
  if (out->format_version == 0) return HeaderFault::ZeroVersion;
  if (out->header_size < kRecordHeaderSize) return HeaderFault::ShortHeader;
  return HeaderFault::None;
}

// The whole record's size a header claims: header, inline schema and payload. A 64-bit sum of
// 16- and 32-bit fields: it cannot overflow.
inline std::uint64_t claimed_record_size(const RecordHeader& h) {
  return std::uint64_t{h.header_size} + h.schema_size + h.payload_size;
}

// The record's checksum: CRC-32C of its `size` bytes with the checksum field read as zero,
// without modifying them. `extend` is a CRC-32C extension (crc32c_extend_small or a faster
// one), called over three spans.
template <typename Extend>
std::uint32_t record_checksum(const std::uint8_t* record, std::size_t size, Extend extend) {
  const std::uint8_t zero[4] = {0, 0, 0, 0};
  std::uint32_t crc = extend(0, record, kRecordChecksumOffset);
  crc = extend(crc, zero, sizeof zero);
  return extend(crc, record + kRecordChecksumOffset + 4, size - kRecordChecksumOffset - 4);
}

// The fields of an authenticated record's header after the 56 bytes (the MAC aside).
struct RecordAuthentication {
  std::uint32_t key_id = 0;             // the key its MAC was made with
  std::uint32_t mac_version = 0;        // kRecordMacVersion
  std::uint64_t journal_freshness = 0;  // version 2
};
inline void encode_record_authentication(const RecordAuthentication& a, std::uint8_t* record) {
  store32(record + kRecordKeyIdOffset, a.key_id);
  store32(record + kRecordMacVersionOffset, a.mac_version);
  store64(record + kRecordJournalFreshnessOffset, a.journal_freshness);
}

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_RECORD_HPP
