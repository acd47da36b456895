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

Status StoreReader::open(const char* path) {
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
  read_store_id(header, got, store_id_);
  const KeySnapshot keys = current_keys();
  JournalSeal seal;
  seal.keys = keys.get();
  seal.store_id = store_id_;
  journal_ = read_restore_journal(header, got, &seal, &journal_distrust_);
  status = decode_store_header(header, std::min<std::size_t>(got, format::kStoreHeaderSize), path,
                               geometry_);
  if (!status.ok()) return status;
  // A file shorter than its geometry (truncated) is read as a program reads it: the slots
  // still whole restore, those cut off read as empty or damaged.
  for (int i = 0; i < 2; ++i) {
    status = load_store_area(fd_, path, geometry_.area_offset(i), geometry_.schema_area_size,
                             nullptr, areas_[i]);
    if (!status.ok()) return status;
  }
  slots_.assign(geometry_.slot_count, StoreSlot());
  std::vector<std::uint8_t> bytes;
  RecordView view;
  std::uint64_t newest = 0, saved_under = 0;  // the newest authenticated checkpoint's journal
  for (std::uint32_t i = 0; i < geometry_.slot_count; ++i) {
    status = classify_slot(i, bytes, view, slots_[i]);
    if (!status.ok()) return status;
    if (keys && slots_[i].state == StoreSlotState::Valid && view.header.sequence > newest &&
        check_authentication(keys.get(), bytes.data(), view, binding(i, slots_[i].area)).ok()) {
      newest = view.header.sequence;
      saved_under = view.header.journal_freshness;
    }
  }
  if (keys) {
    if (const char* why = stale_journal_reason(journal_, saved_under)) {
      if (!journal_.empty()) journal_distrust_ = why;
      journal_ = RestoreJournal();
      journal_.freshness = saved_under;
    }
  }
  return Status();
}

Status StoreReader::classify_slot(std::uint32_t index, std::vector<std::uint8_t>& bytes,
                                  RecordView& view, StoreSlot& slot) const {
  slot = StoreSlot();
  StoreSlotRead read;
  Status status = read_store_slot(fd_, path_.c_str(), geometry_.slot_offset(index),
                                  geometry_.slot_size, areas_, bytes, view, read, &slot.problem);
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
  binding.location = geometry_.slot_offset(index);
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
