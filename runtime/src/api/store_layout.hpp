// The store file's layout (docs/format.md §4; its constants are the format core's,
// symcr/format/store.hpp), written once for the writing Store and the read-only StoreReader: the
// header, the two schema areas, reading and classifying one slot, and finding the checkpoints of a
// store whose header is damaged. Internal to the runtime.
#ifndef SYMCR_SRC_STORE_LAYOUT_HPP
#define SYMCR_SRC_STORE_LAYOUT_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "parsed_schema.hpp"
#include "record.hpp"
#include "symcr/format/store.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

struct StoreGeometry {
  std::uint32_t slot_count = 0;
  std::uint32_t slot_size = 0;
  std::uint32_t schema_area_size = 0;
  std::uint64_t slots_offset = 0;

  std::uint64_t area_offset(int area) const {
    return format::kStorePageSize + static_cast<std::uint64_t>(area) * schema_area_size;
  }
  std::uint64_t slot_offset(std::uint32_t slot) const {
    return slots_offset + static_cast<std::uint64_t>(slot) * slot_size;
  }
  std::uint64_t file_size() const { return slot_offset(slot_count); }
};

// The geometry of a new store: `slots` × `slot_size`, with schema areas four times the
// creating build's schema (at least 64 KiB), leaving room for later builds' larger schemas.
StoreGeometry store_geometry_for(std::uint32_t slots, std::uint32_t slot_size,
                                 std::size_t schema_bytes);
// TooLarge unless `slots` and `slot_size` are within the format's bounds.
Status check_store_dimensions(std::uint32_t slots, std::uint32_t slot_size);

void encode_store_header(const StoreGeometry& geometry,
                         std::uint8_t* out);  // format::kStoreHeaderSize
// Decodes the first `size` bytes of a store: magic, version, CRC and geometry.
Status decode_store_header(const std::uint8_t* data, std::size_t size, const char* path,
                           StoreGeometry& out);

// The SHA-256 of a schema's serialised bytes, what a record's MAC binds, computed at the first
// use and then kept: only a store with keys set needs it, and hashing a schema costs several
// times all the rest of opening a store. Like the Store that holds it, not for concurrent use.
class LazySchemaDigest {
 public:
  // The digest of `bytes` (`size` of them): the same bytes at every call.
  const std::uint8_t* of(const std::uint8_t* bytes, std::size_t size) const;

 private:
  mutable bool known_ = false;
  mutable std::uint8_t digest_[32] = {};
};

struct StoreSchemaArea {
  bool valid = false;  // CRC, hash and schema all hold
  std::uint64_t hash = 0;
  std::uint32_t size = 0;  // bytes of serialised schema
  // The area's schema: the opening build's own when the area holds exactly its serialised form
  // (then nothing is parsed), else parsed and shared with the plans built from it, which may
  // outlive the store.
  const Schema* own = nullptr;
  std::shared_ptr<const ParsedSchema> parsed;
  const Schema& schema() const { return own ? *own : parsed->schema(); }
  // SHA-256 of the schema's bytes (a valid area's only), computed at the first call.
  const std::uint8_t* digest() const;

  LazySchemaDigest lazy_digest;
};
// Loads the schema area at `offset` holding at most `capacity` bytes (its header included).
// A damaged or empty area is loaded as not valid; only an I/O error is a failure. `own`, if
// given, is the opening build's schema, recognised by its bytes instead of parsed.
Status load_store_area(int fd, const char* path, std::uint64_t offset, std::uint64_t capacity,
                       const Schema* own, StoreSchemaArea& area);

enum class StoreSlotState : std::uint8_t {
  Valid,          // the record validates and its schema area is valid
  Empty,          // never written (all-zero magic), or past the end of a truncated file
  Corrupt,        // torn or damaged record
  UnknownSchema,  // the record is intact but no valid area holds its schema
  FutureVersion,  // written by a newer record format
  // Valid, but its MAC is missing or does not verify with the program's keys (for its store,
  // its slot and its schema): with keys set, every scan checks every slot's MAC, so that an
  // unauthenticated slot never counts.
  Unauthenticated,
};
const char* store_slot_state_name(StoreSlotState state);

struct StoreSlotRead {
  StoreSlotState state = StoreSlotState::Empty;
  int area = -1;  // Valid: the schema area its record references
};

// Reads the record in the slot at `offset` (at most `capacity` bytes: the slot size) into
// `buffer`, grown only when it is smaller than the record (a buffer of the slot size is never
// reallocated), and classifies it against `areas` (two). `view` describes the record when it
// parsed; `problem`, when given, says why the slot is not Valid. One pread for a record of up
// to a page.
Status read_store_slot(int fd, const char* path, std::uint64_t offset, std::uint32_t capacity,
                       const StoreSchemaArea* areas, std::vector<std::uint8_t>& buffer,
                       RecordView& view, StoreSlotRead& out, Status* problem = nullptr);

// What could be found of a store whose header is damaged (zeroed, torn, overwritten): the
// records that validate, wherever they are in the file, and the schema areas they reference.
struct StoreSalvage {
  std::vector<std::uint64_t> record_offsets;  // ascending
  std::vector<std::uint32_t> record_sizes;
  StoreSchemaArea areas[2];
  std::uint64_t area_offsets[2] = {0, 0};
  std::uint64_t area_capacities[2] = {0, 0};
};
// Scans the file (`file_size` bytes) for records and schema areas. Reads only.
Status salvage_store(int fd, const char* path, std::uint64_t file_size, StoreSalvage& out);
// True when `geometry` places every salvaged record at a slot, its areas where they were found
// and exactly fills `file_size`: the geometry the store was created with, as far as its bytes
// can tell, and safe to write into a new header.
bool salvage_fits_geometry(const StoreSalvage& salvage, const StoreGeometry& geometry,
                           std::uint64_t file_size);

// True when `data` (at least 8 bytes) starts like a store rather than a record.
bool looks_like_store(const std::uint8_t* data, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_STORE_LAYOUT_HPP
