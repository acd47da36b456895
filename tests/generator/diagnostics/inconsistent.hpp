#include <symcr/symcr.hpp>

struct Shared {
  int value;
  int scratch;
};
