// v1 of flight_modes: a patch adds a mode and reorders the mode members. The current mode comes
// back as a pointer to v1's own mode object of the same name, whatever its new place; a
// pointer to a mode object that is not part of the state is refused when saving.
#include <cstdio>
#include <cstring>

#include "check.hpp"

struct Mode {
  virtual ~Mode() = default;
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct ModeRTL : Mode {
  int number() const override { return 6; }
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};
struct ModeStabilize : Mode {
  int number() const override { return 0; }
};

struct Copter {
  ModeRTL mode_rtl;  // new
  ModeLoiter mode_loiter;
  ModeAuto mode_auto;
  ModeStabilize mode_stabilize;
  Mode* flightmode = &mode_stabilize;
  Mode* previous = nullptr;
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(copter.flightmode == &copter.mode_auto);
  XV_CHECK(copter.flightmode != nullptr && copter.flightmode->number() == 3);
  XV_CHECK(copter.mode_auto.next_waypoint == 4 && copter.mode_auto.entered_ms == 1234);
  XV_CHECK(copter.previous == &copter.mode_loiter && copter.mode_loiter.radius_m == 7.5f);
  XV_CHECK(xv::restored(report, "copter.flightmode"));

  // A mode object outside the state has no known dynamic type there: saving refuses it.
  ModeAuto* loose = new ModeAuto();
  copter.flightmode = loose;
  std::vector<std::uint8_t> bytes;
  const symcr::Status saved = symcr::checkpoint_to_buffer(*symcr_program_schema(), bytes);
  XV_CHECK(saved.error() == symcr::Error::Unsupported);
  XV_CHECK(std::strstr(saved.message(), "polymorphic class Mode") != nullptr);
  delete loose;
  return xv::verdict();
}
