// The device profile's ring of checkpoint slots over a Storage (device.hpp): the slot to write
// next and the newest slot to restore are found from the slots' own records, so the ring keeps
// no state of its own in storage. A header's sequence is trusted only once its record's CRC
// holds: a reset while a slot is written leaves any header (on flash, the magic written and the
// sequence still erased, all ones), and such a slot must not decide where saving goes on.
#include <cstring>

#include "device_format.hpp"

namespace symcr {
namespace device {
namespace {

bool memory_read(void* context, std::size_t offset, void* out, std::size_t n) {
  std::memcpy(out, static_cast<const std::uint8_t*>(context) + offset, n);
  return true;
}

bool memory_write(void* context, std::size_t offset, const void* data, std::size_t n) {
  std::memcpy(static_cast<std::uint8_t*>(context) + offset, data, n);
  return true;
}

}  // namespace

Storage memory_storage(void* base, std::size_t size) {
  Storage storage{size, 1, memory_read, memory_write, nullptr, base};
  return storage;
}

Result Ring::open(const Storage& storage, std::size_t slot_size) {
  *this = Ring();
  const std::size_t unit = storage.erase_unit > 1 ? storage.erase_unit : 1;
  if (storage.read == nullptr || storage.write == nullptr ||
      slot_size < format::kRecordHeaderSize || slot_size % unit != 0 ||
      (unit > 1 && storage.erase == nullptr)) {
    return Result::Unsupported;
  }
  const std::size_t slots = storage.size / slot_size;
  if (slots < 2) return Result::NoSpace;
  storage_ = storage;
  slot_size_ = slot_size;
  slot_count_ = slots > kMaxSlots ? kMaxSlots : slots;
  std::uint64_t sequences[kMaxSlots];
  std::size_t order[kMaxSlots];
  const std::size_t newest = newest_whole(order, scan(sequences, order));
  if (newest != kMaxSlots) last_sequence_ = sequences[newest];
  return Result::Ok;
}

std::size_t Ring::scan(std::uint64_t* sequences, std::size_t* order) const {
  std::size_t used = 0;
  for (std::size_t i = 0; i < slot_count_; ++i) {
    std::uint8_t header[format::kRecordHeaderSize];
    sequences[i] = 0;
    if (!storage_.read(storage_.context, i * slot_size_, header, sizeof header) ||
        !format::starts_like_record(header, sizeof header)) {
      continue;
    }
    sequences[i] = format::load64(header + format::kRecordSequenceOffset);
    if (sequences[i] == 0 || sequences[i] > kLastRingSequence) {  // not a sequence save writes
      sequences[i] = 0;
      continue;
    }
    // Insertion by sequence, newest first: a handful of slots.
    std::size_t at = used++;
    while (at > 0 && sequences[order[at - 1]] < sequences[i]) {
      order[at] = order[at - 1];
      --at;
    }
    order[at] = i;
  }
  return used;
}

bool Ring::whole(std::size_t slot) const {
  // The CRC is computed through a small window, so that open() and save() need no slot-sized
  // buffer: the header's checksum field counts as zeros (docs/format.md §1).
  std::uint8_t window[format::kRecordHeaderSize];
  const std::size_t offset = slot * slot_size_;
  if (!storage_.read(storage_.context, offset, window, sizeof window)) return false;
  // Whatever the version: a whole record of a newer one is still the ring's newest.
  const std::size_t header = format::load16(window + format::kRecordHeaderSizeOffset);
  const std::uint64_t record = static_cast<std::uint64_t>(header) +
                               format::load32(window + format::kRecordSchemaSizeOffset) +
                               format::load32(window + format::kRecordPayloadSizeOffset);
  if (header < format::kRecordHeaderSize || record > slot_size_) return false;
  const std::uint32_t stored = format::load32(window + format::kRecordChecksumOffset);
  format::store32(window + format::kRecordChecksumOffset, 0);
  std::uint32_t crc = format::crc32c_extend_small(0, window, sizeof window);
  for (std::size_t at = sizeof window; at < record;) {
    const std::size_t n = record - at < sizeof window ? record - at : sizeof window;
    if (!storage_.read(storage_.context, offset + at, window, n)) return false;
    crc = format::crc32c_extend_small(crc, window, n);
    at += n;
  }
  return crc == stored;
}

std::size_t Ring::newest_whole(const std::size_t* order, std::size_t used) const {
  for (std::size_t k = 0; k < used; ++k) {
    if (whole(order[k])) return order[k];
  }
  return kMaxSlots;
}

Result Ring::save(const Build& build, std::uint8_t* buffer, std::size_t capacity) {
  if (slot_count_ == 0) return Result::Unsupported;
  std::uint64_t sequences[kMaxSlots];
  std::size_t order[kMaxSlots];
  // After the newest whole record: a torn or damaged slot is passed over, and is the slot
  // written next when it follows that record.
  const std::size_t newest = newest_whole(order, scan(sequences, order));
  const std::size_t target = newest == kMaxSlots ? 0 : (newest + 1) % slot_count_;
  const std::uint64_t previous = newest == kMaxSlots ? last_sequence_ : sequences[newest];
  if (previous >= kLastRingSequence) return Result::SequenceExhausted;  // never wrap to 0
  const std::uint64_t sequence = previous + 1;
  std::size_t size = 0;
  const std::size_t limit = capacity < slot_size_ ? capacity : slot_size_;
  Result result = device::save(build, sequence, buffer, limit, &size);
  if (result != Result::Ok) return result;
  const std::size_t offset = target * slot_size_;
  // The old record's CRC goes first (on flash, the whole slot): a reset later in the save
  // leaves a slot whose CRC fails. With the old CRC kept, a torn write of the new header (the
  // same sequence, when the old record had been damaged) could bring the old record back.
  if (storage_.erase_unit > 1) {
    if (!storage_.erase(storage_.context, offset, slot_size_)) return Result::Corrupt;
  } else {
    static const std::uint8_t kBlank[4] = {0};
    if (!storage_.write(storage_.context, offset + format::kRecordChecksumOffset, kBlank,
                        sizeof kBlank)) {
      return Result::Corrupt;
    }
  }
  if (!storage_.write(storage_.context, offset, buffer, size)) return Result::Corrupt;
  last_sequence_ = sequence;
  return Result::Ok;
}

Result Ring::restore_latest(const Build& build, std::uint8_t* buffer, std::size_t capacity,
                            std::uint8_t* scratch, std::size_t scratch_capacity,
                            std::uint64_t* sequence, std::size_t* slot, std::size_t* skipped) {
  if (slot_count_ == 0) return Result::Unsupported;
  if (capacity < slot_size_) return Result::NoSpace;
  std::uint64_t sequences[kMaxSlots];
  std::size_t order[kMaxSlots];
  const std::size_t used = scan(sequences, order);
  Result newest = Result::Empty;  // no slot holds a record: nothing was ever saved
  for (std::size_t k = 0; k < used; ++k) {
    const std::size_t i = order[k];
    Result result =
        storage_.read(storage_.context, i * slot_size_, buffer, slot_size_)
            ? device::restore(build, buffer, slot_size_, scratch, scratch_capacity, sequence)
            : Result::Corrupt;
    if (result == Result::Ok) {
      if (slot != nullptr) *slot = i;
      if (skipped != nullptr) *skipped = k;
      return result;
    }
    if (k == 0) newest = result;
    // The caller's own mistakes are not the slot's: no fallback past them.
    if (result == Result::NoSpace || result == Result::Unsupported) return result;
  }
  if (skipped != nullptr) *skipped = used;
  return newest;
}

}  // namespace device
}  // namespace symcr
