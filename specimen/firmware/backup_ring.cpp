#include "backup_ring.hpp"

#include <cstdio>

namespace firmware {
namespace {

constexpr std::uint32_t kBackupMagic = 0x53594D42u;  // "SYMB"

// The board's backup RAM: no segment of the image covers it, so neither loading nor a reset
// touches it (cmake/boards/mps2-an386/mps2_an386.ld places the symbol).
struct Backup {
  std::uint32_t magic;
  std::uint32_t boots;
  alignas(8) std::uint8_t slots[kSlots * kSlotSize];
};
extern "C" Backup symcr_backup_sram;

symcr::device::Ring ring;
alignas(8) std::uint8_t record[kSlotSize];
alignas(8) std::uint8_t scratch[4096];

}  // namespace

bool open_backup_ring() {
  Backup& backup = symcr_backup_sram;
  if (backup.magic != kBackupMagic) {  // power-on: RAM holds noise
    backup.magic = kBackupMagic;
    backup.boots = 0;
    for (std::uint8_t& byte : backup.slots) byte = 0;
  }
  ++backup.boots;
  const symcr::device::Result opened =
      ring.open(symcr::device::memory_storage(backup.slots, sizeof backup.slots), kSlotSize);
  if (opened != symcr::device::Result::Ok) {
    std::printf("checkpoint: %s\n", symcr::device::result_text(opened));
    return false;
  }
  return true;
}

symcr::device::Ring& backup_ring() { return ring; }
std::uint8_t* backup_slots() { return symcr_backup_sram.slots; }
std::uint32_t boot_count() { return symcr_backup_sram.boots; }
std::uint8_t* record_buffer() { return record; }
std::size_t record_capacity() { return sizeof record; }
std::uint8_t* scratch_buffer() { return scratch; }
std::size_t scratch_capacity() { return sizeof scratch; }

}  // namespace firmware
