// The store file's layout (store_layout.hpp, docs/format.md §4).
#include "store_layout.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <numeric>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "file_io.hpp"
#include "parsed_schema.hpp"
#include "schema_blob.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {
namespace {

// First read of a slot: one pread covers the header and a record of up to a page.
constexpr std::size_t kSlotFirstRead = 4096;
// The salvage scan reads the file in pieces of this size.
constexpr std::size_t kSalvageChunk = 1 << 20;

bool all_zero(const std::uint8_t* p, std::size_t n) {
  return std::all_of(p, p + n, [](std::uint8_t b) { return b == 0; });
}

std::uint64_t round_up_to_page(std::uint64_t n) {
  return (n + format::kStorePageSize - 1) / format::kStorePageSize * format::kStorePageSize;
}

// The size a record header claims for its whole record.
std::uint64_t claimed_record_size(const std::uint8_t* header) {
  return std::uint64_t{format::load16(header + format::kRecordHeaderSizeOffset)} +
         format::load32(header + format::kRecordSchemaSizeOffset) +
         format::load32(header + format::kRecordPayloadSizeOffset);
}

}  // namespace

StoreGeometry store_geometry_for(std::uint32_t slots, std::uint32_t slot_size,
                                 std::size_t schema_bytes) {
  StoreGeometry g;
  g.slot_count = slots;
  g.slot_size = slot_size;
  const std::uint64_t wanted = 4 * (format::kStoreAreaHeaderSize + std::uint64_t{schema_bytes});
  g.schema_area_size = static_cast<std::uint32_t>(
      round_up_to_page(std::max<std::uint64_t>(format::kStoreMinSchemaAreaSize, wanted)));
  g.slots_offset = format::kStorePageSize + 2 * std::uint64_t{g.schema_area_size};
  return g;
}

Status check_store_dimensions(std::uint32_t slots, std::uint32_t slot_size) {
  if (slots < 2 || slots > format::kStoreMaxSlots) {
    return Status(Error::TooLarge, "a store needs 2 to %u slots, not %u", format::kStoreMaxSlots,
                  slots);
  }
  if (slot_size < format::kStoreMinSlotSize || slot_size > format::kStoreMaxSlotSize) {
    return Status(Error::TooLarge, "a store slot must have %u to %u bytes, not %u",
                  format::kStoreMinSlotSize, format::kStoreMaxSlotSize, slot_size);
  }
  return Status();
}

void encode_store_header(const StoreGeometry& geometry, std::uint8_t* out) {
  std::memset(out, 0, format::kStoreHeaderSize);
  std::memcpy(out, format::kStoreFileMagic, sizeof format::kStoreFileMagic);
  format::store16(out + format::kStoreVersionOffset, format::kStoreFileFormatVersion);
  format::store32(out + format::kStoreSlotCountOffset, geometry.slot_count);
  format::store32(out + format::kStoreSlotSizeOffset, geometry.slot_size);
  format::store32(out + format::kStoreSchemaAreaSizeOffset, geometry.schema_area_size);
  format::store64(out + format::kStoreSlotsOffsetOffset, geometry.slots_offset);
  format::store32(out + format::kStoreHeaderCrcOffset, crc32c(out, format::kStoreHeaderCrcOffset));
}

Status decode_store_header(const std::uint8_t* data, std::size_t size, const char* path,
                           StoreGeometry& out) {
  if (size < sizeof format::kStoreFileMagic || std::memcmp(data, format::kStoreFileMagic, 8) != 0) {
    return Status(Error::NotACheckpoint, "%s is not a symcr store (bad magic)", path);
  }
  if (size < format::kStoreHeaderSize)
    return Status(Error::Truncated, "%s: store header truncated", path);
  const std::uint16_t version = format::load16(data + format::kStoreVersionOffset);
  if (version > format::kStoreFileFormatVersion) {
    return Status(Error::FutureVersion,
                  "%s was written by store format version %u; this build reads up to %u", path,
                  unsigned{version}, unsigned{format::kStoreFileFormatVersion});
  }
  if (format::load32(data + format::kStoreHeaderCrcOffset) !=
      crc32c(data, format::kStoreHeaderCrcOffset)) {
    return Status(Error::Checksum, "%s: store header checksum mismatch", path);
  }
  out.slot_count = format::load32(data + format::kStoreSlotCountOffset);
  out.slot_size = format::load32(data + format::kStoreSlotSizeOffset);
  out.schema_area_size = format::load32(data + format::kStoreSchemaAreaSizeOffset);
  out.slots_offset = format::load64(data + format::kStoreSlotsOffsetOffset);
  if (version == 0 || !check_store_dimensions(out.slot_count, out.slot_size).ok() ||
      out.schema_area_size <= format::kStoreAreaHeaderSize ||
      out.schema_area_size % format::kStorePageSize != 0 ||
      out.slots_offset != format::kStorePageSize + 2 * std::uint64_t{out.schema_area_size}) {
    return Status(Error::Corrupt, "%s: invalid store header", path);
  }
  return Status();
}

Status load_store_area(int fd, const char* path, std::uint64_t offset, std::uint64_t capacity,
                       const Schema* own, StoreSchemaArea& area) {
  area = StoreSchemaArea();
  std::uint8_t head[format::kStoreAreaHeaderSize];
  std::size_t got = 0;
  Status status = pread_full(fd, head, sizeof head, static_cast<off_t>(offset), got, path);
  if (!status.ok()) return status;
  const std::uint32_t size = format::load32(head + format::kStoreAreaSizeOffset);
  if (got < sizeof head || size == 0 || capacity < format::kStoreAreaHeaderSize ||
      size > capacity - format::kStoreAreaHeaderSize) {
    return Status();  // empty or damaged: no schema here
  }
  std::vector<std::uint8_t> bytes(size);
  status = pread_full(fd, bytes.data(), size,
                      static_cast<off_t>(offset + format::kStoreAreaHeaderSize), got, path);
  if (!status.ok()) return status;
  const std::uint64_t hash = format::load64(head + format::kStoreAreaHashOffset);
  const std::uint32_t crc =
      crc32c_extend(crc32c(head, format::kStoreAreaCrcOffset), bytes.data(), size);
  if (got < size || crc != format::load32(head + format::kStoreAreaCrcOffset)) return Status();
  const SchemaBlob* own_blob = own ? &schema_blob(*own) : nullptr;
  if (own_blob && own_blob->hash == hash && own_blob->size == size &&
      std::memcmp(own_blob->data, bytes.data(), size) == 0) {
    area.own = own;  // the bytes are the blob the hash was computed over: nothing to check
  } else {
    auto parsed = std::make_shared<ParsedSchema>();
    if (format::fnv1a64(bytes.data(), size) != hash ||
        !parse_schema(bytes.data(), size, *parsed, &hash).ok()) {
      return Status();
    }
    area.parsed = std::move(parsed);
  }
  area.valid = true;
  area.hash = hash;
  area.size = size;
  return Status();
}

const std::uint8_t* LazySchemaDigest::of(const std::uint8_t* bytes, std::size_t size) const {
  if (!known_) {
    schema_digest(bytes, size, digest_);
    known_ = true;
  }
  return digest_;
}

const std::uint8_t* StoreSchemaArea::digest() const {
  if (own) {
    const SchemaBlob& blob = schema_blob(*own);
    return lazy_digest.of(blob.data, blob.size);
  }
  if (!parsed) return lazy_digest.of(nullptr, 0);  // not valid: bound by no record
  const std::vector<std::uint8_t>& bytes = parsed->bytes();
  return lazy_digest.of(bytes.data(), bytes.size());
}

const char* store_slot_state_name(StoreSlotState state) {
  switch (state) {
    case StoreSlotState::Valid:
      return "valid";
    case StoreSlotState::Empty:
      return "empty";
    case StoreSlotState::Corrupt:
      return "corrupt";
    case StoreSlotState::UnknownSchema:
      return "unknown-schema";
    case StoreSlotState::FutureVersion:
      return "future-version";
    case StoreSlotState::Unauthenticated:
      return "unauthenticated";
  }
  return "?";
}

Status read_store_slot(int fd, const char* path, std::uint64_t offset, std::uint32_t capacity,
                       const StoreSchemaArea* areas, std::vector<std::uint8_t>& buffer,
                       RecordView& view, StoreSlotRead& out, Status* problem) {
  out = StoreSlotRead();
  const std::size_t first = std::min<std::size_t>(capacity, kSlotFirstRead);
  if (buffer.size() < first) buffer.resize(first);
  std::size_t got = 0;
  Status status = pread_full(fd, buffer.data(), first, static_cast<off_t>(offset), got, path);
  if (!status.ok()) return status;
  if (got < format::kRecordHeaderSize || all_zero(buffer.data(), 8)) {
    // Never written, or cut off by a truncated file: nothing to restore either way.
    if (got > 0 && !all_zero(buffer.data(), std::min<std::size_t>(got, 8))) {
      out.state = StoreSlotState::Corrupt;
      if (problem)
        *problem = Status(Error::Truncated, "the record is cut off by the end of the file");
    }
    return Status();
  }
  // Read the rest of the record when the header claims more (bounded by the slot).
  const std::size_t wanted = static_cast<std::size_t>(
      std::min<std::uint64_t>(claimed_record_size(buffer.data()), capacity));
  if (wanted > got && got == first) {
    if (buffer.size() < wanted) buffer.resize(wanted);
    std::size_t more = 0;
    status = pread_full(fd, buffer.data() + got, wanted - got, static_cast<off_t>(offset + got),
                        more, path);
    if (!status.ok()) return status;
    got += more;
  }
  const Status parsed = parse_record(buffer.data(), got, view);
  if (!parsed.ok()) {
    out.state = parsed.error() == Error::FutureVersion ? StoreSlotState::FutureVersion
                                                       : StoreSlotState::Corrupt;
    if (problem) *problem = parsed;
    return Status();
  }
  if (view.header.sequence > format::kMaxRecordSequence) {
    out.state = StoreSlotState::Corrupt;
    if (problem) {
      *problem = Status(Error::Corrupt,
                        "sequence %llu is beyond the store's range (2^63-1): damage or forgery",
                        static_cast<unsigned long long>(view.header.sequence));
    }
    return Status();
  }
  if (view.schema != nullptr) {  // store records reference their schema; never inline
    out.state = StoreSlotState::Corrupt;
    if (problem)
      *problem = Status(Error::Corrupt, "a store slot's record carries an inline schema");
    return Status();
  }
  for (int i = 0; i < 2; ++i) {
    if (areas[i].valid && areas[i].hash == view.header.schema_hash) out.area = i;
  }
  if (out.area < 0) {
    out.state = StoreSlotState::UnknownSchema;
    if (problem) {
      *problem = Status(Error::SchemaUnknown, "schema %016llx is in neither schema area",
                        static_cast<unsigned long long>(view.header.schema_hash));
    }
    return Status();
  }
  out.state = StoreSlotState::Valid;
  return Status();
}

Status salvage_store(int fd, const char* path, std::uint64_t file_size, StoreSalvage& out) {
  out = StoreSalvage();
  // Records: every place the record magic starts a record whose checksum holds. The scan
  // resumes after a record found, so a checkpoint held as data inside another is not taken.
  // The scan ends where the largest store the records found could belong to ends: slots are
  // one slot size apart, so the slot size divides the distance between any two records found,
  // and a store has at most format::kStoreMaxSlots slots. Holes in a sparse file (zeros, no record)
  // are skipped without reading them.
  std::vector<std::uint8_t> chunk(kSalvageChunk);
  std::vector<std::uint8_t> record;
  RecordView view;
  std::uint64_t position = format::kStorePageSize;
  std::uint64_t end = file_size;
  std::uint64_t spacing = 0;  // the greatest common divisor of the records' distances
  while (position + format::kRecordHeaderSize <= end) {
    const off_t data = ::lseek(fd, static_cast<off_t>(position), SEEK_DATA);
    if (data < 0 && errno == ENXIO) break;  // only a hole from here on
    if (data > 0 && static_cast<std::uint64_t>(data) > position) {
      position = static_cast<std::uint64_t>(data);
      continue;
    }
    std::size_t got = 0;
    Status status =
        pread_full(fd, chunk.data(), chunk.size(), static_cast<off_t>(position), got, path);
    if (!status.ok()) return status;
    if (got < sizeof format::kRecordMagic) break;
    const std::uint8_t* hit = static_cast<const std::uint8_t*>(
        ::memmem(chunk.data(), got, format::kRecordMagic, sizeof format::kRecordMagic));
    if (hit == nullptr) {
      position += got - (sizeof format::kRecordMagic - 1);  // a magic may straddle two pieces
      continue;
    }
    const std::uint64_t offset = position + static_cast<std::uint64_t>(hit - chunk.data());
    std::uint8_t header[format::kRecordHeaderSize];
    status = pread_full(fd, header, sizeof header, static_cast<off_t>(offset), got, path);
    if (!status.ok()) return status;
    const std::uint64_t claimed = got == sizeof header ? claimed_record_size(header) : 0;
    bool found = false;
    if (claimed >= format::kRecordHeaderSize && claimed <= format::kStoreMaxSlotSize &&
        offset + claimed <= file_size) {
      record.resize(static_cast<std::size_t>(claimed));
      status = pread_full(fd, record.data(), record.size(), static_cast<off_t>(offset), got, path);
      if (!status.ok()) return status;
      found = got == record.size() && parse_record(record.data(), got, view).ok() &&
              view.schema == nullptr;
    }
    if (found) {
      if (!out.record_offsets.empty()) {
        spacing = std::gcd(spacing, offset - out.record_offsets.front());
      }
      out.record_offsets.push_back(offset);
      out.record_sizes.push_back(static_cast<std::uint32_t>(view.record_size));
      const std::uint64_t slot_size_bound =
          spacing != 0 ? std::min<std::uint64_t>(spacing, format::kStoreMaxSlotSize)
                       : format::kStoreMaxSlotSize;
      end = std::min(file_size,
                     out.record_offsets.front() + format::kStoreMaxSlots * slot_size_bound);
      position = offset + view.record_size;
    } else {
      position = offset + 1;
    }
  }
  // Without a record there is nothing to restore and no area to look for.
  if (out.record_offsets.empty()) return Status();
  // Schema areas: area 0 is at the first page; area 1 one area size further, at a page
  // boundary before the first slot. Candidates in a hole are skipped unread.
  const std::uint64_t areas_end = out.record_offsets.front();
  for (std::uint64_t area_size = format::kStoreMinSchemaAreaSize;
       format::kStorePageSize + 2 * area_size <= areas_end; area_size += format::kStorePageSize) {
    const std::uint64_t at = format::kStorePageSize + area_size;
    const off_t data = ::lseek(fd, static_cast<off_t>(at), SEEK_DATA);
    if (data < 0 && errno == ENXIO) break;
    if (data > 0 && static_cast<std::uint64_t>(data) > at) {
      // The first area size whose area starts at or past the data; the loop's step adds a page.
      const std::uint64_t reaching =
          (static_cast<std::uint64_t>(data) - 1) / format::kStorePageSize * format::kStorePageSize;
      area_size = reaching - format::kStorePageSize;
      continue;
    }
    StoreSchemaArea candidate;
    Status status = load_store_area(fd, path, format::kStorePageSize + area_size, area_size,
                                    nullptr, candidate);
    if (!status.ok()) return status;
    if (candidate.valid) {
      out.areas[1] = std::move(candidate);
      out.area_offsets[1] = format::kStorePageSize + area_size;
      out.area_capacities[1] = area_size;
      break;
    }
  }
  out.area_offsets[0] = format::kStorePageSize;
  out.area_capacities[0] =
      out.areas[1].valid
          ? out.area_capacities[1]
          : (areas_end > format::kStorePageSize ? areas_end - format::kStorePageSize : 0);
  return load_store_area(fd, path, out.area_offsets[0], out.area_capacities[0], nullptr,
                         out.areas[0]);
}

bool salvage_fits_geometry(const StoreSalvage& salvage, const StoreGeometry& g,
                           std::uint64_t file_size) {
  if (g.file_size() != file_size || g.slots_offset != g.area_offset(2)) return false;
  for (int i = 0; i < 2; ++i) {
    if (!salvage.areas[i].valid) continue;
    if (salvage.area_offsets[i] != g.area_offset(i) ||
        format::kStoreAreaHeaderSize + salvage.areas[i].size > g.schema_area_size) {
      return false;
    }
  }
  for (std::size_t i = 0; i < salvage.record_offsets.size(); ++i) {
    const std::uint64_t offset = salvage.record_offsets[i];
    if (offset < g.slots_offset || (offset - g.slots_offset) % g.slot_size != 0 ||
        salvage.record_sizes[i] > g.slot_size) {
      return false;
    }
  }
  return true;
}

bool looks_like_store(const std::uint8_t* data, std::size_t size) {
  return size >= sizeof format::kStoreFileMagic &&
         std::memcmp(data, format::kStoreFileMagic, sizeof format::kStoreFileMagic) == 0;
}

}  // namespace symcr::detail
