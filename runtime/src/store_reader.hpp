// A read-only view of a checkpoint store (docs/format.md §4) for tools: the geometry, both
// schema areas and every slot's state, without a live Schema, without a lock (the program may
// be running and saving) and without ever writing. Torn reads of a slot being written show up
// as checksum failures, as they would for restore_latest().
#ifndef SYMCR_SRC_STORE_READER_HPP
#define SYMCR_SRC_STORE_READER_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine.hpp"
#include "record.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

inline constexpr std::uint8_t kStoreFileMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'S', 'T', 'O'};
inline constexpr std::uint16_t kStoreFileFormatVersion = 1;

struct StoreGeometry {
  std::uint32_t slot_count = 0;
  std::uint32_t slot_size = 0;
  std::uint32_t schema_area_size = 0;
  std::uint64_t slots_offset = 0;
};

struct StoreSchemaArea {
  bool valid = false;      // CRC, hash and schema all hold
  std::uint64_t hash = 0;
  std::uint32_t size = 0;  // bytes of serialised schema
  ParsedSchema schema;
};

enum class StoreSlotState : std::uint8_t {
  Valid,          // the record validates and its schema area is valid
  Empty,          // never written (all-zero magic)
  Corrupt,        // torn or damaged record (problem says how)
  UnknownSchema,  // the record is intact but no valid area holds its schema
  FutureVersion,  // written by a newer record format
};
const char* store_slot_state_name(StoreSlotState state);

struct StoreSlot {
  StoreSlotState state = StoreSlotState::Empty;
  Status problem;          // why the slot is not Valid
  RecordHeader header;     // Valid and UnknownSchema: the record's header
  int area = -1;           // Valid: the schema area its record references
};

class StoreReader {
 public:
  StoreReader() = default;
  ~StoreReader();
  StoreReader(const StoreReader&) = delete;
  StoreReader& operator=(const StoreReader&) = delete;

  // Opens `path` read-only (never following a symlink), validates the store header and the
  // file size, loads both schema areas and classifies every slot.
  Status open(const char* path);

  const StoreGeometry& geometry() const { return geometry_; }
  const StoreSchemaArea& area(int index) const { return areas_[index]; }
  const std::vector<StoreSlot>& slots() const { return slots_; }

  // Valid slots, highest sequence first: the order restore_latest() tries them in.
  std::vector<std::uint32_t> valid_slots_newest_first() const;

  // Reads the record of slot `index` into `bytes`; `view` points into them and `area` is the
  // schema area it references. Fails unless the slot (still) validates.
  Status read_record(std::uint32_t index, std::vector<std::uint8_t>& bytes, RecordView& view,
                     int& area) const;

 private:
  Status load_area(int index);
  Status classify_slot(std::uint32_t index, std::vector<std::uint8_t>& bytes, RecordView& view,
                       StoreSlot& slot) const;

  int fd_ = -1;
  std::string path_;
  StoreGeometry geometry_;
  StoreSchemaArea areas_[2];
  std::vector<StoreSlot> slots_;
};

// True when `data` (at least 8 bytes) starts like a store rather than a record.
bool looks_like_store(const std::uint8_t* data, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_STORE_READER_HPP
