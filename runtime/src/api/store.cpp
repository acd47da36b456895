// The checkpoint store (docs/format.md §4): one preallocated file, a header page, two schema
// areas and a ring of fixed-size slots, each holding one record that references its schema by
// hash. save() is one pwrite of a whole record into the oldest slot; restore_latest() takes the
// newest slot that validates and falls back past torn or corrupt ones. The file's layout is
// store_layout.hpp's; this file decides when to create, recover, rewrite or refuse.
#include <fcntl.h>
#include <limits.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "file_io.hpp"
#include "file_system.hpp"
#include "freshness.hpp"
#include "program_schema.hpp"
#include "record.hpp"
#include "report_access.hpp"
#include "restore_journal.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "store_layout.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace symcr {
namespace {

using detail::StoreGeometry;
using detail::StoreSchemaArea;
using detail::StoreSlotState;

bool all_zero(const std::uint8_t* p, std::size_t n) {
  return std::all_of(p, p + n, [](std::uint8_t b) { return b == 0; });
}

// True when the first `size` bytes of a file are what an initialisation cut short leaves: all
// zero, or the start of a store header (its magic, or a prefix of it, then zeros or the rest).
// Such a file with no record in it is initialised again rather than refused forever.
bool interrupted_initialisation(const std::uint8_t* header, std::size_t size) {
  const std::size_t magic = std::min(size, sizeof format::kStoreFileMagic);
  std::size_t matched = 0;
  while (matched < magic && header[matched] == format::kStoreFileMagic[matched]) ++matched;
  return matched == sizeof format::kStoreFileMagic || all_zero(header + matched, size - matched);
}

bool same_dimensions(const StoreGeometry& a, const StoreGeometry& b) {
  return a.slot_count == b.slot_count && a.slot_size == b.slot_size;
}

// The geometry `options` asks for with the area size the file's bytes imply, if any: how a
// damaged header is rebuilt.
bool geometry_from_file_size(const StoreOptions& options, std::uint64_t file_size,
                             StoreGeometry& out) {
  const std::uint64_t slots_bytes = std::uint64_t{options.slots} * options.slot_size;
  if (file_size < format::kStorePageSize + slots_bytes) return false;
  const std::uint64_t areas = file_size - format::kStorePageSize - slots_bytes;
  if (areas % (2 * format::kStorePageSize) != 0 || areas / 2 < format::kStoreMinSchemaAreaSize ||
      areas / 2 > 0xFFFFFFFFull) {
    return false;
  }
  out.slot_count = options.slots;
  out.slot_size = options.slot_size;
  out.schema_area_size = static_cast<std::uint32_t>(areas / 2);
  out.slots_offset = format::kStorePageSize + areas;
  return true;
}

}  // namespace

struct Store::Impl {
  // For writing: create if absent, and fall back to read-only where the file or its file
  // system cannot be written. Every failure closes `out` (and removes a file it created).
  static Status open(const char* path, const Schema& schema, const StoreOptions& options,
                     bool writable, Store& out);
  static Status open_descriptor(const char* path, const Schema& schema, const StoreOptions& options,
                                bool writable, Store& out);

  struct Slot {
    StoreSlotState state = StoreSlotState::Empty;
    std::uint64_t sequence = 0;
    int area = -1;
    std::uint64_t offset = 0;    // of the slot in the file
    std::uint32_t capacity = 0;  // bytes a record there may have
    // Valid with keys set: the journal freshness the record was saved under.
    std::uint64_t journal_freshness = 0;
    std::string unauthenticated;  // Unauthenticated: why
  };

  std::string path;
  StoreGeometry geometry;  // the file's; unknown (zero) for a salvaged store
  StoreSchemaArea areas[2];
  std::uint64_t area_offsets[2] = {0, 0};
  int own_area = -1;  // the area holding this build's schema, once written or found
  std::vector<Slot> slots;
  // Why save() refuses; empty when it may write.
  std::string read_only_reason;
  // A geometry other than the file's that the caller asked for: applied at the next save().
  bool geometry_pending = false;
  StoreGeometry requested;

  std::vector<std::uint8_t> record;      // save(): the encoded record
  std::vector<std::uint8_t> slot_bytes;  // restore: one slot as read
  detail::RecordView view;               // of slot_bytes, when its slot is valid
  // The newest valid slot of the last scan, kept so restoring it needs no second read.
  std::vector<std::uint8_t> newest_bytes;
  detail::RecordView newest_view;
  int newest_scanned = -1;
  std::vector<std::uint32_t> newest_first;
  // The scan open() made is what the file holds: only this Store writes a store it locked, and
  // it has not saved since. The first restore_latest() then reads no slot again.
  bool scan_current = false;

  // Crash-loop fallback (restore_journal.hpp): the depth asked for, the journal as this Store
  // knows it and as the file last held it, and whether the restore it names unconfirmed is
  // this Store's own (a second restore_latest() in one run is no sign of a crash).
  std::uint32_t fallback_depth = 0;
  bool allow_unrecorded_restore = false;
  detail::RestoreJournal journal;
  detail::RestoreJournal recorded;
  bool unconfirmed_is_ours = false;
  // Per slot, during save(): whether the crash-loop fallback may still restore it.
  std::vector<std::uint8_t> needed_by_fallback;

  // Authentication and freshness (docs/threat-model.md). `keys`: the snapshot of the operation
  // under way (one per save, restore or confirm); the scan's slot states hold for `scanned_with`.
  detail::KeySnapshot keys;
  const detail::KeyRing* scanned_with = nullptr;
  const detail::KeyRing* journal_read_with = nullptr;
  std::uint8_t store_id[detail::kStoreIdSize] = {};
  // A new `store_id` not yet in the file, whose damaged copies name none (Store::open): written
  // by the first save that signs with it.
  bool store_id_unwritten = false;
  const detail::SchemaBlob* own_blob = nullptr;  // this build's schema, serialised
  detail::LazySchemaDigest own_blob_digest;
  FreshnessCounter* counter = nullptr;
  std::unique_ptr<detail::FileFreshnessCounter> own_counter;
  std::uint64_t counter_value = 0;  // the counter as last read or advanced
  // Why the journal in the file was not trusted (keys set), for the next restore's report.
  std::string journal_distrust;

  // For a store whose identity copies are both lost (keys set, the default counter file): the
  // identity its counter file names under a MAC, when a checkpoint of the store verifies under
  // it (another store's genuine counter names another), in `store_id` with the slots scanned
  // again under it; `found` says whether one was.
  Status identity_from_counter(int fd, bool& found) {
    found = false;
    std::uint8_t ids[detail::kCounterCopyCount][detail::kStoreIdSize];
    const std::size_t count = keys && own_counter ? own_counter->store_ids(ids) : 0;
    if (count == 0) return Status();
    std::uint8_t drawn[detail::kStoreIdSize];
    std::memcpy(drawn, store_id, sizeof drawn);
    for (std::size_t i = 0; i < count && !found; ++i) {
      std::memcpy(store_id, ids[i], sizeof store_id);
      const Status status = scan_slots(fd);
      if (!status.ok()) return status;
      for (const Slot& slot : slots) found = found || slot.state == StoreSlotState::Valid;
    }
    if (!found) {
      std::memcpy(store_id, drawn, sizeof store_id);
      const Status status = scan_slots(fd);
      if (!status.ok()) return status;
    }
    own_counter->use_store_id(store_id);
    return Status();
  }

  // Writes both copies of `store_id` into the header page, synced.
  Status write_store_id(int fd) {
    std::uint8_t id_copy[detail::kStoreIdBlockSize];
    detail::encode_store_id(store_id, id_copy);
    Status status = detail::pwrite_all(fd, id_copy, sizeof id_copy,
                                       static_cast<off_t>(detail::kStoreIdOffset), path.c_str());
    if (status.ok() && detail::file_system().fdatasync(fd) != 0) {
      status = detail::io_error("cannot fdatasync", path.c_str(), errno);
    }
    if (status.ok()) store_id_unwritten = false;
    return status;
  }

  void take_keys() {
    keys = detail::current_keys();
    if (own_counter) own_counter->use_keys(keys.get());
  }

  detail::JournalSeal journal_seal() const {
    detail::JournalSeal seal;
    seal.keys = keys.get();
    seal.store_id = store_id;
    return seal;
  }

  // Advances the counter to `value` (keys set), keeping `counter_value` in step.
  Status advance_counter(std::uint64_t value) {
    if (!keys || counter == nullptr) return Status();
    Status status = counter->advance(value);
    if (!status.ok()) {
      return Status(status.error(), "%s: the freshness counter was not advanced to %llu: %s",
                    path.c_str(), static_cast<unsigned long long>(value), status.message());
    }
    counter_value = std::max(counter_value, value);
    return Status();
  }

  // With keys set: RolledBack unless the store is as fresh as its counter (freshness_verdict;
  // the crash-loop fallback may then still restore an older checkpoint, as the authenticated
  // journal directs).
  Status check_freshness() {
    if (!keys || counter == nullptr) return Status();
    const std::uint64_t newest = newest_authentic_sequence();
    std::uint64_t counted = 0;
    Status read = counter->read(counted);
    if (!read.ok()) {
      if (newest == 0 && journal.freshness == 0) return Status();  // nothing to roll back
      return Status(read.error() == Error::Io ? Error::Io : Error::RolledBack,
                    "%s: %s, and the store holds authenticated checkpoints, so their freshness "
                    "cannot be told: nothing restored (the next save sets the counter again)",
                    path.c_str(), read.message());
    }
    counter_value = std::max(counter_value, counted);
    return freshness_against(counted);
  }

  // The sequences of the authenticated (with keys set: every Valid) slots.
  std::vector<std::uint64_t> authentic_sequences() const {
    std::vector<std::uint64_t> sequences;
    for (const Slot& slot : slots) {
      if (slot.state == StoreSlotState::Valid) sequences.push_back(slot.sequence);
    }
    return sequences;
  }
  // Whether every slot is empty: nothing was ever saved (or all of it is past a truncation).
  bool holds_no_record() const {
    for (const Slot& slot : slots) {
      if (slot.state != StoreSlotState::Empty) return false;
    }
    return true;
  }

  std::uint64_t newest_authentic_sequence() const {
    const std::vector<std::uint64_t> sequences = authentic_sequences();
    return sequences.empty() ? 0 : *std::max_element(sequences.begin(), sequences.end());
  }
  // restore_latest()'s freshness rule for the store as this Store sees it.
  Status freshness_against(std::uint64_t counted) const {
    const std::vector<std::uint64_t> sequences = authentic_sequences();
    const std::uint64_t newest =
        sequences.empty() ? 0 : *std::max_element(sequences.begin(), sequences.end());
    return detail::freshness_verdict(path.c_str(), newest,
                                     detail::newest_allowed(sequences, journal), journal, counted);
  }

  // Reads the journal as empty, `why` it is not trusted, keeping `floor` as its freshness: the
  // checkpoints saved from now on carry it, so that the distrusted journal put back again is
  // still older than they were saved under (an empty journal excludes nothing, so ignoring one
  // never restores an older state).
  void distrust_journal(const char* why, std::uint64_t floor) {
    journal_distrust = why;
    const std::uint64_t generation = recorded.generation;
    journal = detail::RestoreJournal();
    journal.generation = generation;
    journal.freshness = floor;
    recorded = journal;
  }

  // With keys set, a journal older than the one the newest authenticated checkpoint was saved
  // under is an older copy put back.
  void distrust_stale_journal() {
    if (!keys) return;
    std::uint64_t newest = 0, saved_under = 0;
    for (const Slot& slot : slots) {
      if (slot.state == StoreSlotState::Valid && slot.sequence > newest) {
        newest = slot.sequence;
        saved_under = slot.journal_freshness;
      }
    }
    if (const char* why = detail::stale_journal_reason(journal, saved_under)) {
      // One that holds nothing: only its freshness is raised, with no warning.
      const bool held_nothing = journal.empty();
      distrust_journal(why, saved_under);
      if (held_nothing) journal_distrust.clear();
    }
  }

  // Records `journal` in the header page, unless that is what the file already holds: in both
  // copies, with one write (both lie in the file's first sector). Cut short, in address order,
  // that write leaves one copy of the previous journal or of the new one; and one copy damaged
  // later leaves the current journal in the other.
  // With keys set, the journal is sealed with a MAC and a freshness value above every
  // sequence and value before it, and the counter is advanced to that value once it is written.
  Status write_journal(int fd, Durability durability) {
    if (journal.same_state(recorded)) return Status();
    journal.generation = recorded.generation + 1;
    if (keys) {
      const std::uint64_t fresh =
          std::max({highest_known_sequence(), counter_value, recorded.freshness}) + 1;
      if (fresh > format::kMaxRecordSequence) {
        return Status(Error::Corrupt,
                      "%s: the store's sequence numbers are exhausted (its journal would be "
                      "numbered past 2^63 - 1, which only damage or forgery produce); nothing "
                      "was written: save into a new store",
                      path.c_str());
      }
      journal.freshness = fresh;
      journal.newest = detail::newest_allowed(authentic_sequences(), journal);
    } else {
      journal.freshness = 0;
      journal.newest = 0;
    }
    const detail::JournalSeal seal = journal_seal();
    constexpr std::uint64_t kFirst = detail::kRestoreJournalOffsets[0];
    std::uint8_t bytes[detail::kRestoreJournalEnd - kFirst] = {};
    for (const std::uint64_t copy : detail::kRestoreJournalOffsets) {
      detail::encode_restore_journal(journal, bytes + (copy - kFirst), &seal);
    }
    Status status =
        detail::pwrite_all(fd, bytes, sizeof bytes, static_cast<off_t>(kFirst), path.c_str());
    if (status.ok() && durability == Durability::Fdatasync &&
        detail::file_system().fdatasync(fd) != 0) {
      status = detail::io_error("cannot fdatasync", path.c_str(), errno);
    }
    if (!status.ok()) return status;
    recorded = journal;
    journal_distrust.clear();
    return advance_counter(journal.freshness);
  }

  // The slots no restore could use, for the report (a slot found unauthenticated is listed
  // where the restore came to it).
  void list_unrestorable_slots(std::vector<SkippedCheckpoint>& skipped) const {
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      const char* reason = nullptr;
      switch (slots[i].state) {
        case StoreSlotState::Corrupt:
          reason = "torn or corrupt: its record does not validate";
          break;
        case StoreSlotState::UnknownSchema:
          reason = "its schema is in neither schema area (a later build overwrote it)";
          break;
        case StoreSlotState::FutureVersion:
          reason = "written by a newer record format";
          break;
        case StoreSlotState::Unauthenticated:
          reason = slots[i].unauthenticated.c_str();
          break;
        default:
          break;
      }
      if (reason != nullptr) skipped.push_back(SkippedCheckpoint{i, 0, reason});
    }
  }

  // `page`: the first `size` bytes of the file.
  // With keys set, only a journal whose seal verifies for this store is adopted.
  void adopt_journal(const std::uint8_t* page, std::size_t size) {
    const detail::JournalSeal seal = journal_seal();
    journal_read_with = keys.get();
    journal_distrust.clear();
    journal = page != nullptr ? detail::read_restore_journal(page, size, &seal, &journal_distrust)
                              : detail::RestoreJournal();
    recorded = journal;
  }

  Status read_journal(int fd) {
    std::uint8_t page[detail::kStoreHeaderPageRead] = {};
    std::size_t got = 0;
    Status status = detail::pread_full(fd, page, sizeof page, 0, got, path.c_str());
    if (status.ok()) adopt_journal(page, got);
    return status;
  }

  // The highest sequence the store holds (in any record that is intact, restorable or not) or
  // its journal names: a new checkpoint is numbered above it.
  std::uint64_t highest_known_sequence() const {
    std::uint64_t highest = std::max(journal.highest_sequence(), journal.freshness);
    for (const Slot& slot : slots) highest = std::max(highest, slot.sequence);
    return highest;
  }

  // Marks in `needed_by_fallback` the checkpoints the crash-loop fallback may still restore
  // while a restore waits for confirm(): the restored one, and the newest valid ones older than
  // it that the journal does not exclude, one for each fallback the depth still allows.
  // Returns how many it marked.
  std::uint32_t mark_fallback_needs() {
    needed_by_fallback.assign(slots.size(), 0);
    if (fallback_depth == 0 || journal.unconfirmed == 0) return 0;
    std::uint32_t marked = 0;
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      if (slots[i].state == StoreSlotState::Valid && slots[i].sequence == journal.unconfirmed) {
        needed_by_fallback[i] = 1;
        ++marked;
      }
    }
    std::uint64_t below = journal.unconfirmed;
    for (std::uint32_t level = journal.fallbacks; level < fallback_depth; ++level) {
      int next = -1;
      for (std::uint32_t i = 0; i < slots.size(); ++i) {
        const Slot& slot = slots[i];
        if (slot.state == StoreSlotState::Valid && slot.sequence < below &&
            !journal.excludes(slot.sequence) &&
            (next < 0 || slot.sequence > slots[static_cast<std::size_t>(next)].sequence)) {
          next = static_cast<int>(i);
        }
      }
      if (next < 0) break;
      needed_by_fallback[static_cast<std::size_t>(next)] = 1;
      below = slots[static_cast<std::size_t>(next)].sequence;
      ++marked;
    }
    return marked;
  }

  // The slot save() writes: one holding nothing restorable, else the oldest checkpoint the
  // journal excludes, else the oldest one the fallback does not need; -1 when every slot is
  // needed. It is never the newest valid checkpoint, unless the fallback needs every older one
  // and the newest was itself saved after a restore still waiting for confirm().
  int slot_to_overwrite() {
    mark_fallback_needs();
    int excluded = -1, oldest = -1;
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      const Slot& slot = slots[i];
      if (slot.state != StoreSlotState::Valid) return static_cast<int>(i);
      if (journal.excludes(slot.sequence)) {
        if (excluded < 0 || slot.sequence < slots[static_cast<std::size_t>(excluded)].sequence)
          excluded = static_cast<int>(i);
      } else if (!needed_by_fallback[i] &&
                 (oldest < 0 || slot.sequence < slots[static_cast<std::size_t>(oldest)].sequence)) {
        oldest = static_cast<int>(i);
      }
    }
    return excluded >= 0 ? excluded : oldest;
  }

  int area_for_hash(std::uint64_t hash) const {
    for (int i = 0; i < 2; ++i) {
      if (areas[i].valid && areas[i].hash == hash) return i;
    }
    return -1;
  }

  // The valid slot with the highest sequence, or -1.
  int newest_valid_slot() const {
    int newest = -1;
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      if (slots[i].state == StoreSlotState::Valid &&
          (newest < 0 || slots[i].sequence > slots[static_cast<std::size_t>(newest)].sequence)) {
        newest = static_cast<int>(i);
      }
    }
    return newest;
  }

  // Slots and buffers laid out by `geometry`.
  void lay_out_slots() {
    slots.assign(geometry.slot_count, Slot());
    for (std::uint32_t i = 0; i < geometry.slot_count; ++i) {
      slots[i].offset = geometry.slot_offset(i);
      slots[i].capacity = geometry.slot_size;
    }
    for (int i = 0; i < 2; ++i) area_offsets[i] = geometry.area_offset(i);
    newest_first.reserve(slots.size());
  }

  // Reads slot `i` and classifies it; when Valid, `view` describes its record in slot_bytes.
  Status read_slot(int fd, std::uint32_t i, Slot& slot) {
    detail::StoreSlotRead read;
    Status status = detail::read_store_slot(fd, path.c_str(), slots[i].offset, slots[i].capacity,
                                            areas, slot_bytes, view, read);
    if (!status.ok()) return status;
    slot.state = read.state;
    slot.area = read.area;
    slot.unauthenticated.clear();
    slot.journal_freshness = 0;
    // With keys set, only an authenticated record counts: one whose MAC (for this store, this
    // slot and its schema's bytes) does not verify is passed over and never numbered above.
    if (keys && read.state == StoreSlotState::Valid) {
      detail::RecordBinding binding;
      std::memcpy(binding.store_id, store_id, sizeof store_id);
      binding.location = slots[i].offset;
      std::memcpy(binding.schema_digest, areas[read.area].digest(), sizeof binding.schema_digest);
      const Status authenticated =
          detail::check_authentication(keys.get(), slot_bytes.data(), view, binding);
      if (!authenticated.ok()) {
        slot.state = StoreSlotState::Unauthenticated;
        slot.area = -1;
        slot.unauthenticated = authenticated.message();
      } else {
        slot.journal_freshness = view.header.journal_freshness;
      }
    }
    // An intact record of an unknown schema still holds its number: saves number above it
    // (unless keys are set: its MAC cannot be checked without its schema).
    const bool intact = read.state == StoreSlotState::Valid ||
                        (!keys && read.state == StoreSlotState::UnknownSchema);
    slot.sequence =
        intact && slot.state != StoreSlotState::Unauthenticated ? view.header.sequence : 0;
    return Status();
  }

  Status scan_slots(int fd) {
    newest_scanned = -1;
    scanned_with = keys.get();
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      Status status = read_slot(fd, i, slots[i]);
      if (!status.ok()) return status;
      if (slots[i].state == StoreSlotState::Valid &&
          (newest_scanned < 0 ||
           slots[i].sequence > slots[static_cast<std::size_t>(newest_scanned)].sequence)) {
        // Swapping vectors moves no bytes: `view` keeps pointing at the same storage.
        std::swap(slot_bytes, newest_bytes);
        newest_view = view;
        newest_scanned = static_cast<int>(i);
      }
    }
    return Status();
  }

  Status load_areas(int fd, const Schema& own) {
    for (int i = 0; i < 2; ++i) {
      Status status = detail::load_store_area(fd, path.c_str(), geometry.area_offset(i),
                                              geometry.schema_area_size, &own, areas[i]);
      if (!status.ok()) return status;
    }
    return Status();
  }

  // Writes this build's schema into the area the newest valid slot does not use, so that
  // checkpoint stays restorable, and never into one holding a checkpoint the crash-loop
  // fallback needs; slots using the overwritten area become unrestorable.
  Status write_own_area(int fd, const Schema& schema, Durability durability) {
    Status status = scan_slots(fd);  // the disk may have changed since open
    if (!status.ok()) return status;
    bool area_needed[2] = {false, false};
    mark_fallback_needs();
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      if (needed_by_fallback[i] && slots[i].area >= 0) area_needed[slots[i].area] = true;
    }
    const int newest = newest_valid_slot();
    int target = (newest >= 0 && slots[static_cast<std::size_t>(newest)].area == 0) ? 1 : 0;
    if (area_needed[target]) target = 1 - target;
    if (area_needed[target]) {
      return Status(Error::StoreFull,
                    "%s: this build's first checkpoint needs a schema area, and both hold "
                    "checkpoints the crash-loop fallback needs until confirm(); nothing was "
                    "written",
                    path.c_str());
    }
    const detail::SchemaBlob& blob = detail::schema_blob(schema);
    if (format::kStoreAreaHeaderSize + blob.size > geometry.schema_area_size) {
      return Status(Error::TooLarge,
                    "%s: this build's schema (%zu bytes) does not fit the store's schema area "
                    "(%u bytes); open a new store (a new path) for this build",
                    path.c_str(), blob.size, geometry.schema_area_size);
    }
    std::vector<std::uint8_t> area_bytes(format::kStoreAreaHeaderSize + blob.size);
    format::store64(area_bytes.data() + format::kStoreAreaHashOffset, blob.hash);
    format::store32(area_bytes.data() + format::kStoreAreaSizeOffset,
                    static_cast<std::uint32_t>(blob.size));
    std::memcpy(area_bytes.data() + format::kStoreAreaHeaderSize, blob.data, blob.size);
    format::store32(
        area_bytes.data() + format::kStoreAreaCrcOffset,
        detail::crc32c_extend(detail::crc32c(area_bytes.data(), format::kStoreAreaCrcOffset),
                              blob.data, blob.size));
    // Forget the old area before overwriting it: a failed write leaves it unusable either way.
    areas[target] = StoreSchemaArea();
    for (Slot& slot : slots) {
      if (slot.area == target) {
        slot.state = StoreSlotState::UnknownSchema;
        slot.area = -1;
      }
    }
    status = detail::pwrite_all(fd, area_bytes.data(), area_bytes.size(),
                                static_cast<off_t>(geometry.area_offset(target)), path.c_str());
    if (status.ok() && durability == Durability::Fdatasync &&
        detail::file_system().fdatasync(fd) != 0) {
      status = detail::io_error("cannot fdatasync", path.c_str(), errno);
    }
    if (!status.ok()) return status;
    areas[target].own = &schema;
    areas[target].valid = true;
    areas[target].hash = blob.hash;
    areas[target].size = static_cast<std::uint32_t>(blob.size);
    own_area = target;
    return Status();
  }

  // Zero-filled, preallocated `fd` laid out by `g`, every slot and area empty, plus `copies`
  // written into it. The header is written last, so an interrupted initialisation leaves a
  // file that reads as blank.
  struct Copy {
    std::uint64_t offset;  // in the new layout
    const std::uint8_t* bytes;
    std::size_t size;
  };
  Status initialise(int fd, const char* file, const StoreGeometry& g,
                    const std::vector<Copy>& copies) {
    detail::FileSystem& files = detail::file_system();
    if (files.ftruncate(fd, 0) != 0) return detail::io_error("cannot truncate", file, errno);
    const int rc = files.fallocate(fd, static_cast<off_t>(g.file_size()));
    if (rc != 0) return detail::io_error("cannot preallocate", file, rc);
    for (const Copy& copy : copies) {
      Status status =
          detail::pwrite_all(fd, copy.bytes, copy.size, static_cast<off_t>(copy.offset), file);
      if (!status.ok()) return status;
    }
    std::uint8_t header[format::kStoreHeaderSize];
    detail::encode_store_header(g, header);
    Status status = detail::pwrite_all(fd, header, sizeof header, 0, file);
    if (!status.ok()) return status;
    if (files.fdatasync(fd) != 0) return detail::io_error("cannot fdatasync", file, errno);
    return Status();
  }

  // Adds the journal the file holds to `copies`, both of them (encoded into `buffer`,
  // kRestoreJournalCopySize bytes, sealed with keys set): the crash-loop fallback's memory, and the
  // sequences it names, move with the store.
  void add_journal_copy(std::vector<Copy>& copies, std::uint8_t* buffer) const {
    if (recorded.empty() && recorded.freshness == 0) return;
    const detail::JournalSeal seal = journal_seal();
    detail::encode_restore_journal(recorded, buffer, &seal);
    for (const std::uint64_t offset : detail::kRestoreJournalOffsets) {
      copies.push_back({offset, buffer, detail::kRestoreJournalCopySize});
    }
  }

  // Adds the store's identity (encoded into `buffer`, kStoreIdBlockSize bytes) to `copies`.
  void add_store_id(std::vector<Copy>& copies, std::uint8_t* buffer) const {
    detail::encode_store_id(store_id, buffer);
    copies.push_back({detail::kStoreIdOffset, buffer, detail::kStoreIdBlockSize});
  }

  // The signing of a record for the slot at `offset` (keys set).
  detail::RecordSigning signing_for(std::uint64_t offset, detail::RecordBinding& binding) const {
    std::memcpy(binding.store_id, store_id, sizeof store_id);
    binding.location = offset;
    std::memcpy(binding.schema_digest, own_blob_digest.of(own_blob->data, own_blob->size),
                sizeof binding.schema_digest);
    detail::RecordSigning signing;
    signing.keys = keys.get();
    signing.binding = &binding;
    signing.journal_freshness = journal.freshness;
    return signing;
  }

  // Adopts `g` for a file just initialised with nothing in it but the journal.
  void become_empty(const StoreGeometry& g) {
    geometry = g;
    for (StoreSchemaArea& area : areas) area = StoreSchemaArea();
    own_area = -1;
    lay_out_slots();
  }

  // Rewrites the store with the requested geometry: a new file, renamed over the old one, that
  // holds both schema areas and the newest valid checkpoints (as many as fit, the newest
  // first). The old file is untouched until the rename. On success `fd` is the new file's.
  Status apply_requested_geometry(int& fd, const Schema& own) {
    const std::size_t own_schema_bytes = detail::schema_blob(own).size;
    Status status = scan_slots(fd);
    if (!status.ok()) return status;
    StoreGeometry target =
        detail::store_geometry_for(requested.slot_count, requested.slot_size, own_schema_bytes);
    target.schema_area_size = std::max(target.schema_area_size, geometry.schema_area_size);
    target.slots_offset = format::kStorePageSize + 2 * std::uint64_t{target.schema_area_size};

    // What to carry: the areas, every checkpoint the crash-loop fallback may still need, then
    // the newest others the journal does not exclude, up to slot_count - 1 in all (the save
    // about to happen takes the last slot).
    const std::uint32_t needed = mark_fallback_needs();
    if (needed + 1 > target.slot_count) {
      return Status(Error::StoreFull,
                    "%s: cannot rewrite the store into %u slots while the crash-loop fallback "
                    "needs %u checkpoints until confirm(), and one slot for this one; nothing "
                    "was written",
                    path.c_str(), target.slot_count, needed);
    }
    std::vector<std::vector<std::uint8_t>> kept;
    std::vector<Copy> copies;
    for (int i = 0; i < 2; ++i) {
      if (!areas[i].valid) continue;
      kept.emplace_back(format::kStoreAreaHeaderSize + areas[i].size);
      std::size_t got = 0;
      status = detail::pread_full(fd, kept.back().data(), kept.back().size(),
                                  static_cast<off_t>(area_offsets[i]), got, path.c_str());
      if (!status.ok()) return status;
      if (got != kept.back().size())
        return Status(Error::Io, "%s: a schema area changed", path.c_str());
    }
    newest_first.clear();
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      if (slots[i].state == StoreSlotState::Valid &&
          (needed_by_fallback[i] || !journal.excludes(slots[i].sequence))) {
        newest_first.push_back(i);
      }
    }
    std::sort(newest_first.begin(), newest_first.end(), [this](std::uint32_t a, std::uint32_t b) {
      if (needed_by_fallback[a] != needed_by_fallback[b]) return needed_by_fallback[a] > 0;
      return slots[a].sequence > slots[b].sequence;
    });
    std::uint32_t carried = 0;
    for (const std::uint32_t i : newest_first) {
      if (carried + 1 >= target.slot_count) break;
      Slot reread;
      status = read_slot(fd, i, reread);
      if (!status.ok()) return status;
      if (reread.state != StoreSlotState::Valid) continue;
      if (view.record_size > target.slot_size) {
        // The newest checkpoint, and those the fallback needs, must survive: keep the old
        // geometry while they cannot move.
        if (carried == 0 || needed_by_fallback[i]) return Status();
        continue;
      }
      kept.emplace_back(slot_bytes.begin(),
                        slot_bytes.begin() + static_cast<std::ptrdiff_t>(view.record_size));
      if (keys) {
        // Verified where it was (read_slot): signed again for the slot it moves to, with its
        // area's schema digest and the journal freshness it was saved under.
        detail::RecordBinding binding;
        std::memcpy(binding.store_id, store_id, sizeof store_id);
        binding.location = target.slot_offset(carried);
        std::memcpy(binding.schema_digest, areas[reread.area].digest(),
                    sizeof binding.schema_digest);
        detail::RecordSigning signing;
        signing.keys = keys.get();
        signing.binding = &binding;
        signing.journal_freshness = view.header.journal_freshness;
        detail::reseal_record(kept.back().data(), kept.back().size(), signing);
      }
      ++carried;
    }
    std::size_t next = 0;
    for (int i = 0; i < 2; ++i) {
      if (!areas[i].valid) continue;
      copies.push_back({target.area_offset(i), kept[next].data(), kept[next].size()});
      ++next;
    }
    for (std::uint32_t slot = 0; next < kept.size(); ++next, ++slot) {
      copies.push_back({target.slot_offset(slot), kept[next].data(), kept[next].size()});
    }
    std::uint8_t journal_copy[detail::kRestoreJournalCopySize];
    add_journal_copy(copies, journal_copy);
    std::uint8_t id_copy[detail::kStoreIdBlockSize];
    add_store_id(copies, id_copy);

    char temp[PATH_MAX];
    int new_fd = -1;
    status = detail::create_temp_file(path.c_str(), O_RDWR, temp, sizeof temp, new_fd);
    if (!status.ok()) return status;
    detail::FileSystem& files = detail::file_system();
    if (files.flock(new_fd, LOCK_EX | LOCK_NB) != 0) {
      status = detail::io_error("cannot lock", temp, errno);
    }
    if (status.ok()) status = initialise(new_fd, temp, target, copies);
    if (status.ok() && files.rename(temp, path.c_str()) != 0) {
      status = detail::io_error("cannot rename the rewritten store onto", path.c_str(), errno);
    }
    if (!status.ok()) {
      files.unlink(temp);
      files.close(new_fd);
      return status;
    }
    files.close(fd);  // releases the old file's lock; the new file holds its own
    fd = new_fd;
    geometry_pending = false;
    geometry = target;
    lay_out_slots();
    status = load_areas(fd, own);
    if (status.ok()) status = scan_slots(fd);
    if (status.ok()) status = detail::sync_parent_directory(path.c_str());
    return status;
  }

  // A store whose header does not decode: find its checkpoints by scanning. With `options`
  // (opened for writing) the header is rebuilt when that geometry places everything found.
  // Returns the original header problem when nothing restorable is found.
  Status recover(int fd, std::uint64_t file_size, const Status& header_problem,
                 const StoreOptions* options, bool& rebuilt) {
    rebuilt = false;
    detail::StoreSalvage salvage;
    Status status = detail::salvage_store(fd, path.c_str(), file_size, salvage);
    if (!status.ok()) return status;
    if (salvage.record_offsets.empty()) return header_problem;
    StoreGeometry guess;
    if (options != nullptr && geometry_from_file_size(*options, file_size, guess) &&
        detail::salvage_fits_geometry(salvage, guess, file_size)) {
      std::uint8_t header[format::kStoreHeaderSize];
      detail::encode_store_header(guess, header);
      status = detail::pwrite_all(fd, header, sizeof header, 0, path.c_str());
      if (status.ok() && detail::file_system().fdatasync(fd) != 0) {
        status = detail::io_error("cannot fdatasync", path.c_str(), errno);
      }
      if (!status.ok()) return status;
      geometry = guess;
      lay_out_slots();
      rebuilt = true;
      return Status();
    }
    // Restore-only: one slot per record found, in place.
    geometry = StoreGeometry();
    slots.assign(salvage.record_offsets.size(), Slot());
    for (std::size_t i = 0; i < slots.size(); ++i) {
      slots[i].offset = salvage.record_offsets[i];
      slots[i].capacity = salvage.record_sizes[i];
    }
    for (int i = 0; i < 2; ++i) {
      areas[i] = std::move(salvage.areas[i]);
      area_offsets[i] = salvage.area_offsets[i];
    }
    newest_first.reserve(slots.size());
    read_only_reason = "store " + path + " has a damaged header (" + header_problem.message() +
                       "); its " + std::to_string(slots.size()) +
                       " checkpoints were found by scanning and can be restored, but its "
                       "geometry could not be confirmed, so symcr writes nothing into it: "
                       "restore from it, then save into a new path";
    return Status();
  }
};

Store::~Store() { close(); }

Store::Store(Store&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      schema_(std::exchange(other.schema_, nullptr)),
      options_(other.options_),
      last_sequence_(std::exchange(other.last_sequence_, 0)),
      impl_(std::exchange(other.impl_, nullptr)) {}

Store& Store::operator=(Store&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    schema_ = std::exchange(other.schema_, nullptr);
    options_ = other.options_;
    last_sequence_ = std::exchange(other.last_sequence_, 0);
    impl_ = std::exchange(other.impl_, nullptr);
  }
  return *this;
}

void Store::close() {
  if (fd_ >= 0) detail::file_system().close(fd_);  // also releases the flock
  fd_ = -1;
  delete impl_;
  impl_ = nullptr;
  schema_ = nullptr;
  last_sequence_ = 0;
}

bool Store::read_only() const { return impl_ != nullptr && !impl_->read_only_reason.empty(); }

bool Store::holds_checkpoints() const {
  if (impl_ == nullptr) return false;
  for (const Impl::Slot& slot : impl_->slots)
    if (slot.state != StoreSlotState::Empty) return true;
  return false;
}

Status Store::open(const char* path, const StoreOptions& options, Store& out) {
  const Schema* schema = nullptr;
  Status status = detail::program_schema(schema);
  if (!status.ok()) return status;
  return open(path, *schema, options, out);
}

Status Store::open_readonly(const char* path, Store& out) {
  const Schema* schema = nullptr;
  Status status = detail::program_schema(schema);
  if (!status.ok()) return status;
  return open_readonly(path, *schema, out);
}

namespace {

struct OpenedStoreFile {
  int fd = -1;
  bool created = false;
  std::string read_only_reason;  // empty when opened for writing (and then locked)
  struct stat info {};
};

bool is_permission_error(int error_number) {
  return error_number == EROFS || error_number == EACCES || error_number == EPERM;
}

bool is_same_file(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// Opens the store file: for writing (created if absent, and locked), or read-only where the
// file or its file system cannot be written or `writable` is false. The lock must be on the
// file the path still names once locked: a writer rewriting the store for a new geometry
// renames a new file over the path, and a descriptor opened just before locks the replaced
// one, which that writer has left: another writer was at work, so the open fails as if locked.
Status open_store_file(const char* path, bool writable, OpenedStoreFile& out) {
  detail::FileSystem& files = detail::file_system();
  out = OpenedStoreFile();
  int fd = -1;
  if (writable) {
    fd = files.open(path, O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    out.created = fd >= 0;
    if (fd < 0 && (errno == EEXIST || is_permission_error(errno))) {
      const int create_error = errno;
      fd = files.open(path, O_RDWR | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0);
      // Absent and not creatable (a read-only directory): the creation's error says why.
      if (fd < 0 && errno == ENOENT)
        return detail::open_error("cannot open store", path, create_error);
    }
    if (fd < 0 && is_permission_error(errno)) {
      out.read_only_reason = std::string("store ") + path + " was opened read-only (" +
                             std::strerror(errno) + "): restore_latest() works, save() does not";
    }
  } else {
    out.read_only_reason = std::string("store ") + path + " was opened with open_readonly()";
  }
  if (fd < 0 && !out.read_only_reason.empty()) {
    fd = files.open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0);
  }
  if (fd < 0) return detail::open_error("cannot open store", path, errno);
  Status status;
  if (files.fstat(fd, &out.info) != 0) {
    status = detail::io_error("cannot stat", path, errno);
  } else if (!S_ISREG(out.info.st_mode)) {
    status = Status(Error::Io, "%s is not a regular file", path);
  } else if (!out.read_only_reason.empty()) {
    out.fd = fd;
    return Status();
  } else if (files.flock(fd, LOCK_EX | LOCK_NB) != 0) {
    // One writer per store: two processes saving into one ring would overwrite each other.
    status = errno == EWOULDBLOCK
                 ? Status(Error::Io, "store %s is open elsewhere (locked by another Store)", path)
                 : detail::io_error("cannot lock", path, errno);
  } else {
    struct stat named {};
    if (files.lstat(path, &named) == 0 && is_same_file(named, out.info) && out.info.st_nlink > 0) {
      out.fd = fd;
      return Status();
    }
    status = Status(Error::Io,
                    "store %s is open elsewhere (another Store rewrote it while this one "
                    "opened it)",
                    path);
  }
  files.close(fd);
  return status;
}

}  // namespace

Status Store::open(const char* path, const Schema& schema, const StoreOptions& options,
                   Store& out) {
  out.close();
  Status status = detail::check_store_dimensions(options.slots, options.slot_size);
  if (!status.ok()) return status;
  return Impl::open(path, schema, options, /*writable=*/true, out);
}

Status Store::open_readonly(const char* path, const Schema& schema, Store& out) {
  out.close();
  return Impl::open(path, schema, StoreOptions(), /*writable=*/false, out);
}

Status Store::Impl::open(const char* path, const Schema& schema, const StoreOptions& options,
                         bool writable, Store& out) {
  Status status = open_descriptor(path, schema, options, writable, out);
  if (!status.ok()) {
    out.close();
    return status;
  }
  out.schema_ = &schema;
  return Status();
}

Status Store::Impl::open_descriptor(const char* path, const Schema& schema,
                                    const StoreOptions& options, bool writable, Store& out) {
  const detail::SchemaBlob& blob = detail::schema_blob(schema);
  OpenedStoreFile file;
  Status status = open_store_file(path, writable, file);
  if (!status.ok()) return status;
  // Adopt the descriptor now: the caller closes it on every failure below.
  out.fd_ = file.fd;
  out.impl_ = new Impl();
  Impl& impl = *out.impl_;
  impl.path = path;
  impl.read_only_reason = file.read_only_reason;
  const int fd = file.fd;
  const bool created = file.created;
  const bool can_write = file.read_only_reason.empty();
  // A created file that cannot be made a store is removed again: no empty file is left.
  auto creation_failed = [&](const Status& failure) {
    if (created) detail::file_system().unlink(path);
    return failure;
  };
  // A rewrite for a new geometry killed before its rename left its new file behind.
  if (can_write) detail::remove_stale_temp_files(path);
  const struct stat& info = file.info;
  const std::uint64_t file_size = static_cast<std::uint64_t>(info.st_size);
  const StoreGeometry wanted =
      detail::store_geometry_for(options.slots, options.slot_size, blob.size);

  // One read for the header, the restore journal and the store's identity after it.
  std::uint8_t header[detail::kStoreHeaderPageRead] = {};
  std::size_t got = 0;
  status = detail::pread_full(fd, header, sizeof header, 0, got, path);
  if (!status.ok()) return creation_failed(status);
  impl.fallback_depth = writable ? options.fallback_depth : 0;
  impl.allow_unrecorded_restore = options.allow_unrecorded_restore;
  // A store without an identity (new, written by an earlier version, or its two copies lost)
  // gets one before this Store writes anything into it; one opened read-only keeps the all-zero
  // identity. An existing store may take its own back from its counter file (below).
  bool id_whole = false;
  const bool id_missing = !detail::read_store_id(header, got, impl.store_id, &id_whole);
  if (id_missing && can_write) detail::new_store_id(impl.store_id);
  const std::size_t page_got = got;
  impl.own_blob = &blob;
  impl.take_keys();
  if (options.freshness_counter != nullptr) {
    impl.counter = options.freshness_counter;
  } else {
    // An empty path is no path: the default, next to the store.
    const bool named = options.counter_path != nullptr && options.counter_path[0] != '\0';
    const std::string counter_path = named ? options.counter_path : std::string(path) + ".fresh";
    status = detail::check_counter_path(counter_path.c_str(), info, path);
    if (!status.ok()) return creation_failed(status);
    impl.own_counter.reset(
        new detail::FileFreshnessCounter(counter_path, impl.store_id, options.durability));
    impl.own_counter->use_keys(impl.keys.get());
    impl.counter = impl.own_counter.get();
  }
  // Read for numbering; checked again by each restore.
  const Status counter_read =
      impl.keys ? impl.counter->read(impl.counter_value) : Status(Error::NoValidSlot, "no keys");
  impl.adopt_journal(header, got);
  got = std::min(got, format::kStoreHeaderSize);
  Status header_status;
  if (!created) header_status = detail::decode_store_header(header, got, path, impl.geometry);
  // A store whose identity copies are both lost may take it back from its counter file (keys
  // set), once its slots are scanned: `found` says whether it has one.
  const auto take_identity_back = [&](bool& found) -> Status {
    found = !id_missing;
    if (!id_missing || created) return Status();
    const Status taken = impl.identity_from_counter(fd, found);
    if (taken.ok() && found) {  // the journal's seal and the counter are bound to it too
      impl.adopt_journal(header, page_got);
      if (impl.keys) (void)impl.counter->read(impl.counter_value);
    }
    return taken;
  };
  bool needs_initialising = created;
  if (!header_status.ok() && !created) {
    if (header_status.error() == Error::FutureVersion) return header_status;
    bool rebuilt = false;
    status = impl.recover(fd, file_size, header_status, can_write ? &options : nullptr, rebuilt);
    if (!status.ok()) {
      // Nothing to restore in it. Only a file an interrupted initialisation left is reused.
      if (!(can_write && interrupted_initialisation(header, got))) return status;
      needs_initialising = true;
    } else if (rebuilt) {
      header_status = Status();
    }
  } else if (!created) {
    impl.lay_out_slots();
  }

  if (needs_initialising) {
    if (!can_write) return Status(Error::NoValidSlot, "%s holds no store", path);
    std::vector<Impl::Copy> copies;
    std::uint8_t journal_copy[detail::kRestoreJournalCopySize];
    impl.add_journal_copy(copies, journal_copy);
    std::uint8_t id_copy[detail::kStoreIdBlockSize];
    impl.add_store_id(copies, id_copy);
    status = impl.initialise(fd, path, wanted, copies);
    if (status.ok() && created) status = detail::sync_parent_directory(path);
    if (!status.ok()) return creation_failed(status);
    impl.become_empty(wanted);
  } else if (header_status.ok()) {
    if (can_write && file_size < impl.geometry.file_size()) {
      // Truncated: the whole slots are kept; the file grows back to its size, zero-filled,
      // before anything is read from it, so that this open and every later scan read the same
      // bytes (a record whose lost tail was zeros is whole again for both).
      const int rc =
          detail::file_system().fallocate(fd, static_cast<off_t>(impl.geometry.file_size()));
      if (rc != 0) return detail::io_error("cannot extend the truncated store", path, rc);
    }
    status = impl.load_areas(fd, schema);
    if (status.ok()) status = impl.scan_slots(fd);  // slots past a truncation read as empty
    if (!status.ok()) return status;
    bool id_found = false;
    status = take_identity_back(id_found);
    if (!status.ok()) return status;
    // A new identity, or a damaged copy written again. A new one is written at open only into a
    // store that holds nothing yet: the checkpoints of one are bound to the identity lost, which
    // only this program's next save with keys gives up on (a program holding other keys, or
    // none, that merely opens it must not).
    if (!id_whole && can_write) {
      if (!id_found && !impl.holds_no_record()) {
        impl.store_id_unwritten = true;
      } else {
        status = impl.write_store_id(fd);
        if (!status.ok()) return status;
      }
    }
    if (can_write && !same_dimensions(impl.geometry, wanted)) {
      // Another geometry: read with the file's, rewrite (a new file renamed over this one) at
      // the first save, so that a crash never leaves less than the old store.
      impl.geometry_pending = true;
      impl.requested = wanted;
    }
  } else {
    status = impl.scan_slots(fd);  // restore-only: a salvaged store
    bool id_found = false;
    if (status.ok()) status = take_identity_back(id_found);
    if (!status.ok()) return status;
  }
  impl.own_area = impl.area_for_hash(blob.hash);
  impl.distrust_stale_journal();
  if (impl.keys && can_write && impl.read_only_reason.empty() && !counter_read.ok() &&
      impl.holds_no_record() && impl.journal.freshness == 0) {
    // Nothing saved yet: the counter is created now, before the first checkpoint, so that a
    // crash while it is first written never leaves a checkpoint without a counter. A counter
    // that cannot be written yet is reported by the first save. A store holding records this
    // program cannot verify (other keys) keeps the counter it has: an open changes nothing.
    (void)impl.advance_counter(impl.highest_known_sequence());
  }
  impl.scan_current = impl.newest_scanned >= 0 || impl.newest_valid_slot() < 0;
  if (impl.newest_scanned >= 0) {
    // A build opens its store while it initialises and restores where time counts (a restore
    // point, the first loop): what the restore needs of the schemas alone is resolved now.
    const StoreSchemaArea& area =
        impl.areas[impl.slots[static_cast<std::size_t>(impl.newest_scanned)].area];
    detail::prepare_restore(area.schema(), area.hash, schema, area.parsed);
  }
  out.last_sequence_ = impl.highest_known_sequence();
  out.options_ = options;
  if (impl.geometry.slot_count != 0) {
    out.options_.slots = impl.geometry.slot_count;
    out.options_.slot_size = impl.geometry.slot_size;
  }
  return Status();
}

Status Store::save() {
  if (!is_open()) return Status(Error::Io, "the store is not open");
  Impl& impl = *impl_;
  if (!impl.read_only_reason.empty()) {
    return Status(Error::Io, "%s", impl.read_only_reason.c_str());
  }
  // One key set for the whole save; slot states found with another are found again.
  impl.take_keys();
  if (impl.scanned_with != impl.keys.get() && impl.geometry.slot_count != 0) {
    Status rescan = impl.scan_slots(fd_);
    if (!rescan.ok()) return rescan;
  }
  // A save into a store older than its counter (keys set) does not trust its journal: saved
  // under the counter's value, the new checkpoint makes the old journal stale for good.
  if (impl.keys && !impl.freshness_against(impl.counter_value).ok()) {
    impl.distrust_journal("it is older than the freshness counter (an older copy put back)",
                          std::max(impl.counter_value, impl.journal.freshness) + 1);
  }
  // Above every sequence the store holds (authenticated, with keys set), its journal names and
  // the freshness counter has seen, so that no older record and no exclusion can outrank or
  // cover it.
  const std::uint64_t newest =
      std::max({last_sequence_, impl.highest_known_sequence(), impl.keys ? impl.counter_value : 0});
  if (newest >= format::kMaxRecordSequence) {
    return Status(Error::Corrupt,
                  "%s: the store's sequence numbers are exhausted (a record, the journal or the "
                  "freshness counter names sequence %llu, which only damage or forgery "
                  "produce); nothing was written: save into a new store",
                  impl.path.c_str(), static_cast<unsigned long long>(newest));
  }
  // The identity this save signs with, in a store whose copies were damaged and gave none back
  // (Store::open): written first, or the checkpoint would not verify at the next open.
  if (impl.keys && impl.store_id_unwritten) {
    const Status written = impl.write_store_id(fd_);
    if (!written.ok()) return written;
  }
  const std::uint64_t sequence = newest + 1;
  impl.scan_current = false;
  // With keys, the header is laid out for a MAC made once the slot is chosen.
  detail::RecordSigning deferred;
  deferred.keys = impl.keys.get();
  Status status =
      detail::encode_record(*schema_, /*inline_schema=*/false, sequence, impl.record, &deferred);
  if (!status.ok()) return status;
  if (impl.geometry_pending) {
    status = impl.apply_requested_geometry(fd_, *schema_);
    if (!status.ok()) return status;
    impl.own_area = impl.area_for_hash(detail::schema_blob(*schema_).hash);
    options_.slots = impl.geometry.slot_count;
    options_.slot_size = impl.geometry.slot_size;
  }
  if (impl.record.size() > impl.geometry.slot_size) {
    return Status(Error::TooLarge,
                  "%s: a checkpoint of %zu bytes does not fit a slot of %u bytes; nothing was "
                  "written (open the store with a larger slot_size)",
                  impl.path.c_str(), impl.record.size(), impl.geometry.slot_size);
  }
  if (impl.own_area < 0) {
    status = impl.write_own_area(fd_, *schema_, options_.durability);
    if (!status.ok()) return status;
  }
  const int target = impl.slot_to_overwrite();
  if (target < 0) {
    return Status(Error::StoreFull,
                  "%s: every one of its %zu slots holds a checkpoint the crash-loop fallback "
                  "needs until confirm() (the restored one and up to %u older ones); this "
                  "checkpoint was not written: call confirm() once the restored state has "
                  "proven itself, or give the store at least %u slots",
                  impl.path.c_str(), impl.slots.size(), impl.fallback_depth,
                  impl.fallback_depth + 2);
  }
  Impl::Slot& slot = impl.slots[static_cast<std::size_t>(target)];
  if (impl.keys) {
    detail::RecordBinding binding;
    detail::reseal_record(impl.record.data(), impl.record.size(),
                          impl.signing_for(slot.offset, binding));
  }
  slot.state = StoreSlotState::Corrupt;  // until the write completes
  slot.area = -1;
  status = detail::pwrite_all(fd_, impl.record.data(), impl.record.size(),
                              static_cast<off_t>(slot.offset), impl.path.c_str());
  if (!status.ok()) return status;
  slot.state = StoreSlotState::Valid;
  slot.sequence = sequence;
  slot.area = impl.own_area;
  slot.journal_freshness = impl.keys ? impl.journal.freshness : 0;
  last_sequence_ = sequence;
  if (options_.durability == Durability::Fdatasync && detail::file_system().fdatasync(fd_) != 0) {
    return detail::io_error("cannot fdatasync", impl.path.c_str(), errno);
  }
  // After the record: a crash in between leaves the counter one save behind, never ahead. A
  // checkpoint saved while a restore waits for confirm() is suspect to the crash-loop fallback
  // until then, and the slot it is in may be the next save's (slot_to_overwrite): the counter
  // passes it when confirm() writes the journal.
  if (impl.journal.unconfirmed != 0) return Status();
  const Status advanced = impl.advance_counter(sequence);
  if (!advanced.ok()) {
    // The checkpoint is whole and counts (a counter behind the store is no rollback): say so,
    // so that the caller does not take it for lost.
    return Status(advanced.error(), "checkpoint %llu was saved, but %s",
                  static_cast<unsigned long long>(sequence), advanced.message());
  }
  return Status();
}

namespace {

void skip(std::vector<SkippedCheckpoint>& skipped, std::uint32_t slot, std::uint64_t sequence,
          std::string reason) {
  skipped.push_back(SkippedCheckpoint{slot, sequence, std::move(reason)});
}

}  // namespace

Status Store::confirm() {
  if (!is_open()) return Status(Error::Io, "the store is not open");
  Impl& impl = *impl_;
  if (!impl.unconfirmed_is_ours) return Status();  // nothing this Store restored waits for it
  impl.take_keys();
  impl.journal.confirm();
  Status status = impl.write_journal(fd_, options_.durability);
  if (status.ok()) impl.unconfirmed_is_ours = false;
  return status;
}

Report Store::restore_latest(const RestoreOptions& options) {
  Report report;
  if (!is_open()) {
    detail::ReportAccess::set_status(report, Status(Error::Io, "the store is not open"));
    return report;
  }
  Impl& impl = *impl_;
  // A store opened read-only may have been written by its owner since the scan; one scanned
  // with other keys is scanned again with the keys of this restore.
  impl.take_keys();
  Status status;
  if (!impl.scan_current || !impl.read_only_reason.empty() ||
      impl.scanned_with != impl.keys.get()) {
    status = impl.scan_slots(fd_);
  }
  if (status.ok() && (!impl.read_only_reason.empty() ||
                      (impl.journal_read_with != impl.keys.get() && !impl.unconfirmed_is_ours))) {
    status = impl.read_journal(fd_);
    if (status.ok()) impl.distrust_stale_journal();
  }
  impl.scan_current = false;
  if (!status.ok()) {
    detail::ReportAccess::set_status(report, status);
    return report;
  }
  // Freshness first: a rolled-back store is refused before anything (the journal included) is
  // written; the report lists the slots that could not count, and why.
  status = impl.check_freshness();
  if (!status.ok()) {
    detail::ReportAccess::set_status(report, status);
    std::vector<SkippedCheckpoint> unusable;
    impl.list_unrestorable_slots(unusable);
    detail::ReportAccess::skipped(report) = std::move(unusable);
    return report;
  }
  impl.newest_first.clear();
  std::uint64_t newest_valid = 0;
  for (std::uint32_t i = 0; i < impl.slots.size(); ++i) {
    if (impl.slots[i].state != StoreSlotState::Valid) continue;
    impl.newest_first.push_back(i);
    newest_valid = std::max(newest_valid, impl.slots[i].sequence);
  }
  last_sequence_ = std::max(last_sequence_, newest_valid);
  std::sort(impl.newest_first.begin(), impl.newest_first.end(),
            [&impl](std::uint32_t a, std::uint32_t b) {
              return impl.slots[a].sequence > impl.slots[b].sequence;
            });

  // A journal not trusted (keys set) was read as empty; the report says so, whatever happens.
  const std::string journal_distrust =
      impl.journal_distrust.empty()
          ? std::string()
          : "the store's restore journal was not trusted and was read as empty: " +
                impl.journal_distrust +
                "; the crash-loop fallback starts afresh from the newest checkpoint";

  // Crash-loop fallback: a restore recorded by an earlier start and never confirmed makes its
  // checkpoint and the newer ones suspect; past the depth, the fallback gives up on them all.
  // A store that cannot be written still honours what its journal says, but cannot record this
  // restore: a crash it caused would go unnoticed, so it is refused unless the program chose
  // to restore without the fallback.
  detail::RestoreJournal& journal = impl.journal;
  const bool recording = impl.fallback_depth > 0 && impl.read_only_reason.empty();
  if (impl.fallback_depth > 0 && !recording) {
    if (!impl.allow_unrecorded_restore) {
      detail::ReportAccess::set_status(
          report, Status(Error::Io,
                         "nothing restored: the crash-loop fallback cannot record a restore in a "
                         "store it cannot write (StoreOptions::allow_unrecorded_restore restores "
                         "without the fallback): %s",
                         impl.read_only_reason.c_str()));
      return report;
    }
  }
  bool crashed = false;  // this start found an unconfirmed restore
  std::uint32_t crash_depth = 0;
  if (recording && !impl.unconfirmed_is_ours) {
    crash_depth = journal.fallbacks + 1;
    crashed = journal.count_crash(last_sequence_, impl.fallback_depth);
  }
  // A restore of this run still unconfirmed: another one does not vouch for it (the state may
  // still hold what it restored), so the older of the two is the one a crash is blamed on.
  const std::uint64_t pending = impl.unconfirmed_is_ours ? journal.unconfirmed : 0;
  if (recording) journal.depth = impl.fallback_depth;

  std::vector<SkippedCheckpoint> skipped;
  // Valid slots whose payload the engine still rejected as corrupt (after its CRC passed: a
  // writer bug or a collision), and the last such message.
  unsigned rejected = 0, suspect = 0;
  Status last_rejection;
  for (const std::uint32_t i : impl.newest_first) {
    const std::uint64_t sequence = impl.slots[i].sequence;
    if (journal.excludes(sequence)) {
      ++suspect;
      skip(skipped, i, sequence, journal.exclusion_reason(sequence));
      continue;
    }
    const detail::RecordView* record = &impl.newest_view;
    int area_index = impl.slots[i].area;
    if (static_cast<int>(i) != impl.newest_scanned) {  // a fallback: read it again
      Impl::Slot reread;
      status = impl.read_slot(fd_, i, reread);
      if (!status.ok()) {
        detail::ReportAccess::set_status(report, status);
        return report;
      }
      if (reread.state != StoreSlotState::Valid) {
        impl.slots[i].state = reread.state;
        impl.slots[i].unauthenticated = reread.unauthenticated;
        if (reread.state != StoreSlotState::Unauthenticated) {
          skip(skipped, i, sequence, "changed since it was validated, and no longer validates");
        }
        continue;
      }
      record = &impl.view;
      area_index = reread.area;
    }
    // With keys set, read_slot verified its MAC: only authenticated slots are Valid.
    if (recording) {
      // Recorded before the state is touched: a crash during or after the restore is seen by
      // the next start. A restore that cannot be recorded is not applied.
      journal.unconfirmed = pending != 0 ? std::min(pending, sequence) : sequence;
      status = impl.write_journal(fd_, options_.durability);
      if (!status.ok()) {
        detail::ReportAccess::set_status(report, status);
        return report;
      }
      impl.unconfirmed_is_ours = true;
    }
    const StoreSchemaArea& area = impl.areas[area_index];
    report =
        detail::restore_record(*record, area.schema(), area.hash, *schema_, options, area.parsed);
    const Error error = report.status().error();
    if (error != Error::Corrupt && error != Error::Truncated) {
      if (!report.ok() && recording) {
        journal.unconfirmed = pending;  // nothing was applied: nothing new to confirm
        (void)impl.write_journal(fd_, options_.durability);
      }
      if (report.ok() && impl.fallback_depth > 0 && !recording) {
        detail::ReportAccess::warn(
            report,
            "the crash-loop fallback is disarmed for this restore: " + impl.read_only_reason +
                "; if the restored state crashes the program, the next start restores "
                "it again");
      }
      if (!journal_distrust.empty()) detail::ReportAccess::warn(report, journal_distrust);
      impl.list_unrestorable_slots(skipped);
      detail::ReportAccess::skipped(report) = std::move(skipped);
      return report;
    }
    ++rejected;
    last_rejection = report.status();
    skip(skipped, i, sequence, std::string("rejected by the restore: ") + last_rejection.message());
  }

  unsigned empty = 0, corrupt = 0, unknown = 0, future = 0, unauthenticated = 0;
  for (const Impl::Slot& slot : impl.slots) {
    empty += slot.state == StoreSlotState::Empty;
    corrupt += slot.state == StoreSlotState::Corrupt;
    unknown += slot.state == StoreSlotState::UnknownSchema;
    future += slot.state == StoreSlotState::FutureVersion;
    unauthenticated += slot.state == StoreSlotState::Unauthenticated;
  }
  report.clear();
  // A store whose checkpoints all fail this program's keys, and whose journal names no crash
  // it trusts, is another key holder's: signing its journal (and counter) over with these keys
  // would leave its own program a store it refuses as rolled back.
  const bool anothers_store = !crashed && unauthenticated > 0 && impl.newest_first.empty();
  if (recording && !anothers_store) {
    // Nothing restored: the state stays initial and nothing waits for confirmation. After a
    // crash, what is left is given up on, so the checkpoints saved from the initial state are
    // the next ones restored (with the full depth again).
    if (crashed) journal.give_up(last_sequence_);
    journal.unconfirmed = pending;
    impl.unconfirmed_is_ours = pending != 0;
    status = impl.write_journal(fd_, options_.durability);
    if (!status.ok()) {
      detail::ReportAccess::set_status(report, status);
      return report;
    }
  }
  if (crashed) {
    detail::ReportAccess::set_status(
        report, Status(Error::NoValidSlot,
                       "%s: the crash-loop fallback %s after %u unconfirmed restores in a row "
                       "(depth %u): nothing restored, the state stays initial",
                       impl.path.c_str(),
                       crash_depth > impl.fallback_depth ? "gave up"
                                                         : "found no older checkpoint to restore",
                       crash_depth, impl.fallback_depth));
  } else {
    detail::ReportAccess::set_status(
        report,
        Status(Error::NoValidSlot,
               "%s: no restorable checkpoint in %zu slots (%u empty, %u corrupt or torn, %u with "
               "an unknown schema, %u from a future format, %u unauthenticated, %u passed over "
               "by the crash-loop fallback, %u rejected by restore%s%s)",
               impl.path.c_str(), impl.slots.size(), empty, corrupt, unknown, future,
               unauthenticated, suspect, rejected, rejected ? ": " : "",
               rejected ? last_rejection.message() : ""));
  }
  if (!journal_distrust.empty()) detail::ReportAccess::warn(report, journal_distrust);
  impl.list_unrestorable_slots(skipped);
  detail::ReportAccess::skipped(report) = std::move(skipped);
  return report;
}

}  // namespace symcr
