// A root must have static storage: a local variable is an error.
#include <symcr/symcr.hpp>

int tick() {
  SYMCR_CHECKPOINT int counter = 0;
  return ++counter;
}
