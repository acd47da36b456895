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

#include "authentication.hpp"
#include "record.hpp"
#include "restore_journal.hpp"
#include "store_layout.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

struct StoreSlot {
  StoreSlotState state = StoreSlotState::Empty;
  Status problem;       // why the slot is not Valid
  RecordHeader header;  // Valid and UnknownSchema: the record's header
  int area = -1;        // Valid: the schema area its record references
};

class StoreReader {
 public:
  StoreReader() = default;
  ~StoreReader();
  StoreReader(const StoreReader&) = delete;
  StoreReader& operator=(const StoreReader&) = delete;

  // Opens `path` read-only (never following a symlink), reads the store header (a damaged one:
  // the checkpoints are found by scanning, see salvaged()), loads both schema areas and
  // classifies every slot (those past the end of a truncated file read as
  // empty, as for a program). With keys set (set_checkpoint_keys), the journal counts only when
  // its MAC verifies for this store and it is not older than the journal the newest
  // authenticated checkpoint was saved under (an older copy put back). With keys, a store that
  // lost both copies of its identity takes it back from its counter file (`counter_path`, else
  // the default `<path>.fresh`) when a checkpoint verifies under it, as a program's open does.
  Status open(const char* path, const char* counter_path = nullptr);

  // All zero for a store whose header is damaged: then salvaged() says how its checkpoints
  // were found (by scanning, as a program's open finds them), else it is empty.
  const StoreGeometry& geometry() const { return geometry_; }
  const std::string& salvaged() const { return salvaged_; }
  const std::string& path() const { return path_; }
  const StoreSchemaArea& area(int index) const { return areas_[index]; }
  const std::vector<StoreSlot>& slots() const { return slots_; }
  // The crash-loop fallback's journal as the store holds it (empty when it has none, or, with
  // keys set, when it is not trusted: then journal_distrust() says why).
  const RestoreJournal& journal() const { return journal_; }
  const std::string& journal_distrust() const { return journal_distrust_; }
  // The store's identity (all zero when it has none) and what a record in slot `index`, of
  // schema area `area`, is bound to.
  const std::uint8_t* store_id() const { return store_id_; }
  RecordBinding binding(std::uint32_t index, int area) const;
  // The freshness check of restore_latest() (keys set) against `counter_value`, given the
  // slots whose MAC verified (`authentic`, per slot): RolledBack when the newest of them and
  // the journal are older.
  Status check_freshness(std::uint64_t counter_value, const std::vector<bool>& authentic) const;
  // The highest sequence an intact record (restorable or not) holds or the journal names: what
  // a start that opens the store takes as its newest sequence.
  std::uint64_t highest_known_sequence() const;
  // The journal as the program's next start applies it before it chooses a slot: a restore
  // still unconfirmed (the program crashed, or stopped, or has not confirmed yet) counts as a
  // crash (RestoreJournal::count_crash) at the fallback depth the journal records, which may
  // give up on every checkpoint. `counts_crash`: whether a crash is counted.
  RestoreJournal journal_at_next_start(bool* counts_crash = nullptr) const;

  // Valid slots, highest sequence first: the order restore_latest() tries them in.
  std::vector<std::uint32_t> valid_slots_newest_first() const;

  // Reads the record of slot `index` into `bytes`; `view` points into them and `area` is the
  // schema area it references. Fails unless the slot (still) validates.
  Status read_record(std::uint32_t index, std::vector<std::uint8_t>& bytes, RecordView& view,
                     int& area) const;

 private:
  Status classify_slot(std::uint32_t index, std::vector<std::uint8_t>& bytes, RecordView& view,
                       StoreSlot& slot) const;
  // A header that does not decode (`header_problem`): the checkpoints found by scanning.
  Status salvage(std::uint64_t file_size, const Status& header_problem);
  // Slot `index` is valid and its record (read into `bytes`, `view`) verifies with `keys`.
  bool authentic(std::uint32_t index, const KeyRing& keys, std::vector<std::uint8_t>& bytes,
                 RecordView& view) const;
  // The journal freshness the newest checkpoint that verifies with `keys` was saved under.
  std::uint64_t newest_authentic_journal(const KeyRing& keys) const;
  // For a store whose identity copies are both lost: the identity the counter file names under
  // a MAC that verifies, if a checkpoint verifies under it (else the identity stays all zero).
  void identity_from_counter(const char* counter_path, const KeyRing& keys);

  int fd_ = -1;
  std::string path_;
  StoreGeometry geometry_;
  std::string salvaged_;
  std::vector<std::uint64_t> slot_offsets_;  // per slot: where it lies, and its size
  std::vector<std::uint32_t> slot_capacities_;
  StoreSchemaArea areas_[2];
  std::vector<StoreSlot> slots_;
  RestoreJournal journal_;
  std::string journal_distrust_;
  std::uint8_t store_id_[kStoreIdSize] = {};
};

}  // namespace symcr::detail

#endif  // SYMCR_SRC_STORE_READER_HPP
