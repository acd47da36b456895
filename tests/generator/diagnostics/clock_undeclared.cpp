// A time of a clock no directive declares.
#include <cstdint>
struct Timers {
  std::uint32_t last_ms;
};
Timers timers;
#pragma symcr checkpoint(timers)
#pragma symcr time(Timers::last_ms, millis)
