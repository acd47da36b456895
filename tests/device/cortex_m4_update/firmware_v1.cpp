// Firmware V1 of the update test, built with PREVIOUS_SCHEMA firmware_v0's schema file: members
// added, removed, reordered and renamed, an integer widened, an enum renumbered, an array
// grown. After the update's reset it restores V0's newest checkpoint from the ring through the
// plan symcr-gen embedded, and checks every value; a record of an unknown build is refused
// first, leaving the state initial.
#include <symcr/symcr.hpp>

#include "board.hpp"

enum class Mode : std::uint8_t { Land = 1, Stabilize = 2, Auto = 4, AltHold = 5, Guided = 6 };
struct Waypoint {
  float alt;
  std::int32_t lng;
  std::int32_t lat;
  std::uint16_t speed = 5;  // added
};
struct Battery {
  std::uint16_t cycles;
  std::uint32_t millivolts;
};
struct Vehicle {
  Mode mode = Mode::Stabilize;
  bool armed = false;
  Battery battery{};
  std::int32_t climb_rate SYMCR_RANGE(-500, 500) = 0;  // widened from 16 bits
  Waypoint mission[6];                                 // grown from 4
  std::uint8_t mission_count = 0;
  Waypoint* next = nullptr;
  std::uint16_t fence_radius SYMCR_RENAMED_FROM("fence_radius_m") = 50;
  std::uint32_t boots_since_update = 1;  // added
};

SYMCR_CHECKPOINT Vehicle vehicle;

namespace {

using symcr::device::Result;

bool initial() {
  bool same = vehicle.mode == Mode::Stabilize && !vehicle.armed && vehicle.battery.cycles == 0 &&
              vehicle.battery.millivolts == 0 && vehicle.climb_rate == 0 &&
              vehicle.mission_count == 0 && vehicle.next == nullptr && vehicle.fence_radius == 50 &&
              vehicle.boots_since_update == 1;
  for (const Waypoint& w : vehicle.mission) {
    same = same && w.alt == 0.0f && w.lng == 0 && w.lat == 0 && w.speed == 5;
  }
  return same;
}

// V0's third checkpoint, as V1 holds it.
bool restored_from_v0() {
  bool same = vehicle.mode == Mode::Land && vehicle.armed && vehicle.climb_rate == -117 &&
              vehicle.battery.millivolts == 15500u && vehicle.battery.cycles == 41 &&
              vehicle.mission_count == 4 && vehicle.next == &vehicle.mission[3] &&
              vehicle.fence_radius == 200 && vehicle.boots_since_update == 1;
  for (int i = 0; i < 4; ++i) {
    const Waypoint& w = vehicle.mission[i];
    same = same && w.lat == 473977 + i && w.lng == 85456 - i &&
           w.alt == 20.0f + 2.5f * static_cast<float>(i) && w.speed == 5;
  }
  for (int i = 4; i < 6; ++i) {  // V0 had no such waypoints: their initial values
    const Waypoint& w = vehicle.mission[i];
    same = same && w.lat == 0 && w.lng == 0 && w.alt == 0.0f && w.speed == 5;
  }
  return same;
}

}  // namespace

int main() {
  board::check(board::load_backup(), "V1: backup SRAM as V0 left it");
  const symcr::device::Build build = symcr::device::program_build();
  board::check(build.schema != nullptr && build.plan_count == 1, "V1: carries V0's plan");
  board::check(initial(), "V1: after the update's reset, the initial state");
  symcr::device::Ring ring;
  board::check(ring.open(board::backup_storage(), board::kSlotSize) == Result::Ok &&
                   ring.last_sequence() == 3,
               "V1: ring found V0's three checkpoints");

  // A record of a build V1 has no plan for: refused, nothing changed.
  std::size_t size = 0;
  const symcr::device::Build unknown(build.schema, build.schema_hash ^ 0x5A5Au);
  board::check(
      symcr::device::save(unknown, 9, board::record, sizeof board::record, &size) == Result::Ok,
      "V1: a record of an unknown build");
  board::check(symcr::device::restore(build, board::record, size, board::scratch,
                                      sizeof board::scratch) == Result::OtherSchema &&
                   initial(),
               "V1: the unknown build's record refused, the state initial");

  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  const Result result =
      ring.restore_latest(build, board::record, sizeof board::record, board::scratch,
                          sizeof board::scratch, &sequence, nullptr, &skipped);
  if (result != Result::Ok)
    std::printf("  restore_latest: %s\n", symcr::device::result_text(result));
  board::check(result == Result::Ok && sequence == 3 && skipped == 0,
               "V1: restored V0's newest checkpoint");
  board::check(restored_from_v0(), "V1: every value of V0's checkpoint, as V1 holds it");

  // V1 goes on in its own format: its next checkpoint is its own build's.
  vehicle.boots_since_update = 2;
  board::check(ring.save(build, board::record, sizeof board::record) == Result::Ok &&
                   ring.last_sequence() == 4,
               "V1: saves its own checkpoint after V0's");
  vehicle.boots_since_update = 7;
  board::check(ring.restore_latest(build, board::record, sizeof board::record, board::scratch,
                                   sizeof board::scratch, &sequence) == Result::Ok &&
                   sequence == 4 && vehicle.boots_since_update == 2 && vehicle.mode == Mode::Land,
               "V1: restores its own checkpoint");
  std::printf("firmware-v1: %s\n", board::failures == 0 ? "PASS" : "FAIL");
  return board::failures == 0 ? 0 : 1;
}
