// State the device profile cannot hold: each member below is diagnosed with its path and fix.
#include <symcr/symcr.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct Waypoint {
  float lat, lng;
  std::string label;  // heap
};

struct Base {
  std::optional<int> trim;
};

struct Vehicle : Base {
  int mode = 0;
  Waypoint waypoints[4];          // an array of structs holding a string
  std::vector<int> log;           // a container
  std::unique_ptr<Waypoint> next; // owning pointer
  std::array<double, 3> gains{};  // fine
  Vehicle* self = nullptr;        // fine: a reference by path
  SYMCR_SKIP std::string name;    // fine: skipped
};

SYMCR_CHECKPOINT Vehicle vehicle;
