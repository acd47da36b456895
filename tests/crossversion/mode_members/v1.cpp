// v1: the patch renamed the loiter member, added a mode, reordered the members, dropped the
// landing mode and moved the mode classes' fields; the never-owner declaration is now a
// pragma. The pointers come back to the new build's members by name (the renamed one through
// its old name), the one whose member is gone is reported and keeps this build's value, and
// the unselected members keep this build's values.
#include <cstring>

#include "check.hpp"

struct Mode {
  virtual ~Mode() {}
  virtual int number() const = 0;
  long long entered_us = 0;
  unsigned entered_ms = 0;
};
struct ModeGuided : Mode {
  int number() const override { return 4; }
  double target[3] = {0, 0, 0};
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  int laps = 0;
  float radius_m = 3;
};
struct ModeRTL : Mode {
  int number() const override { return 6; }
  double home_alt = 0;
  int stage = 1;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};

struct Vehicle {
  ModeGuided mode_guided;
  ModeRTL rtl_modes[3];
  ModeLoiter loiter SYMCR_RENAMED_FROM("mode_loiter");
  int ticks = 0;
  ModeAuto mode_auto SYMCR_INCLUDE;
  Mode* last_failsafe SYMCR_INCLUDE = &mode_guided;
  Mode* previous SYMCR_INCLUDE = nullptr;
  Mode* flightmode SYMCR_INCLUDE = &mode_auto;
};
#pragma symcr not_owner(Vehicle::flightmode, Vehicle::previous, Vehicle::last_failsafe)

SYMCR_CHECKPOINT_SHALLOW Vehicle vehicle;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(vehicle.ticks == 42);
  XV_CHECK(vehicle.mode_auto.next_waypoint == 4);
  // References by path, into members whose values were not saved.
  XV_CHECK(vehicle.flightmode == &vehicle.loiter);
  XV_CHECK(vehicle.flightmode->number() == 5);
  XV_CHECK(vehicle.previous == &vehicle.rtl_modes[1]);
  XV_CHECK(xv::restored(report, "vehicle.flightmode"));
  XV_CHECK(xv::restored(report, "vehicle.previous"));
  // Their values are this build's: only what the root selects was saved.
  XV_CHECK(vehicle.loiter.radius_m == 3.0f);
  XV_CHECK(vehicle.rtl_modes[1].stage == 1);
  // The landing mode is gone: the pointer is rejected and keeps this build's value.
  XV_CHECK(vehicle.last_failsafe == &vehicle.mode_guided);
  XV_CHECK(xv::decided(report, "vehicle.last_failsafe", symcr::Decision::Rejected));
  bool named = false;
  for (const symcr::ReportEntry& e : report.entries()) {
    named |= e.path == "vehicle.last_failsafe" && e.decision == symcr::Decision::Rejected &&
             e.detail.find("target member mode_land of Vehicle not in this build") !=
                 std::string::npos;
  }
  XV_CHECK(named);
  return xv::verdict();
}
