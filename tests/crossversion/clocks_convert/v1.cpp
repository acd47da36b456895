// v1, restarted: its millisecond clock starts again near zero, its microsecond clock has gone
// on, and it has a clock v0 did not: a time of it and a new time of the millisecond clock keep
// this build's values. Members are reordered, an array grew, and a time has a range (checked
// as saved). Restored directly, by `symcr convert` and the device profile, or by the device's
// own cross-version plan, every time moves by its clock's advance since v0's checkpoint, and
// the times v0 had no value for stay as this build set them.
//
// XV_NOW_MS=<ms> restores at that millisecond reading instead of 100, a checkpoint `symcr
// convert --initial` wrote from a state saved at 100: the times it kept from that state have
// moved by the clock's advance since (convert_clocks.cmake).
#include <cstdint>
#include <cstdlib>

#include "check.hpp"

static std::uint32_t g_millis = 0;
static std::uint64_t g_micros = 0;
std::uint32_t hal_millis() { return g_millis; }
std::uint64_t hal_micros64() { return g_micros; }
std::uint32_t power_ticks() { return 77; }
SYMCR_CLOCK(millis, hal_millis)
SYMCR_CLOCK(micros, hal_micros64)
SYMCR_CLOCK(power, power_ticks)

typedef std::uint32_t time_ms SYMCR_TIME(millis);

struct Failsafe {
  std::uint32_t gps_glitch_ms SYMCR_TIME(millis, never=0xFFFFFFFF);
  time_ms last_heartbeat_ms;
};

struct Vehicle {
  Failsafe failsafe;
  std::int64_t armed_us SYMCR_TIME(micros);
  time_ms wp_start_ms SYMCR_RANGE(0, 100000);
  time_ms near_ms;
  std::uint16_t cells[3];
  time_ms landed_ms = 60;
  std::uint32_t battery_ticks SYMCR_TIME(power) = 70;
  std::uint32_t loiter_ms;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  const char* now_ms = std::getenv("XV_NOW_MS");
  g_millis = now_ms ? static_cast<std::uint32_t>(std::strtoul(now_ms, nullptr, 10)) : 100u;
  const std::uint32_t kept_moved = g_millis - 100u;  // 0 unless restoring a conversion later
  g_micros = 1000000500000ull;  // 0.5 s after v0's checkpoint on this clock
  const bool live = xv::live_source() != nullptr;  // one process: nothing moves
  const std::uint32_t ms = live ? 0u : g_millis - 5000u;  // mod 2^32
  const std::int64_t us = live ? 0 : 500000;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(vehicle.wp_start_ms == 4800u + ms);
  XV_CHECK(g_millis - vehicle.wp_start_ms == (live ? 100u - 4800u : 200u));  // 200 ms in
  XV_CHECK(vehicle.near_ms == 4900u + ms);
  XV_CHECK(vehicle.armed_us == 999999000000ll + us);
  XV_CHECK(vehicle.loiter_ms == 1500u);
  XV_CHECK(vehicle.failsafe.last_heartbeat_ms == 4990u + ms);
  XV_CHECK(vehicle.failsafe.gps_glitch_ms == 0xFFFFFFFFu);
  XV_CHECK(vehicle.cells[0] == 4999u && vehicle.cells[1] == 3000u && vehicle.cells[2] == 0u);
  XV_CHECK(vehicle.landed_ms == 60u + kept_moved);
  XV_CHECK(vehicle.battery_ticks == 70u);
  if (!live) XV_CHECK(xv::decided(report, "vehicle.wp_start_ms", symcr::Decision::Rebased));
  if (live) XV_CHECK(report.count(symcr::Decision::Rebased) == 0);
  return xv::verdict();
}
