// A time must be an integer count of its clock's unit; a clock's function must return one.
#include <cstdint>
#include <symcr/symcr.hpp>
std::uint32_t millis() { return 0; }
double seconds() { return 0; }
SYMCR_CLOCK(millis)
SYMCR_CLOCK(seconds)
struct Timers {
  float last_s SYMCR_TIME(millis);
};
SYMCR_CHECKPOINT Timers timers;
