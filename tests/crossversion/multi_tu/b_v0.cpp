#include "shared_v0.hpp"

namespace {
struct Log {
  std::vector<Waypoint> visited;  // the same std::vector<Waypoint> as Fleet::route
  std::string note;
};
SYMCR_CHECKPOINT Log flight_log;
}  // namespace

void fill_log() {
  flight_log.visited = {{5, 6}};
  flight_log.note = "b.cpp";
}
const std::vector<Waypoint>& log_route() { return flight_log.visited; }
