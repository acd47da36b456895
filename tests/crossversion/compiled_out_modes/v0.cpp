// v0 of compiled_out_modes: flight modes as an autopilot declares them: virtual functions
// defined out of line (a class's vtable is emitted only where its first one, the key function,
// is defined) and no virtual destructor (the program never deletes a mode through a base
// pointer). Every mode is built in v0; heap objects of ModeAuto and ModeSport are saved as their
// classes, and the generated code deletes them as such without a warning under -Werror.
#include <new>

#include "check.hpp"

struct Mode {
  virtual const char* name() const;
  unsigned entered_ms = 0;
};
struct ModeAuto : Mode {
  const char* name() const override;
  int next_waypoint = 0;
};
struct ModeSport : Mode {
  const char* name() const override;
  float rate_dps = 0;
};
const char* Mode::name() const { return "MODE"; }
const char* ModeAuto::name() const { return "AUTO"; }
const char* ModeSport::name() const { return "SPORT"; }

struct Vehicle {
  ModeAuto mode_auto;
  Mode* flightmode = nullptr;  // a member of the state
  Mode* planned = nullptr;     // a heap ModeAuto
  Mode* sport = nullptr;       // a heap ModeSport
  int ticks = 0;
};

SYMCR_CHECKPOINT Vehicle vehicle;

// As `delete` would, without deleting through a class whose destructor is not virtual.
template <typename T>
void destroy(T* object) {
  object->~T();
  ::operator delete(object);
}

int main(int argc, char** argv) {
  vehicle.mode_auto.next_waypoint = 3;
  vehicle.flightmode = &vehicle.mode_auto;
  ModeAuto* planned = new ModeAuto();
  planned->next_waypoint = 9;
  planned->entered_ms = 40;
  ModeSport* sport = new ModeSport();
  sport->rate_dps = 90;
  vehicle.planned = planned;
  vehicle.sport = sport;
  vehicle.ticks = 12;
  const int saved = xv::save(argc, argv);
  destroy(planned);
  destroy(sport);
  return xv::failures() ? 1 : saved;
}
