// v1 of the rover, a patched build: members reordered, `heading_` renamed `yaw_` and widened
// to double, a waypoint field added. The sidecar restores `rover` at the exit of Rover::init.
#pragma once
#include <string>
#include <vector>

struct Waypoint {
  double lon;
  double lat;
  float speed = 2.5f;  // new in v1: keeps this default
};

class Rover {
 public:
  void init();
  void print() const;

 private:
  unsigned steps_ = 0;
  std::vector<Waypoint> route_;
  double yaw_ = -1;
  int mode_ = 0;
  std::string name_ = "unnamed";
};

extern Rover rover;
const char* banner();  // util.cpp: nothing of symcr's
