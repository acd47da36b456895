// 256 types with a symcr_validate: more than the compact tables' 8-bit validator index holds.
#include <symcr/symcr.hpp>

#include "repeat.hpp"

#define VALIDATED(n) \
  struct Part##n {   \
    int value;       \
  };                 \
  inline bool symcr_validate(const Part##n& part) { return part.value >= 0; }
SYMCR_REPEAT_256(VALIDATED, _)
#define MEMBER(n) Part##n part##n;
struct Parts {
  SYMCR_REPEAT_256(MEMBER, _)
};
SYMCR_CHECKPOINT Parts parts;
