// The specimen's autopilot as a flight controller's firmware: after a reset it restores the
// vehicle from its newest checkpoint if there is one (else it starts its mission), then flies,
// checkpointing every 50 loops. Built twice, with and without symcr (the difference is what
// symcr adds to the firmware: benchmarks/run --code-size-only).
#include <cstdio>

#include "AP_Checkpoint.hpp"
#include "Copter.hpp"
#include "vehicle_sim.hpp"

int main() {
  copter.setup();
  const AP_Checkpoint::Method method =
      AP_Checkpoint::symcr_available() ? AP_Checkpoint::Method::Symcr : AP_Checkpoint::Method::None;
  if (!checkpointing.init(method, nullptr, 50)) return 1;
  if (checkpointing.restore()) {
    copter.resume_after_restore();
  } else if (!firmware::start_mission()) {
    return 1;
  }
  firmware::fly(1000);
  std::printf("flight: mode %u, %s\n", static_cast<unsigned>(copter.get_mode()),
              copter.armed() ? "armed" : "disarmed");
  return 0;
}
