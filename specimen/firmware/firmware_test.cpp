// The specimen's checkpoints on a microcontroller, under qemu-system-arm (mps2-an386): the
// autopilot's own code and symcr-gen's tables for it, built for a Cortex-M4, with the device
// profile's ring in backup RAM.
//
//   boot 1: the vehicle aligns, takes its mission, arms in AUTO and flies; its scheduler
//           checkpoints it every 50 loops; then the machine resets the way a watchdog does.
//   boot 2: the vehicle is back at its initial state; a damaged record and another build's
//           are refused with the state untouched; the newest checkpoint is restored (armed, AUTO,
//           the flight mode pointer at the same mode object, every saved value equal: saving
//           again gives the same bytes); it flies on; with the newest slot damaged, the ring
//           falls back to the one before.
#include <cstdio>
#include <cstring>

#include "AP_Checkpoint.hpp"
#include "Copter.hpp"
#include "backup_ring.hpp"
#include "vehicle_sim.hpp"

namespace {

using symcr::device::Result;

constexpr std::uint32_t kEvery = 50;
int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}

[[noreturn]] void watchdog_reset() {
  std::fflush(stdout);
  *reinterpret_cast<volatile std::uint32_t*>(0xE000ED0Cu) = 0x05FA0004u;  // AIRCR.SYSRESETREQ
  for (;;) {
  }
}

// The newest slot's record, copied out of the ring.
std::size_t newest_record(std::uint8_t* out, std::size_t capacity, std::size_t* slot) {
  symcr::device::Ring& ring = firmware::backup_ring();
  *slot = static_cast<std::size_t>((ring.last_sequence() - 1) % ring.slot_count());
  const std::size_t size = firmware::kSlotSize < capacity ? firmware::kSlotSize : capacity;
  std::memcpy(out, firmware::backup_slots() + *slot * firmware::kSlotSize, size);
  return size;
}

bool refused_untouched(Result expected, const symcr::device::Build& build,
                       const std::uint8_t* record, std::size_t size, const char* what) {
  static std::uint8_t before[sizeof(Copter)];
  std::memcpy(before, static_cast<const void*>(&copter), sizeof before);
  const Result result = symcr::device::restore(build, record, size, firmware::scratch_buffer(),
                                               firmware::scratch_capacity());
  if (result != expected) std::printf("  %s: %s\n", what, symcr::device::result_text(result));
  return result == expected &&
         std::memcmp(before, static_cast<const void*>(&copter), sizeof before) == 0;
}

void first_boot() {
  check(firmware::start_mission(), "the vehicle armed in AUTO with its mission");
  firmware::fly(400);
  check(copter.armed() && copter.get_mode() == Mode::AUTO, "flying the mission");
  check(firmware::backup_ring().last_sequence() >= 8, "checkpoints saved by the scheduler");
  std::printf("boot 1: %u checkpoints; watchdog reset\n",
              static_cast<unsigned>(firmware::backup_ring().last_sequence()));
  watchdog_reset();
}

void second_boot() {
  check(
      !copter.armed() && copter.get_mode() == Mode::STABILIZE && copter.mission.num_commands() == 0,
      "after the reset the vehicle is at its initial state");
  static std::uint8_t record[firmware::kSlotSize];
  std::size_t slot = 0;
  const std::size_t size = newest_record(record, sizeof record, &slot);
  const symcr::device::Build build = symcr::device::program_build();

  record[200] ^= 0x10;
  check(refused_untouched(Result::Corrupt, build, record, size, "damaged"),
        "a damaged record is refused, the vehicle untouched");
  record[200] ^= 0x10;
  const symcr::device::Build other{build.schema, build.schema_hash ^ 1u};
  check(refused_untouched(Result::OtherSchema, other, record, size, "other build"),
        "another build's record is refused, the vehicle untouched");

  check(checkpointing.restore(), "the newest checkpoint restored");
  copter.resume_after_restore();
  check(copter.armed() && copter.get_mode() == Mode::AUTO && copter.mission.num_commands() == 4,
        "armed, in AUTO (the mode pointer at the same mode object), with its mission");
  // Every saved value came back: the restored vehicle saves to the same bytes.
  static std::uint8_t again[firmware::kSlotSize];
  std::size_t again_size = 0;
  std::uint64_t sequence = 0;
  std::memcpy(&sequence, record + 16, sizeof sequence);  // the header's sequence (docs/format.md)
  check(symcr::device::save(build, sequence, again, sizeof again, &again_size) == Result::Ok &&
            again_size <= size && std::memcmp(again, record, again_size) == 0,
        "every saved value restored (saving again gives the same record)");

  firmware::fly(200);
  check(copter.armed() && copter.get_mode() == Mode::AUTO, "the vehicle flies on");

  // The newest slot damaged: the ring falls back to the slot before it.
  symcr::device::Ring& ring = firmware::backup_ring();
  const std::uint64_t newest = ring.last_sequence();
  firmware::backup_slots()[((newest - 1) % ring.slot_count()) * firmware::kSlotSize + 100] ^= 0x01;
  std::uint64_t restored_sequence = 0;
  std::size_t skipped = 0;
  const Result fallback = ring.restore_latest(
      build, firmware::record_buffer(), firmware::record_capacity(), firmware::scratch_buffer(),
      firmware::scratch_capacity(), &restored_sequence, nullptr, &skipped);
  check(fallback == Result::Ok && skipped == 1 && restored_sequence == newest - 1,
        "a damaged newest slot: the ring restores the one before");
}

}  // namespace

int main() {
  copter.setup();
  if (!checkpointing.init(AP_Checkpoint::Method::Symcr, nullptr, kEvery)) {
    std::printf("firmware-test: FAILED to open the ring\n");
    return 1;
  }
  std::printf("boot %u\n", static_cast<unsigned>(firmware::boot_count()));
  if (firmware::boot_count() == 1) first_boot();
  second_boot();
  std::printf("firmware-test: %s\n", failures == 0 ? "PASS" : "FAILED");
  return failures == 0 ? 0 : 1;
}
