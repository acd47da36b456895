// The device profile as a microcontroller runs it: built for a Cortex-M4 with
// gcc-arm-none-eabi, run under qemu-system-arm (mps2-an386) with semihosting for output. The
// ring lives in RAM that a reset leaves alone (mps2_an386.ld), as backup SRAM: the first boot
// saves and then resets the machine the way a watchdog would (SYSRESETREQ); the second finds
// its state back at its initial value and restores it from the ring.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "symcr/device.hpp"
#include "vehicle.hpp"

namespace {

using device_tests::fill;
using device_tests::holds;
using device_tests::kSchema;
using device_tests::vehicle;
using symcr::device::Result;

constexpr std::uint32_t kBackupMagic = 0x53594D43u;  // "SYMC"
constexpr std::size_t kSlotSize = 512;
constexpr std::size_t kSlots = 4;

// Backup SRAM: not in the image, so neither loading nor a reset touches it.
struct Backup {
  std::uint32_t magic;
  std::uint32_t boot;
  std::uint8_t slots[kSlots * kSlotSize];
};
extern "C" Backup symcr_backup_sram;  // placed by the linker script
Backup& backup = symcr_backup_sram;

std::uint8_t record[kSlotSize];
std::uint8_t scratch[256];

const symcr::device::Build kBuild{&kSchema, 0x5EED0001DEC0DE01ull};
int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}

bool untouched_after(Result expected, const std::uint8_t* bytes, std::size_t size,
                     const char* what) {
  std::uint8_t before[sizeof vehicle];
  std::memcpy(before, &vehicle, sizeof vehicle);
  const Result result = symcr::device::restore(kBuild, bytes, size, scratch, sizeof scratch);
  const bool same = std::memcmp(before, &vehicle, sizeof vehicle) == 0;
  if (result != expected) std::printf("  %s: %s\n", what, symcr::device::result_text(result));
  return result == expected && same;
}

[[noreturn]] void watchdog_reset() {
  std::fflush(stdout);
  *reinterpret_cast<volatile std::uint32_t*>(0xE000ED0Cu) = 0x05FA0004u;  // AIRCR.SYSRESETREQ
  for (;;) {
  }
}

void first_boot() {
  check(sizeof scratch >= symcr::device::scratch_size(kSchema), "scratch fits the roots");
  // A round trip through a buffer.
  fill(4);
  std::size_t size = 0;
  check(symcr::device::save(kBuild, 1, record, sizeof record, &size) == Result::Ok, "save");
  const device_tests::Vehicle zero{};
  std::memcpy(static_cast<void*>(&vehicle), &zero, sizeof vehicle);
  check(symcr::device::restore(kBuild, record, size, scratch, sizeof scratch) == Result::Ok &&
            holds(4),
        "round trip");
  // Damaged and foreign records are refused, the state untouched.
  fill(5);
  record[size - 20] ^= 0x01;
  check(untouched_after(Result::Corrupt, record, size, "corrupt") && holds(5),
        "corrupt record refused, state untouched");
  record[size - 20] ^= 0x01;
  check(untouched_after(Result::Truncated, record, size - 1, "truncated") && holds(5),
        "truncated record refused, state untouched");
  const symcr::device::Build other{&kSchema, kBuild.schema_hash + 1};
  check(
      symcr::device::restore(other, record, size, scratch, sizeof scratch) == Result::OtherSchema &&
          holds(5),
      "another build's record refused");
  // The ring in backup SRAM: three checkpoints, then the reset.
  symcr::device::Ring ring;
  check(ring.open(symcr::device::memory_storage(backup.slots, sizeof backup.slots), kSlotSize) ==
            Result::Ok,
        "ring opened");
  for (int seed = 1; seed <= 3; ++seed) {
    fill(seed);
    check(ring.save(kBuild, record, sizeof record) == Result::Ok, "ring save");
  }
}

void second_boot() {
  const device_tests::Vehicle zero{};
  check(std::memcmp(&vehicle, &zero, sizeof vehicle) == 0, "after the reset: initial state");
  symcr::device::Ring ring;
  check(ring.open(symcr::device::memory_storage(backup.slots, sizeof backup.slots), kSlotSize) ==
                Result::Ok &&
            ring.last_sequence() == 3,
        "ring found its checkpoints");
  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  Result result = ring.restore_latest(kBuild, record, sizeof record, scratch, sizeof scratch,
                                      &sequence, nullptr, &skipped);
  check(result == Result::Ok && sequence == 3 && skipped == 0 && holds(3),
        "restored the newest checkpoint");
  // The newest slot damaged (slot 2 holds sequence 3): the one before it comes back.
  backup.slots[2 * kSlotSize + 90] ^= 0x10;
  result = ring.restore_latest(kBuild, record, sizeof record, scratch, sizeof scratch, &sequence,
                               nullptr, &skipped);
  check(result == Result::Ok && sequence == 2 && skipped == 1 && holds(2),
        "ring fell back past the damaged slot");
}

}  // namespace

int main() {
  if (backup.magic != kBackupMagic) {  // power-on: backup SRAM holds garbage
    std::memset(&backup, 0, sizeof backup);
    backup.magic = kBackupMagic;
  }
  ++backup.boot;
  std::printf("device-test: boot %u\n", static_cast<unsigned>(backup.boot));
  if (backup.boot == 1) {
    first_boot();
    if (failures == 0) watchdog_reset();
  } else if (backup.boot == 2) {
    second_boot();
  } else {
    check(false, "booted more than twice");
  }
  backup.magic = 0;  // the next run powers on afresh
  std::printf("device-test: %s\n", failures == 0 ? "PASS" : "FAIL");
  return failures == 0 ? 0 : 1;
}
