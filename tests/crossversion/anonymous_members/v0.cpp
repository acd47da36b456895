// v0: unnamed structs and unions inside a struct. v1 adds a field in front of them, so every
// unnamed member's declaration index moves; their members must still be restored by name.
#include <cstdint>

#include "check.hpp"

struct Status {
  std::uint8_t mode;
  union {
    std::uint32_t raw;
    float f;
  };
  struct {
    std::int16_t lo, hi;
  };
  struct {
    double lat, lon;
  };
  union {
    std::uint16_t word;
    std::uint8_t bytes[2];
  };
};

SYMCR_CHECKPOINT Status status;

int main(int argc, char** argv) {
  status.mode = 3;
  status.raw = 0xCAFEF00Du;
  status.lo = -1;
  status.hi = 7;
  status.lat = 42.25;
  status.lon = -83.5;
  status.word = 0xBEEF;
  return xv::save(argc, argv);
}
