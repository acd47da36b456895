// An open-addressing hash table from (address, type) to a 32-bit value. Address 0 marks an
// empty slot (keys are never null). Clearing resets only the slots used since the last clear,
// so the save path's reference memo and region index are reused across calls without
// allocating, and a table grown once for a big graph costs nothing for later small states.
#ifndef SYMCR_SRC_ADDRESS_TABLE_HPP
#define SYMCR_SRC_ADDRESS_TABLE_HPP

#include <cstdint>
#include <cstring>
#include <vector>

namespace symcr::detail {

class AddressTable {
 public:
  void clear() {
    if (used_.size() * 4 > slots_.size()) {
      std::memset(static_cast<void*>(slots_.data()), 0, slots_.size() * sizeof(Slot));
    } else {
      for (std::uint32_t index : used_) slots_[index].address = 0;
    }
    used_.clear();
  }

  // Bytes held (slots and the used-slot list), for scratch statistics.
  std::size_t capacity_bytes() const {
    return slots_.capacity() * sizeof(Slot) + used_.capacity() * sizeof(std::uint32_t);
  }

  // Starts loading the key's first slot: the save path calls this for a struct's pointer
  // fields before encoding them, so their cache misses overlap instead of queueing.
  void prefetch(std::uintptr_t address, std::uint32_t type) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[hash(address, type) & (slots_.size() - 1)]);
  }

  // The value stored for the key, or nullptr.
  std::uint32_t* find(std::uintptr_t address, std::uint32_t type) {
    if (slots_.empty()) return nullptr;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash(address, type) & mask;; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.address == address && slot.type == type) return &slot.value;
      if (slot.address == 0) return nullptr;
    }
  }

  // The value slot for the key, inserting `initial` when absent (`inserted` tells which).
  std::uint32_t& find_or_insert(std::uintptr_t address, std::uint32_t type, std::uint32_t initial,
                                bool& inserted) {
    if ((used_.size() + 1) * 2 > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash(address, type) & mask;; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.address == address && slot.type == type) {
        inserted = false;
        return slot.value;
      }
      if (slot.address == 0) {
        slot = Slot{address, type, initial};
        used_.push_back(static_cast<std::uint32_t>(i));
        inserted = true;
        return slot.value;
      }
    }
  }

 private:
  struct Slot {
    std::uintptr_t address;
    std::uint32_t type;
    std::uint32_t value;
  };

  static std::size_t hash(std::uintptr_t address, std::uint32_t type) {
    std::uint64_t x =
        (static_cast<std::uint64_t>(address) ^ (std::uint64_t{type} << 47)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(x ^ (x >> 32));
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 64 : old.size() * 2, Slot{0, 0, 0});
    used_.clear();
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.address == 0) continue;
      std::size_t i = hash(slot.address, slot.type) & mask;
      while (slots_[i].address != 0) i = (i + 1) & mask;
      slots_[i] = slot;
      used_.push_back(static_cast<std::uint32_t>(i));
    }
  }

  std::vector<Slot> slots_;
  std::vector<std::uint32_t> used_;  // indices of occupied slots, for clear()
};

}  // namespace symcr::detail

#endif  // SYMCR_SRC_ADDRESS_TABLE_HPP
