// std::function reached from a root: diagnosed with the path and the fix.
#include <functional>

#include <symcr/symcr.hpp>

struct AP_AHRS {
  double roll;
  std::function<void()> backend;
};
struct Copter {
  AP_AHRS ahrs;
};
SYMCR_CHECKPOINT Copter copter;
