// What the clocks pair guards against: the same restart without clock annotations. The times
// come back as the dead process's clock wrote them, all in the new clock's future, so every
// "time since" wraps to about 4.29e9 ms and every timer and failsafe fires on the first loop.
#include <cstdint>
#include <memory>
#include <vector>

#include "check.hpp"

static std::uint32_t g_millis = 0;

struct Event {
  int code;
  std::uint32_t at_ms;
};

struct Failsafe {
  std::uint32_t last_heartbeat_ms;
  std::uint32_t radio_lost_ms;
  std::uint32_t gps_glitch_ms;
  std::uint32_t last_seen_ms[3];
};

struct Vehicle {
  std::uint32_t wp_start_ms;
  std::int64_t armed_us;
  std::uint32_t loiter_ms;
  std::uint32_t battery_ms;
  Failsafe failsafe;
  std::vector<Event> log;
  std::unique_ptr<Event> pending;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  g_millis = 10;  // restarted: the clock began again
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(report.count(symcr::Decision::Rebased) == 0);
  XV_CHECK(vehicle.wp_start_ms == 4800u);  // restored as saved
  const std::uint32_t leg_ms = g_millis - vehicle.wp_start_ms;
  const std::uint32_t silent_ms = g_millis - vehicle.failsafe.last_heartbeat_ms;
  std::printf("since the leg began: %u ms, since the last heartbeat: %u ms\n", leg_ms, silent_ms);
  XV_CHECK(leg_ms > 4000000000u);     // a 500 ms waypoint timer fires at once
  XV_CHECK(silent_ms > 4000000000u);  // and so does a 1 s heartbeat failsafe
  return xv::failures() == 0 ? 0 : 1;
}
