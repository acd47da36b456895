// v0: a pilot's behaviours, heap objects of classes derived from the polymorphic Behavior, held
// through Behavior pointers. Each is saved as its own class; v1 changes those classes' members.
#include <cstdint>
#include <vector>

#include "check.hpp"

struct Behavior {
  virtual ~Behavior() {}
  virtual int kind() const = 0;
  std::int32_t ticks = 0;
};
// v1: gains bank_deg, loses laps.
struct Orbit : Behavior {
  int kind() const override { return 1; }
  double radius_m = 0;
  std::int32_t laps = 0;
};
// v1: rate widens to int32, target_m is renamed target_alt_m.
struct Climb : Behavior {
  int kind() const override { return 2; }
  std::int16_t rate = 0;
  float target_m = 0;
};
// v1: hold_s narrows to float (lossy: a double rounds).
struct Hover : Behavior {
  int kind() const override { return 3; }
  double hold_s = 0;
};
// Unchanged in v1.
struct Land : Behavior {
  int kind() const override { return 4; }
  float descent_mps = 0;
};

struct Pilot {
  Behavior* active = nullptr;
  std::vector<Behavior*> queue;
};

SYMCR_CHECKPOINT Pilot pilot;

int main(int argc, char** argv) {
  Orbit* orbit = new Orbit;
  orbit->ticks = 20;
  orbit->radius_m = 150.5;
  orbit->laps = 3;
  Climb* climb = new Climb;
  climb->ticks = 5;
  climb->rate = -120;
  climb->target_m = 42.25f;
  Hover* hover = new Hover;
  hover->ticks = 7;
  hover->hold_s = 2.5;
  Land* land = new Land;
  land->descent_mps = 0.75f;
  pilot.active = orbit;
  pilot.queue = {climb, hover, orbit, land};
  const int saved = xv::save(argc, argv);
  delete orbit;
  delete climb;
  delete hover;
  delete land;
  return saved;
}
