// Integer bounds no double holds exactly: ranges hold doubles, so each would be another number.
#include <symcr/symcr.hpp>

#include <cstdint>

struct Odometer {
  std::int64_t total SYMCR_RANGE(0, 9007199254740993);
  std::uint64_t trips;
  std::int64_t fine SYMCR_RANGE(-9007199254740992, 1e300);  // both held exactly
};
SYMCR_CHECKPOINT Odometer odometer;
#pragma symcr range(Odometer::trips, 0, 0xFFFFFFFFFFFFFFFE)
