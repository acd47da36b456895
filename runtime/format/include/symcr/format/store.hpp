// The store file's fixed layout (docs/format.md §4): its header, the pages and schema areas
// before the slots, and the bounds of its geometry. The host's Store and StoreReader read and
// write it (runtime/src/api/store_layout.*); the restore journal's and identity's places in the
// first page are theirs (restore_journal.hpp, freshness.hpp).
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

static_assert(kStoreVersionOffset == 8 && kStoreSlotCountOffset == 12 &&
                  kStoreSlotSizeOffset == 16 && kStoreSchemaAreaSizeOffset == 20 &&
                  kStoreSlotsOffsetOffset == 24 && kStoreHeaderCrcOffset == 32 &&
                  kStoreHeaderCrcOffset + 4 == kStoreHeaderSize,
              "store header of docs/format.md §4");
static_assert(kStoreAreaSizeOffset == 8 && kStoreAreaCrcOffset == 12 &&
                  kStoreAreaCrcOffset + 4 == kStoreAreaHeaderSize,
              "schema area header of docs/format.md §4");
static_assert(kStoreMinSlotSize == 112, "docs/format.md §4: a slot holds at least 112 bytes");

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_STORE_HPP
