// Firmware v1 of the watchdog example (README.md): the vehicle's state, checkpointed by the
// device profile into backup RAM.
#include <cstdint>
#include <cstdio>
#include <symcr/symcr.hpp>

#include "board.hpp"

struct Attitude {
  float roll, pitch, yaw;
};

struct Vehicle {
  std::uint32_t loops;
  std::int32_t waypoint;  // the mission item being flown
  float battery_pct;
  bool armed;
  Attitude attitude;
};

SYMCR_CHECKPOINT Vehicle vehicle = {0, 0, 100.0f, false, {0.0f, 0.0f, 0.0f}};

namespace board {

const char* const kVersion = "v1";

void fly_one_loop() {
  ++vehicle.loops;
  vehicle.armed = true;
  vehicle.battery_pct -= 0.05f;
  vehicle.attitude.yaw += 0.01f;
  if (vehicle.loops % 40 == 0) ++vehicle.waypoint;
}

void print_state() {
  std::printf("state: loops=%u waypoint=%d battery=%.2f armed=%d yaw=%.2f\n", vehicle.loops,
              vehicle.waypoint, vehicle.battery_pct, vehicle.armed ? 1 : 0, vehicle.attitude.yaw);
}

std::uint64_t loop_count() { return vehicle.loops; }

}  // namespace board

int main(int argc, char** argv) { return board::run(argc, argv); }
