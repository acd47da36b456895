// What both firmwares of the update test share: the board's backup SRAM (a ring of slots that
// a reset and a firmware update leave alone) and the checks' output. QEMU starts each firmware
// in a machine of its own, so the backup SRAM's bytes cross the update through a file on the
// host (semihosting): what V0 left in it is there when V1 boots.
#ifndef SYMCR_DEVICE_UPDATE_BOARD_HPP
#define SYMCR_DEVICE_UPDATE_BOARD_HPP

#include <cstdint>
#include <cstdio>

#include "symcr/device.hpp"

namespace board {

constexpr std::size_t kSlotSize = 512;
constexpr std::size_t kSlots = 4;
constexpr const char* kBackupFile = "backup_sram.bin";

struct Backup {
  alignas(8) std::uint8_t slots[kSlots * kSlotSize];
};
extern "C" Backup symcr_backup_sram;  // placed by the linker script, outside the image

alignas(8) std::uint8_t record[kSlotSize];
alignas(8) std::uint8_t scratch[1024];
int failures = 0;

inline void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}

inline symcr::device::Storage backup_storage() {
  return symcr::device::memory_storage(symcr_backup_sram.slots, sizeof symcr_backup_sram.slots);
}

// The backup SRAM as the previous firmware left it (or all zero at the first power-on).
inline bool load_backup() {
  std::FILE* file = std::fopen(kBackupFile, "rb");
  if (file == nullptr) return false;
  const std::size_t n =
      std::fread(symcr_backup_sram.slots, 1, sizeof symcr_backup_sram.slots, file);
  std::fclose(file);
  return n == sizeof symcr_backup_sram.slots;
}

inline bool keep_backup() {
  std::FILE* file = std::fopen(kBackupFile, "wb");
  if (file == nullptr) return false;
  const std::size_t n =
      std::fwrite(symcr_backup_sram.slots, 1, sizeof symcr_backup_sram.slots, file);
  return std::fclose(file) == 0 && n == sizeof symcr_backup_sram.slots;
}

}  // namespace board

#endif  // SYMCR_DEVICE_UPDATE_BOARD_HPP
