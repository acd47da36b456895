// The store file's fixed layout (docs/format.md §4): its header, the pages and schema areas
// before the slots, the bounds of its geometry, the restore journal's and the identity's places
// and fields in the first page, and the freshness counter file beside it. The host's Store and
// StoreReader read and write them (runtime/src/api: store_layout.*, restore_journal.*,
// freshness.*).
#ifndef SYMCR_FORMAT_STORE_HPP
#define SYMCR_FORMAT_STORE_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/format/record.hpp"

namespace symcr {
namespace format {

constexpr std::uint8_t kStoreFileMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'S', 'T', 'O'};
constexpr std::uint16_t kStoreFileFormatVersion = 1;
// Header fields: u16 version at 8 (then 2 reserved bytes), u32 slot_count, u32 slot_size,
// u32 schema_area_size, u64 slots_offset, and the CRC-32C of the 32 bytes before it.
constexpr std::size_t kStoreVersionOffset = 8;
constexpr std::size_t kStoreSlotCountOffset = 12;
constexpr std::size_t kStoreSlotSizeOffset = 16;
constexpr std::size_t kStoreSchemaAreaSizeOffset = 20;
constexpr std::size_t kStoreSlotsOffsetOffset = 24;
constexpr std::size_t kStoreHeaderCrcOffset = 32;
constexpr std::size_t kStoreHeaderSize = 36;
// The first page holds the header (and the journal and identity); the schema areas follow.
constexpr std::uint64_t kStorePageSize = 4096;
// A schema area's header: u64 hash, u32 size, u32 CRC-32C of the hash, size and schema bytes.
constexpr std::size_t kStoreAreaHashOffset = 0;
constexpr std::size_t kStoreAreaSizeOffset = 8;
constexpr std::size_t kStoreAreaCrcOffset = 12;
constexpr std::size_t kStoreAreaHeaderSize = 16;
constexpr std::uint32_t kStoreMinSchemaAreaSize = 64 * 1024;
constexpr std::uint32_t kStoreMaxSlots = 1u << 20;
constexpr std::uint32_t kStoreMinSlotSize = 2 * kRecordHeaderSize;
constexpr std::uint32_t kStoreMaxSlotSize = 1u << 30;

// ---- The restore journal: two copies in the first page (both in its first 512-byte sector),
// each the journal (offsets from the copy's start) then its seal; written by one pwrite.
constexpr std::uint64_t kJournalFirstCopyOffset = 128;
constexpr std::uint64_t kJournalSecondCopyOffset = 256;
constexpr std::uint8_t kJournalMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'J', 'N', '2'};
constexpr std::size_t kJournalGenerationOffset = 8;
constexpr std::size_t kJournalUnconfirmedOffset = 16;
constexpr std::size_t kJournalSuspectLowOffset = 24;
constexpr std::size_t kJournalSuspectHighOffset = 32;
constexpr std::size_t kJournalGivenUpThroughOffset = 40;
constexpr std::size_t kJournalCrashedLowOffset = 48;
constexpr std::size_t kJournalCrashedHighOffset = 56;
constexpr std::size_t kJournalFallbacksOffset = 64;
constexpr std::size_t kJournalDepthOffset = 68;
constexpr std::size_t kJournalCrcOffset = 72;  // CRC-32C of the bytes before it
constexpr std::size_t kJournalSize = 76;
// The seal, after the journal: u32 key id, u32 1 when sealed, u64 freshness, u64 newest, and
// the first 24 bytes of the HMAC-SHA-256 of its domain, the store's identity and the copy's
// bytes before the MAC.
constexpr std::size_t kJournalSealKeyIdOffset = 0;
constexpr std::size_t kJournalSealSealedOffset = 4;
constexpr std::size_t kJournalSealFreshnessOffset = 8;
constexpr std::size_t kJournalSealNewestOffset = 16;
constexpr std::size_t kJournalSealMacOffset = 24;
constexpr std::size_t kJournalSealSize = 48;
constexpr std::size_t kJournalCopySize = kJournalSize + kJournalSealSize;
constexpr std::size_t kJournalEnd = kJournalSecondCopyOffset + kJournalCopySize;
// The single journal earlier versions wrote: magic, u64 unconfirmed, suspect_low, suspect_high,
// given_up_through, u32 fallbacks, CRC-32C; read only while neither copy was ever written.
constexpr std::uint64_t kLegacyJournalOffset = 64;
constexpr std::uint8_t kLegacyJournalMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'J', 'N', 'L'};
constexpr std::size_t kLegacyJournalUnconfirmedOffset = 8;
constexpr std::size_t kLegacyJournalSuspectLowOffset = 16;
constexpr std::size_t kLegacyJournalSuspectHighOffset = 24;
constexpr std::size_t kLegacyJournalGivenUpThroughOffset = 32;
constexpr std::size_t kLegacyJournalFallbacksOffset = 40;
constexpr std::size_t kLegacyJournalCrcOffset = 44;
constexpr std::size_t kLegacyJournalSize = 48;

// ---- The store's identity: two copies in the first page, each magic, 16 random bytes and the
// CRC-32C of the 24 bytes before it.
constexpr std::uint64_t kStoreIdFirstCopyOffset = 400;
constexpr std::uint64_t kStoreIdSecondCopyOffset = 432;
constexpr std::uint8_t kStoreIdMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'S', 'I', 'D'};
constexpr std::size_t kStoreIdSize = 16;
constexpr std::size_t kStoreIdCrcOffset = 8 + kStoreIdSize;
constexpr std::size_t kStoreIdCopySize = kStoreIdCrcOffset + 4;

// ---- The freshness counter file: two copies, each magic, u32 key id, u32 0, u64 value, the
// store's identity, then the HMAC-SHA-256 of its domain, the identity and the bytes before it.
constexpr std::size_t kCounterFileSize = 256;
constexpr std::uint64_t kCounterFirstCopyOffset = 0;
constexpr std::uint64_t kCounterSecondCopyOffset = 128;
constexpr std::uint8_t kCounterMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'C', 'T', 'R'};
constexpr std::size_t kCounterKeyIdOffset = 8;
constexpr std::size_t kCounterReservedOffset = 12;
constexpr std::size_t kCounterValueOffset = 16;
constexpr std::size_t kCounterStoreIdOffset = 24;
constexpr std::size_t kCounterMacOffset = kCounterStoreIdOffset + kStoreIdSize;  // signed: before
constexpr std::size_t kCounterCopySize = kCounterMacOffset + 32;                 // HMAC-SHA-256

static_assert(kStoreVersionOffset == 8 && kStoreSlotCountOffset == 12 &&
                  kStoreSlotSizeOffset == 16 && kStoreSchemaAreaSizeOffset == 20 &&
                  kStoreSlotsOffsetOffset == 24 && kStoreHeaderCrcOffset == 32 &&
                  kStoreHeaderCrcOffset + 4 == kStoreHeaderSize,
              "store header of docs/format.md §4");
static_assert(kStoreAreaSizeOffset == 8 && kStoreAreaCrcOffset == 12 &&
                  kStoreAreaCrcOffset + 4 == kStoreAreaHeaderSize,
              "schema area header of docs/format.md §4");
static_assert(kStoreMinSlotSize == 112, "docs/format.md §4: a slot holds at least 112 bytes");
static_assert(kStoreHeaderSize <= kLegacyJournalOffset &&
                  kLegacyJournalOffset + kLegacyJournalSize <= kJournalFirstCopyOffset &&
                  kJournalFirstCopyOffset + kJournalCopySize <= kJournalSecondCopyOffset &&
                  kJournalEnd <= kStoreIdFirstCopyOffset && kJournalEnd <= 512 &&
                  kStoreIdFirstCopyOffset + kStoreIdCopySize <= kStoreIdSecondCopyOffset &&
                  kStoreIdSecondCopyOffset + kStoreIdCopySize <= kStorePageSize,
              "the first page of docs/format.md §4: header, journals, identity, apart");
static_assert(kJournalCrcOffset + 4 == kJournalSize && kJournalSize == 76 &&
                  kJournalSealMacOffset + 24 == kJournalSealSize && kJournalEnd == 380,
              "restore journal of docs/format.md §4: bytes 128-251 and 256-379");
static_assert(kLegacyJournalCrcOffset + 4 == kLegacyJournalSize,
              "the earlier versions' journal of docs/format.md §4");
static_assert(kStoreIdCopySize == 28 && kStoreIdSecondCopyOffset + kStoreIdCopySize == 460,
              "identity of docs/format.md §4: bytes 400-427 and 432-459");
static_assert(kCounterMacOffset == 40 && kCounterSecondCopyOffset >= kCounterCopySize &&
                  kCounterSecondCopyOffset + kCounterCopySize <= kCounterFileSize,
              "freshness counter file of docs/format.md §4");

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_STORE_HPP
