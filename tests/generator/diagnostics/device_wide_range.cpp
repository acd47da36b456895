// A 64-bit integer's range bound beyond 2^53 under the device profile: the device compares
// ranges as doubles, which would let 2^53 + 1 pass a bound of 2^53.
#include <symcr/symcr.hpp>

#include <cstdint>

struct Odometer {
  std::uint64_t total SYMCR_RANGE(0, 9007199254740992.0);  // refused
  std::int64_t debt SYMCR_RANGE(-9007199254740991.0, 0);   // fine
  std::int32_t trip SYMCR_RANGE(-1e300, 1e300);            // fine: every int32 is exact
};

SYMCR_CHECKPOINT Odometer odometer;
