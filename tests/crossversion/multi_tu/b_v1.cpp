#include "shared_v1.hpp"

namespace {
struct Log {
  std::string note;
  std::vector<Waypoint> visited;
};
SYMCR_CHECKPOINT Log flight_log;
}  // namespace

const std::vector<Waypoint>& log_route() { return flight_log.visited; }
const std::string& log_note() { return flight_log.note; }
