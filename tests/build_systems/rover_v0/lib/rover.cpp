// The rover's code, in a static library: the sidecar's program point is inserted here.
#include "rover.hpp"

void Rover::start(const char* name) {
  name_ = name;
  mode_ = 1;
  for (int i = 0; i < 3; ++i) route_.push_back(Waypoint{10.0 + i, -20.0 - i});
}

int Rover::step() {
  ++steps_;
  heading_ += 1.5f;
  if (steps_ == 5) mode_ = 3;
  if (steps_ % 4 == 0) {
    route_.push_back(Waypoint{50.0 + steps_, 60.0});
    return static_cast<int>(steps_);  // an early return: the exit point is reached here too
  }
  return static_cast<int>(steps_);
}
