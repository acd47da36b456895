// Firmware V0 of the update test: the vehicle flies a mission and checkpoints it into the ring
// in backup SRAM, three times; then the firmware is replaced (firmware_v1.cpp).
#include <cstring>
#include <symcr/symcr.hpp>

#include "board.hpp"

enum class Mode : std::uint8_t { Stabilize = 0, AltHold = 2, Auto = 3, Land = 9 };
struct Waypoint {
  std::int32_t lat;
  std::int32_t lng;
  float alt;
};
struct Battery {
  std::uint32_t millivolts;
  std::uint16_t cycles;
};
struct Vehicle {
  bool armed;
  Mode mode;
  std::int16_t climb_rate;
  std::uint32_t retired_counter;  // V1 has no such member
  Battery battery;
  Waypoint mission[4];          // V1 holds six
  Waypoint* next;               // a reference by path
  std::uint8_t fence_radius_m;  // V1: fence_radius, 16 bits
  std::uint8_t mission_count;
};

SYMCR_CHECKPOINT Vehicle vehicle;

namespace {

void fly(int step) {
  vehicle.armed = true;
  vehicle.mode = step == 3 ? Mode::Land : Mode::Auto;
  vehicle.climb_rate = static_cast<std::int16_t>(-120 + step);
  vehicle.retired_counter = 0xC0FFEEu;
  vehicle.battery = Battery{15800u - 100u * static_cast<std::uint32_t>(step), 41};
  vehicle.mission_count = 4;
  for (int i = 0; i < 4; ++i) {
    vehicle.mission[i] = Waypoint{473977 + i, 85456 - i, 20.0f + 2.5f * static_cast<float>(i)};
  }
  vehicle.next = &vehicle.mission[step];
  vehicle.fence_radius_m = 200;
}

}  // namespace

int main() {
  std::memset(board::symcr_backup_sram.slots, 0, sizeof board::symcr_backup_sram.slots);
  const symcr::device::Build build = symcr::device::program_build();
  board::check(build.schema != nullptr && build.plan_count == 0, "V0: its own build, no plans");
  board::check(symcr::device::record_size(*build.schema) <= board::kSlotSize,
               "V0: a record fits a slot");
  symcr::device::Ring ring;
  board::check(ring.open(board::backup_storage(), board::kSlotSize) == symcr::device::Result::Ok,
               "V0: ring opened");
  for (int step = 1; step <= 3; ++step) {
    fly(step);
    board::check(ring.save(build, board::record, sizeof board::record) == symcr::device::Result::Ok,
                 "V0: checkpoint saved");
  }
  board::check(board::keep_backup(), "V0: backup SRAM kept across the update");
  std::printf("firmware-v0: %s\n", board::failures == 0 ? "SAVED" : "FAIL");
  return board::failures == 0 ? 0 : 1;
}
