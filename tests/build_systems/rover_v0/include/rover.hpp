// v0 of a rover that knows nothing of checkpointing: no symcr include, macro or call. The
// sidecar .symcr at the project's root selects `rover` and saves it at the exit of Rover::step.
#pragma once
#include <string>
#include <vector>

struct Waypoint {
  double lat;
  double lon;
};

class Rover {
 public:
  void start(const char* name);
  int step();

 private:
  std::string name_;
  int mode_ = 0;
  float heading_ = 0;
  std::vector<Waypoint> route_;
  unsigned steps_ = 0;
};

extern Rover rover;
int clamp_steps(int steps);  // util.cpp: nothing of symcr's
