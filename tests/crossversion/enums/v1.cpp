// v1: enumerators renumbered and reordered, one removed; the underlying type widened.
#include "check.hpp"

enum class Mode : int { Land = 10, Idle = 20, Rtl = 25, Auto = 30 };
enum Phase { CRUISE = 5, DESCENT = 6, TAKEOFF = 7 };

struct Flight {
  Mode mode;
  Phase phase;
  Mode vanished = Mode::Rtl;
};

SYMCR_CHECKPOINT Flight flight;

int main(int argc, char** argv) {
  flight = Flight{};
  flight.vanished = Mode::Rtl;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(flight.mode == Mode::Land);
  XV_CHECK(flight.phase == CRUISE);
  XV_CHECK(flight.vanished == Mode::Rtl);  // Acro is unknown here: rejected, kept
  XV_CHECK(xv::decided(report, "flight.vanished", symcr::Decision::Rejected));
  return xv::verdict();
}
