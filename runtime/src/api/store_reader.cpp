// StoreReader (store_reader.hpp), on the layout functions the writing Store uses too
// (store_layout.hpp).
#include "store_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "file_io.hpp"
#include "freshness.hpp"

namespace symcr::detail {

StoreReader::~StoreReader() {
  if (fd_ >= 0) ::close(fd_);
}

Status StoreReader::open(const char* path, const char* counter_path) {
  path_ = path;
  // O_NONBLOCK: a FIFO is refused below, not waited on.
  fd_ = ::open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd_ < 0) return open_error("cannot open store", path, errno);
  struct stat info {};
  if (::fstat(fd_, &info) != 0) return io_error("cannot stat", path, errno);
  if (!S_ISREG(info.st_mode)) return Status(Error::Io, "%s is not a regular file", path);

  std::uint8_t header[kStoreHeaderPageRead] = {};
  std::size_t got = 0;
  Status status = pread_full(fd_, header, sizeof header, 0, got, path);
  if (!status.ok()) return status;
  const bool id_found = read_store_id(header, got, store_id_);
  status = decode_store_header(header, std::min<std::size_t>(got, format::kStoreHeaderSize), path,
                               geometry_);
  if (!status.ok()) {
    status = salvage(static_cast<std::uint64_t>(info.st_size), status);
    if (!status.ok()) return status;
  } else {
    // A file shorter than its geometry (truncated) is read as a program reads it: the slots
    // still whole restore, those cut off read as empty or damaged.
    for (int i = 0; i < 2; ++i) {
      status = load_store_area(fd_, path, geometry_.area_offset(i), geometry_.schema_area_size,
                               nullptr, areas_[i]);
      if (!status.ok()) return status;
    }
    for (std::uint32_t i = 0; i < geometry_.slot_count; ++i) {
      slot_offsets_.push_back(geometry_.slot_offset(i));
      slot_capacities_.push_back(geometry_.slot_size);
    }
  }
  slots_.assign(slot_offsets_.size(), StoreSlot());
  std::vector<std::uint8_t> bytes;
  RecordView view;
  for (std::uint32_t i = 0; i < slots_.size(); ++i) {
    status = classify_slot(i, bytes, view, slots_[i]);
    if (!status.ok()) return status;
  }
  const KeySnapshot keys = current_keys();
  if (keys && !id_found) {
    const std::string counter = counter_path ? counter_path : path_ + ".fresh";
    identity_from_counter(counter.c_str(), *keys);
  }
  // The journal's seal is bound to the store's identity, recovered or not.
  JournalSeal seal;
  seal.keys = keys.get();
  seal.store_id = store_id_;
  journal_ = read_restore_journal(header, got, &seal, &journal_distrust_);
  if (keys) {
    const std::uint64_t saved_under = newest_authentic_journal(*keys);
    if (const char* why = stale_journal_reason(journal_, saved_under)) {
      if (!journal_.empty()) journal_distrust_ = why;
      journal_ = RestoreJournal();
      journal_.freshness = saved_under;
    }
  }
  return Status();
}

Status StoreReader::salvage(std::uint64_t file_size, const Status& header_problem) {
  // As a program's open recovers it: the checkpoints found by scanning, one slot each, in place.
  if (header_problem.error() == Error::FutureVersion) return header_problem;
  StoreSalvage found;
  Status status = salvage_store(fd_, path_.c_str(), file_size, found);
  if (!status.ok()) return status;
  if (found.record_offsets.empty()) return header_problem;
  geometry_ = StoreGeometry();
  slot_offsets_ = found.record_offsets;
  slot_capacities_ = found.record_sizes;
  for (int i = 0; i < 2; ++i) areas_[i] = std::move(found.areas[i]);
  salvaged_ = std::string("its header is damaged (") + header_problem.message() + "); " +
              std::to_string(slot_offsets_.size()) +
              " checkpoints were found by scanning, each read as a slot of its own, as a "
              "program's open finds them";
  return Status();
}

bool StoreReader::authentic(std::uint32_t index, const KeyRing& keys,
                            std::vector<std::uint8_t>& bytes, RecordView& view) const {
  int area = -1;
  return slots_[index].state == StoreSlotState::Valid &&
         read_record(index, bytes, view, area).ok() &&
         check_authentication(&keys, bytes.data(), view, binding(index, area)).ok();
}

std::uint64_t StoreReader::newest_authentic_journal(const KeyRing& keys) const {
  std::uint64_t newest = 0, saved_under = 0;
  std::vector<std::uint8_t> bytes;
  RecordView view;
  for (std::uint32_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].header.sequence > newest && authentic(i, keys, bytes, view)) {
      newest = view.header.sequence;
      saved_under = view.header.journal_freshness;
    }
  }
  return saved_under;
}

void StoreReader::identity_from_counter(const char* counter_path, const KeyRing& keys) {
  std::vector<std::uint8_t> counter;
  if (!read_regular_file(counter_path, kCounterFileSize, counter).ok()) return;
  std::uint8_t ids[kCounterCopyCount][kStoreIdSize];
  const std::size_t count = store_ids_in_counter_file(counter.data(), counter.size(), keys, ids);
  std::vector<std::uint8_t> bytes;
  RecordView view;
  for (std::size_t c = 0; c < count; ++c) {
    std::memcpy(store_id_, ids[c], sizeof store_id_);
    for (std::uint32_t i = 0; i < slots_.size(); ++i) {
      if (authentic(i, keys, bytes, view)) return;  // a checkpoint verifies under it: its identity
    }
  }
  std::memset(store_id_, 0, sizeof store_id_);
}

Status StoreReader::classify_slot(std::uint32_t index, std::vector<std::uint8_t>& bytes,
                                  RecordView& view, StoreSlot& slot) const {
  slot = StoreSlot();
  StoreSlotRead read;
  Status status = read_store_slot(fd_, path_.c_str(), slot_offsets_[index], slot_capacities_[index],
                                  areas_, bytes, view, read, &slot.problem);
  if (!status.ok()) return status;
  slot.state = read.state;
  slot.area = read.area;
  if (read.state == StoreSlotState::Valid || read.state == StoreSlotState::UnknownSchema) {
    slot.header = view.header;
  }
  return Status();
}

RecordBinding StoreReader::binding(std::uint32_t index, int area) const {
  RecordBinding binding;
  std::memcpy(binding.store_id, store_id_, sizeof store_id_);
  binding.location = index < slot_offsets_.size() ? slot_offsets_[index] : 0;
  if (area >= 0) std::memcpy(binding.schema_digest, areas_[area].digest(), format::kSha256Size);
  return binding;
}

Status StoreReader::check_freshness(std::uint64_t counter_value,
                                    const std::vector<bool>& authentic) const {
  std::vector<std::uint64_t> sequences;
  for (std::uint32_t i = 0; i < slots_.size() && i < authentic.size(); ++i) {
    if (authentic[i]) sequences.push_back(slots_[i].header.sequence);
  }
  const std::uint64_t newest =
      sequences.empty() ? 0 : *std::max_element(sequences.begin(), sequences.end());
  return freshness_verdict("the store", newest, newest_allowed(sequences, journal_), journal_,
                           counter_value);
}

std::vector<std::uint32_t> StoreReader::valid_slots_newest_first() const {
  std::vector<std::uint32_t> valid;
  for (std::uint32_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].state == StoreSlotState::Valid) valid.push_back(i);
  }
  std::stable_sort(valid.begin(), valid.end(), [this](std::uint32_t a, std::uint32_t b) {
    return slots_[a].header.sequence > slots_[b].header.sequence;
  });
  return valid;
}

std::uint64_t StoreReader::highest_known_sequence() const {
  std::uint64_t highest = journal_.highest_sequence();
  for (const StoreSlot& slot : slots_) {
    if (slot.state == StoreSlotState::Valid || slot.state == StoreSlotState::UnknownSchema) {
      highest = std::max(highest, slot.header.sequence);
    }
  }
  return highest;
}

RestoreJournal StoreReader::journal_at_next_start(bool* counts_crash) const {
  RestoreJournal journal = journal_;
  // A journal of an earlier version records no depth: its program's fallback is taken to go
  // one level deeper, not to give up.
  const std::uint32_t depth = journal.depth != 0 ? journal.depth : journal.fallbacks + 1;
  const bool counted = journal.count_crash(highest_known_sequence(), depth);
  if (counts_crash != nullptr) *counts_crash = counted;
  return journal;
}

Status StoreReader::read_record(std::uint32_t index, std::vector<std::uint8_t>& bytes,
                                RecordView& view, int& area) const {
  area = -1;
  if (index >= slots_.size()) {
    return Status(Error::Io, "%s has %zu slots; there is no slot %u", path_.c_str(), slots_.size(),
                  index);
  }
  StoreSlot slot;
  Status status = classify_slot(index, bytes, view, slot);
  if (!status.ok()) return status;
  if (slot.state == StoreSlotState::Empty) {
    return Status(Error::NoValidSlot, "slot %u is empty", index);
  }
  if (slot.state != StoreSlotState::Valid) return slot.problem;
  area = slot.area;
  return Status();
}

}  // namespace symcr::detail
