// v0: flight modes as a class hierarchy whose objects are members of the vehicle, and the
// current mode as a pointer to the base class, as autopilots keep it. The pointer is saved as
// a reference to the member it points at.
#include "check.hpp"

struct Mode {
  virtual ~Mode() = default;
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct ModeStabilize : Mode {
  int number() const override { return 0; }
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};

struct Copter {
  ModeStabilize mode_stabilize;
  ModeAuto mode_auto;
  ModeLoiter mode_loiter;
  Mode* flightmode = &mode_stabilize;
  Mode* previous = nullptr;
  // A callback bound to the vehicle itself: its object is a reference to the root.
  struct Callback {
    Copter* object;
    void (Copter::*method)();
  } on_mode_change{this, &Copter::announce};
  void announce() {}
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  copter.mode_auto.next_waypoint = 4;
  copter.mode_auto.entered_ms = 1234;
  copter.mode_loiter.radius_m = 7.5f;
  copter.previous = &copter.mode_loiter;
  copter.flightmode = &copter.mode_auto;
  return xv::save(argc, argv);
}
