#include <symcr/symcr.hpp>
namespace nav {
struct Waypoint {
  double lat, lon;
};
SYMCR_CHECKPOINT Waypoint home{48.125, 11.5};
SYMCR_CHECKPOINT int waypoint_index = 0;
void advance() { ++waypoint_index; }
}  // namespace nav
