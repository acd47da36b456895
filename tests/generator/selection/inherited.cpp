// Members inherited from a base are named through the derived class, in a pragma and in the
// annotation file (inherited.symcr), as C++ names them: Copter::ahrs is Vehicle::ahrs.
#include <symcr/symcr.hpp>

struct Ahrs {
  float roll, pitch, yaw;
};
struct Vehicle {
  Ahrs ahrs;
  int scheduler_ticks;
  int log_rate;
};
struct Copter : Vehicle {
  int mode;
};
#pragma symcr skip(Copter::scheduler_ticks)

Copter copter;
