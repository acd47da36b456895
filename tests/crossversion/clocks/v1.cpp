// v1, restarted: its millisecond clock starts again near zero and its microsecond clock has
// gone on. It marks its times in the three other ways: a typedef annotated once, SYMCR_TIME on
// members, and a pragma; v0's file-scope clocks are declared by SYMCR_CLOCK and a pragma. Each
// time is moved by its clock's advance in its own integer arithmetic (32-bit milliseconds
// wrap), a "never" value stays, a duration is not a time, and a time of a clock the checkpoint
// holds no reading of keeps this build's value. A live transfer in one process moves nothing.
#include <cstdint>
#include <memory>
#include <vector>

#include "check.hpp"

static std::uint32_t g_millis = 0;
static std::uint64_t g_micros = 0;
std::uint32_t hal_millis() { return g_millis; }
std::uint64_t hal_micros64() { return g_micros; }
namespace power {
std::uint32_t ticks() { return 77; }
}  // namespace power

SYMCR_CLOCK(millis, hal_millis)
#pragma symcr clock(hal_micros64)
#pragma symcr clock(power_ticks, power::ticks)

typedef std::uint32_t time_ms SYMCR_TIME(millis);

struct Event {
  int code;
  time_ms at_ms;
};

struct Failsafe {
  time_ms last_heartbeat_ms;
  time_ms radio_lost_ms;
  std::uint32_t gps_glitch_ms SYMCR_TIME(millis, never=0xFFFFFFFF);
  time_ms last_seen_ms[3];
};

struct Vehicle {
  time_ms wp_start_ms;
  std::int64_t armed_us SYMCR_TIME(hal_micros64);
  std::uint32_t loiter_ms;
  std::uint32_t battery_ms = 12345;
  Failsafe failsafe;
  std::vector<Event> log;
  std::unique_ptr<Event> pending;
};
#pragma symcr time(Vehicle::battery_ms, power_ticks)

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  g_millis = 10;
  g_micros = 1000000500000ull;  // 0.5 s after v0's checkpoint on this clock
  const bool live = xv::live_source() != nullptr;
  // Millisecond times move by 10 - 5000 = -4990 (mod 2^32); microsecond times by +500000.
  const std::uint32_t ms = live ? 0u : 0u - 4990u;
  const std::int64_t us = live ? 0 : 500000;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(vehicle.wp_start_ms == 4800u + ms);
  XV_CHECK(g_millis - vehicle.wp_start_ms == (live ? 10u - 4800u : 200u));  // still 200 ms in
  XV_CHECK(vehicle.armed_us == 999999000000ll + us);
  XV_CHECK(vehicle.loiter_ms == 1500u);
  XV_CHECK(vehicle.failsafe.last_heartbeat_ms == 4990u + ms);
  XV_CHECK(vehicle.failsafe.radio_lost_ms == 0u);
  XV_CHECK(vehicle.failsafe.gps_glitch_ms == 0xFFFFFFFFu);
  XV_CHECK(vehicle.failsafe.last_seen_ms[0] == 4999u + ms);
  XV_CHECK(vehicle.failsafe.last_seen_ms[1] == 0u);
  XV_CHECK(vehicle.failsafe.last_seen_ms[2] == 3000u + ms);
  XV_CHECK(vehicle.log.size() == 3);
  if (vehicle.log.size() == 3) {
    XV_CHECK(vehicle.log[0].at_ms == 1000u + ms);
    XV_CHECK(vehicle.log[1].at_ms == 0u);
    XV_CHECK(vehicle.log[2].at_ms == 4900u + ms);
  }
  XV_CHECK(vehicle.pending && vehicle.pending->at_ms == 4950u + ms);
  if (live) {
    // One process: its clocks are the checkpoint's; nothing is rebased or reported so.
    XV_CHECK(report.count(symcr::Decision::Rebased) == 0);
    XV_CHECK(vehicle.battery_ms == 12345u);  // no reading of power_ticks either way
  } else {
    XV_CHECK(xv::decided(report, "vehicle.wp_start_ms", symcr::Decision::Rebased));
    XV_CHECK(xv::decided(report, "vehicle.failsafe.last_seen_ms", symcr::Decision::Rebased));
    XV_CHECK(xv::decided(report, "vehicle.log[].at_ms", symcr::Decision::Rebased));
    const symcr::ReportEntry* millis = xv::entry(report, "(clock millis)");
    XV_CHECK(millis && millis->detail ==
                           "read 5000 at the checkpoint and 10 now: its times moved by -4990");
    const symcr::ReportEntry* micros = xv::entry(report, "(clock hal_micros64)");
    XV_CHECK(micros && micros->detail == "read 1000000000000 at the checkpoint and "
                                         "1000000500000 now: its times moved by 500000");
    XV_CHECK(vehicle.battery_ms == 12345u);
    const symcr::ReportEntry* battery = xv::entry(report, "vehicle.battery_ms");
    XV_CHECK(battery && battery->decision == symcr::Decision::Kept && battery->lossy);
  }
  return xv::failures() == 0 ? 0 : 1;
}
