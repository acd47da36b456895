// v1's shared header: Waypoint gained a field.
#ifndef XV_MULTI_TU_SHARED_HPP
#define XV_MULTI_TU_SHARED_HPP

#include <string>
#include <vector>

#include "check.hpp"

struct Waypoint {
  double lon;
  double lat;
  float speed = 8.0f;
};

struct Fleet {
  int scratch = -1;
  std::vector<Waypoint> route;
};
#pragma symcr skip(Fleet::scratch)

extern Fleet fleet;
const std::vector<Waypoint>& log_route();
const std::string& log_note();

#endif
