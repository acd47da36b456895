// A member marked a time of two clocks: by its typedef and by its own annotation.
#include <cstdint>
#include <symcr/symcr.hpp>
std::uint32_t millis() { return 0; }
std::uint64_t micros() { return 0; }
SYMCR_CLOCK(millis)
SYMCR_CLOCK(micros)
typedef std::uint32_t time_ms SYMCR_TIME(millis);
struct Timers {
  time_ms last SYMCR_TIME(micros);
};
SYMCR_CHECKPOINT Timers timers;
