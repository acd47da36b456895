// 65,536 one-byte structs (grouped by 256 in 256 more): more types than the compact tables'
// 16-bit index holds.
#include <symcr/symcr.hpp>

#include "repeat.hpp"

template <int N>
struct Part {
  char value;
};
#define PART(n) Part<0x##n> part##n;
#define GROUP(n)                    \
  struct Group##n {                 \
    SYMCR_REPEAT_INNER_256(PART, n) \
  };
SYMCR_REPEAT_256(GROUP, )
#define MEMBER(n) Group##n group##n;
struct Parts {
  SYMCR_REPEAT_256(MEMBER, )
};
SYMCR_CHECKPOINT Parts parts;
