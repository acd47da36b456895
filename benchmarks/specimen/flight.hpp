// A realistic in-flight state for the specimen benchmarks: the world (physics, sensors, ground
// station of specimen/world) and the autopilot (specimen/autopilot) in one process, in the same
// lock-step as sitl_world and the autopilot's main.cpp, with the ground-control link over a
// socket pair. The ground station uploads the mission, sets AUTO and arms; the copter takes off
// and flies the route until `until_item` is the current mission item. The checkpoint root
// `copter` then holds what a checkpoint during a real flight holds: a loaded command list, a
// running mission, an aligned and healthy AHRS, armed flags, targets.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_FLIGHT_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_FLIGHT_HPP

#include <string>

namespace specimen_bench {

struct FlightResult {
  bool ok = false;
  std::string error;
  double seconds = 0;     // simulated flight time
  int mission_items = 0;  // commands in the autopilot's mission
  int current_item = -1;  // the ground station's view of the current mission item
};

// Flies `mission_file` (QGC WPL 110) until the mission's current item is `until_item` (or
// `limit_s` of simulated time pass). Calls copter.setup() first: call it once per process.
FlightResult fly(const std::string& mission_file, int until_item, double limit_s = 600.0);

}  // namespace specimen_bench

#endif  // SYMCR_BENCHMARKS_SPECIMEN_FLIGHT_HPP
