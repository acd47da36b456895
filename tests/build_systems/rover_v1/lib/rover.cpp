// The rover's code, in a static library: the sidecar's restore point is inserted here.
#include <cstdio>

#include "rover.hpp"

void Rover::init() {
  route_.clear();
  mode_ = 0;
}

void Rover::print() const {
  std::printf("name=%s mode=%d yaw=%.2f steps=%u route=%zu\n", name_.c_str(), mode_, yaw_,
              steps_, route_.size());
  for (const Waypoint& w : route_) std::printf("  %.1f %.1f %.1f\n", w.lat, w.lon, w.speed);
}
