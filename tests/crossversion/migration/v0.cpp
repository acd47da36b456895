// v0: the state before v1 changed units, split a field, flattened a nested struct and replaced
// an enum; v1 declares symcr_migrate hooks that rebuild its values from these by name.
#include <cstdint>
#include <vector>

#include "check.hpp"

enum class Mode { Manual, Auto };

struct Position {
  double lat;
  double lon;
};

struct Flight {
  float alt_m;                // v1: int32_t alt_cm
  float speed_kmh;            // v1: double speed_ms
  std::int32_t packed_time;   // hours * 100 + minutes; v1: hours, minutes
  Position pos;               // v1: lat, lon directly in Flight
  Mode mode;                  // v1: bool autopilot
  int heading;                // unchanged
};

namespace logbook {
struct Sample {
  float temp_f;  // v1: double temp_c
  int id;
};
struct Log {
  std::vector<Sample> samples;
  Sample fixed[2];
  Sample* last;  // a heap object
};
}  // namespace logbook

struct Gains {  // the same in v1, where it has a hook that must not run
  double p;
  double i;
};

SYMCR_CHECKPOINT Flight flight;
SYMCR_CHECKPOINT logbook::Log book;
SYMCR_CHECKPOINT Gains gains;

int main(int argc, char** argv) {
  flight = Flight{123.45f, 90.0f, 1742, Position{48.125, 11.5}, Mode::Auto, 270};
  book.samples = {logbook::Sample{212.0f, 1}, logbook::Sample{32.0f, 2}};
  book.fixed[0] = logbook::Sample{50.0f, 3};
  book.fixed[1] = logbook::Sample{-40.0f, 4};
  book.last = new logbook::Sample{98.6f, 5};
  gains = Gains{0.25, 0.125};
  const int result = xv::save(argc, argv);
  delete book.last;
  return result;
}
