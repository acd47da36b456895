// SYMCR_RANGE on a member that is not a number (here an array): restore would ignore it.
#include <symcr/symcr.hpp>

#include <cstdint>

struct Gains {
  std::uint8_t k[4] SYMCR_RANGE(0, 9);
  std::uint8_t scale SYMCR_RANGE(1, 8);  // fine
};

SYMCR_CHECKPOINT Gains gains;
