// v0: no ranges and no validation hooks; writes values some of which v1 declares invalid.
#include <vector>

#include "check.hpp"

struct Motor {
  float rpm;
  int gear;
  float temp;
};

namespace nav {
struct Leg {
  int from;
  int to;
};
struct Waypoint {
  double lat;
  double alt;
};
}  // namespace nav

struct Battery {
  float volts;
  std::vector<int> cells;
};

SYMCR_CHECKPOINT Motor motor;
SYMCR_CHECKPOINT nav::Leg legs[3];
SYMCR_CHECKPOINT nav::Waypoint waypoint;
SYMCR_CHECKPOINT Battery battery;
SYMCR_CHECKPOINT Battery spare;

int main(int argc, char** argv) {
  motor = Motor{20000.0f, 3, 200.0f};  // rpm and temp out of v1's ranges, gear in
  legs[0] = nav::Leg{5, 6};
  legs[1] = nav::Leg{7, 7};  // fails v1's symcr_validate (a hidden friend)
  legs[2] = nav::Leg{8, 9};
  waypoint = nav::Waypoint{48.5, -10.0};  // fails v1's nav::symcr_validate
  battery = Battery{-1.0f, {9, 9, 9}};    // fails v1's global symcr_validate
  spare = Battery{11.5f, {4, 5}};         // passes it
  return xv::save(argc, argv);
}
