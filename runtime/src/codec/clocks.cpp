// The process epoch of clock readings (docs/resolution.md, "Clocks").
#include "clocks.hpp"

#include <sys/random.h>
#include <time.h>
#include <unistd.h>

namespace symcr::detail {

std::uint64_t process_epoch() {
  static const std::uint64_t kEpoch = [] {
    std::uint64_t value = 0;
    if (getrandom(&value, sizeof value, 0) != static_cast<ssize_t>(sizeof value)) {
      // No entropy source: the start time and the pid still tell processes apart.
      timespec now{};
      clock_gettime(CLOCK_REALTIME, &now);
      value = (static_cast<std::uint64_t>(now.tv_sec) * 1000000000u +
               static_cast<std::uint64_t>(now.tv_nsec)) ^
              (static_cast<std::uint64_t>(getpid()) << 40);
    }
    return value != 0 ? value : 1;
  }();
  return kEpoch;
}

}  // namespace symcr::detail
