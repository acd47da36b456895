// v0 of a vehicle whose times are of two clocks, in the device profile's kinds only, so that
// `symcr convert` can carry its checkpoint to v1: the conversion must keep each time in step
// with its clock's reading.
#include <cstdint>

#include "check.hpp"

std::uint32_t hal_millis() { return 5000; }
std::uint64_t hal_micros64() { return 1000000000000ull; }
SYMCR_CLOCK(millis, hal_millis)
SYMCR_CLOCK(micros, hal_micros64)

typedef std::uint32_t time_ms SYMCR_TIME(millis);

struct Failsafe {
  time_ms last_heartbeat_ms;
  std::uint32_t gps_glitch_ms SYMCR_TIME(millis, never=0xFFFFFFFF);
};

struct Vehicle {
  time_ms wp_start_ms;
  time_ms near_ms;  // as long before the checkpoint as v1's --initial is saved after its start
  std::int64_t armed_us SYMCR_TIME(micros);
  std::uint32_t loiter_ms;  // a duration, not a time
  Failsafe failsafe;
  std::uint16_t cells[2];
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  vehicle.wp_start_ms = 4800;
  vehicle.near_ms = 4900;
  vehicle.armed_us = 999999000000ll;
  vehicle.loiter_ms = 1500;
  vehicle.failsafe.last_heartbeat_ms = 4990;
  vehicle.failsafe.gps_glitch_ms = 0xFFFFFFFFu;
  vehicle.cells[0] = 4999;
  vehicle.cells[1] = 3000;
  return xv::save(argc, argv);
}
