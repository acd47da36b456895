// v1 of anonymous_members: a field added first, the two unnamed structs swapped and one of
// them grown, a new unnamed struct with members of its own.
#include <cstdint>

#include "check.hpp"

struct Status {
  std::uint8_t flags;  // new: moves every unnamed member's index
  std::uint8_t mode;
  union {
    std::uint32_t raw;
    float f;
  };
  struct {
    double lat, lon, alt;  // grown; was after {lo, hi}
  };
  struct {
    std::int16_t lo, hi;
  };
  struct {
    int fresh;  // new: shares no member name, keeps its own value
  };
  union {
    std::uint16_t word;
    std::uint8_t bytes[2];
  };
};

SYMCR_CHECKPOINT Status status;

int main(int argc, char** argv) {
  status.flags = 9;
  status.mode = 0;
  status.raw = 0;
  status.lo = status.hi = 0;
  status.lat = status.lon = 0;
  status.alt = 100;
  status.fresh = 5;
  status.word = 0;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(status.flags == 9);
  XV_CHECK(status.mode == 3);
  XV_CHECK(status.raw == 0xCAFEF00Du);
  XV_CHECK(status.lo == -1 && status.hi == 7);
  XV_CHECK(status.lat == 42.25 && status.lon == -83.5);
  XV_CHECK(status.alt == 100);
  XV_CHECK(status.fresh == 5);
  XV_CHECK(status.word == 0xBEEF);
  // Nothing was dropped: every unnamed member found its counterpart.
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.decision == symcr::Decision::Dropped) {
      std::fprintf(stderr, "dropped: %s\n", e.path.c_str());
      ++xv::failures();
    }
  }
  return xv::verdict();
}
