// A clean program for the --previous-schema diagnostics: the errors are the option's.
#include <symcr/symcr.hpp>

struct Vehicle {
  int mode;
  double altitude;
};
SYMCR_CHECKPOINT Vehicle vehicle;
