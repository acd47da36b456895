// v1 of left_to_new_build: the patch changed the constants and the callbacks. The restore keeps
// every one of them as this build made it, and restores the rest.
#include <cstdint>
#include <cstring>

#include "check.hpp"

int ticks_v1 = 0;
void arm_handler_v1() {}

struct Copter {
  Copter() : ticks(ticks_v1) {}
  const std::uint8_t num_flight_modes = 8;
  const int limits[2] = {3, 4};
  int mode = 0;
  int& ticks;
  void (*on_arm)() = &arm_handler_v1;
  void (Copter::*on_update)() = &Copter::update;
  const std::uint16_t startup_delay_ms = 2500;  // was a plain member in v0
  void update() {}
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(copter.mode == 5);
  XV_CHECK(copter.num_flight_modes == 8);
  XV_CHECK(copter.limits[0] == 3 && copter.limits[1] == 4);
  XV_CHECK(&copter.ticks == &ticks_v1);
  XV_CHECK(copter.on_arm == &arm_handler_v1);
  XV_CHECK(copter.on_update == &Copter::update);
  XV_CHECK(copter.startup_delay_ms == 2500);
  // The member that became const keeps this build's value and the report says so, as a
  // decision of this build rather than a loss (strict mode accepts it).
  XV_CHECK(xv::decided(report, "copter.startup_delay_ms", symcr::Decision::Kept));
  const symcr::ReportEntry* constant = xv::entry(report, "copter.startup_delay_ms");
  XV_CHECK(constant != nullptr && !constant->lossy);
  for (const symcr::ReportEntry& e : report.entries()) XV_CHECK(!e.lossy);
  for (const symcr::ReportEntry& e : report.entries()) {
    const bool left = e.path == "copter.num_flight_modes" || e.path == "copter.limits" ||
                      e.path == "copter.ticks" || e.path == "copter.on_arm" ||
                      e.path == "copter.on_update";
    if (left) {
      std::fprintf(stderr, "'%s' is in the schema: %s\n", e.path.c_str(), e.detail.c_str());
      ++xv::failures();
    }
  }
  return xv::verdict();
}
