// Firmware v2 of the watchdog example (README.md): the update. `waypoint` is now
// `mission_index`, the loop counter is 64 bits, the members are reordered, and the vehicle
// remembers its home altitude (a new member whose value only v2 knows).
#include <cstdint>
#include <cstdio>
#include <symcr/symcr.hpp>

#include "board.hpp"

struct Attitude {
  float roll, pitch, yaw;
};

struct Vehicle {
  bool armed;
  Attitude attitude;
  float battery_pct;
  std::int32_t mission_index SYMCR_RENAMED_FROM("waypoint");
  std::uint64_t loops;
  float home_alt_m;
};

SYMCR_CHECKPOINT Vehicle vehicle = {false, {0.0f, 0.0f, 0.0f}, 100.0f, 0, 0, 584.0f};

namespace board {

const char* const kVersion = "v2";

void fly_one_loop() {
  ++vehicle.loops;
  vehicle.armed = true;
  vehicle.battery_pct -= 0.04f;  // v2 draws less
  vehicle.attitude.yaw += 0.01f;
  if (vehicle.loops % 40 == 0) ++vehicle.mission_index;
}

void print_state() {
  std::printf("state: loops=%llu mission_index=%d battery=%.2f armed=%d yaw=%.2f home_alt=%.1f\n",
              static_cast<unsigned long long>(vehicle.loops), vehicle.mission_index,
              vehicle.battery_pct, vehicle.armed ? 1 : 0, vehicle.attitude.yaw, vehicle.home_alt_m);
}

std::uint64_t loop_count() { return vehicle.loops; }

}  // namespace board

int main(int argc, char** argv) { return board::run(argc, argv); }
