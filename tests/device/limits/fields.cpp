// 256 structs of 256 fields each: more fields than the compact tables' 16-bit index reaches.
#include <symcr/symcr.hpp>

#include "repeat.hpp"

#define FIELD(n) int n;
template <int N>
struct Part {
  SYMCR_REPEAT_256(FIELD, f)
};
#define PART(n) Part<0x##n> part##n;
struct Parts {
  SYMCR_REPEAT_256(PART, )
};
SYMCR_CHECKPOINT Parts parts;
