// v0: a vehicle whose times belong to two clocks of its process: a 32-bit millisecond clock
// that starts at zero with the process (as a flight controller's HAL clock does) and a 64-bit
// microsecond clock. The annotation file v0.symcr declares the clocks and marks the times.
#include <cstdint>
#include <memory>
#include <vector>

#include "check.hpp"

// The clocks read what the program says "now" is: the test sets them.
static std::uint32_t g_millis = 0;
static std::uint64_t g_micros = 0;
std::uint32_t hal_millis() { return g_millis; }
std::uint64_t hal_micros64() { return g_micros; }

struct Event {
  int code;
  std::uint32_t at_ms;
};

struct Failsafe {
  std::uint32_t last_heartbeat_ms;
  std::uint32_t radio_lost_ms;     // 0: the radio was never lost ("never")
  std::uint32_t gps_glitch_ms;     // 0xFFFFFFFF: "never" by its own annotation
  std::uint32_t last_seen_ms[3];   // per sensor
};

struct Vehicle {
  std::uint32_t wp_start_ms;
  std::int64_t armed_us;           // a time of the microsecond clock
  std::uint32_t loiter_ms;         // a plain duration, not a time: never moved
  std::uint32_t battery_ms;        // a time in v0; v1 reads it with a clock v0 does not have
  Failsafe failsafe;
  std::vector<Event> log;
  std::unique_ptr<Event> pending;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  g_millis = 5000;
  g_micros = 1000000000000ull;
  vehicle.wp_start_ms = 4800;                // 200 ms into the leg
  vehicle.armed_us = 999999000000ll;         // armed 1,000 s ago
  vehicle.loiter_ms = 1500;
  vehicle.battery_ms = 4000;
  vehicle.failsafe = Failsafe{4990, 0, 0xFFFFFFFFu, {4999, 0, 3000}};
  vehicle.log = {Event{1, 1000}, Event{2, 0}, Event{3, 4900}};
  vehicle.pending.reset(new Event{4, 4950});
  return xv::save(argc, argv);
}
