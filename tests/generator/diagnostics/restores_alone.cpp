// SYMCR_RESTORES_ALONE on a member that is not a boolean or enum state flag.
#include <symcr/symcr.hpp>
struct Ahrs {
  bool started = false;
  int cores SYMCR_RESTORES_ALONE = 0;
};
SYMCR_CHECKPOINT Ahrs ahrs;
