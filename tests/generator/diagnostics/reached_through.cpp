// The selection reaches a simulator object through a pointer: its unrestorable members are
// grouped under the member that leads there, with the one skip line that removes them all.
#include <functional>
#include <mutex>

#include <symcr/symcr.hpp>

struct Terrain;
struct Simulator {
  std::mutex lock;
  Terrain* terrain;
  std::function<void()> logger;
  float wind_speed;
};
Simulator simulator;

struct SimBackend {
  Simulator* sim = &simulator;
};
struct Ahrs {
  float roll, pitch, yaw;
  SimBackend sim_backend;
};
struct Vehicle {
  Ahrs ahrs;
  std::mutex lock;
};
SYMCR_CHECKPOINT Vehicle vehicle;
