// A firmware whose Mode shares no enumerator with the enums pair's v0 (tests/crossversion/enums):
// the device profile could restore no value of v0's 'flight.mode', so --previous-schema with
// v0's schema file is refused when the firmware is built.
#include <symcr/symcr.hpp>

enum class Mode : unsigned char { Hover, Mission };
enum Phase { TAKEOFF, CRUISE, DESCENT };

struct Flight {
  Mode mode;
  Phase phase;
  Mode vanished;
};

SYMCR_CHECKPOINT Flight flight;
