// v0's shared header: types reached from roots in two translation units.
#ifndef XV_MULTI_TU_SHARED_HPP
#define XV_MULTI_TU_SHARED_HPP

#include <string>
#include <vector>

#include "check.hpp"

struct Waypoint {
  double lat;
  double lon;
};

struct Fleet {
  std::vector<Waypoint> route;
  int scratch;  // skipped by the pragma below, in every TU that includes this header
};
#pragma symcr skip(Fleet::scratch)

extern Fleet fleet;           // defined in a.cpp
void fill_log();              // b.cpp
const std::vector<Waypoint>& log_route();

#endif
