// The autopilot process. The world (physics, sensors, ground station) starts it with the two
// ends of its links as file descriptors and drives it in lock-step: one SIM_SENSORS frame in,
// one loop, one SIM_MOTORS frame out.
//
//   copter --sim-fd 3 --gcs-fd 4 [--checkpoint none|raw-image|symcr|symcr-points --checkpoint-path FILE
//          --checkpoint-every LOOPS] [--restore]
//          [--fallback-depth N --confirm-after LOOPS]   (symcr: the crash-loop fallback)
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "AP_Checkpoint.hpp"
#include "AP_Motors.hpp"
#include "Copter.hpp"
#include "messages.hpp"

namespace {
constexpr int kSensorTimeoutMs = 30000;

void usage() {
  std::fprintf(stderr,
               "usage: copter --sim-fd N --gcs-fd N [--checkpoint none|raw-image|symcr|symcr-points]\n"
               "              [--checkpoint-path FILE] [--checkpoint-every LOOPS] [--restore]\n"
               "              [--fallback-depth N] [--confirm-after LOOPS]\n");
}

}  // namespace

int main(int argc, char** argv) {
  int sim_fd = -1, gcs_fd = -1;
  AP_Checkpoint::Method method = AP_Checkpoint::Method::None;
  const char* checkpoint_path = "copter.ckpt";
  std::uint32_t checkpoint_every = 10;
  std::uint32_t fallback_depth = 0;
  std::uint32_t confirm_after = 200;  // loops: 2 s at 100 Hz
  bool restore = false;
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    if (std::strcmp(arg, "--restore") == 0) {
      restore = true;
    } else if (value == nullptr) {
      usage();
      return 2;
    } else if (std::strcmp(arg, "--sim-fd") == 0) {
      sim_fd = std::atoi(value), ++i;
    } else if (std::strcmp(arg, "--gcs-fd") == 0) {
      gcs_fd = std::atoi(value), ++i;
    } else if (std::strcmp(arg, "--checkpoint") == 0) {
      if (!AP_Checkpoint::parse_method(value, method)) {
        usage();
        return 2;
      }
      ++i;
    } else if (std::strcmp(arg, "--checkpoint-path") == 0) {
      checkpoint_path = value, ++i;
    } else if (std::strcmp(arg, "--checkpoint-every") == 0) {
      checkpoint_every = static_cast<std::uint32_t>(std::atoi(value)), ++i;
    } else if (std::strcmp(arg, "--fallback-depth") == 0) {
      fallback_depth = static_cast<std::uint32_t>(std::atoi(value)), ++i;
    } else if (std::strcmp(arg, "--confirm-after") == 0) {
      confirm_after = static_cast<std::uint32_t>(std::atoi(value)), ++i;
    } else {
      usage();
      return 2;
    }
  }
  if (sim_fd < 0 || gcs_fd < 0) {
    usage();
    return 2;
  }
  hal.sim = mav::Channel(sim_fd);
  hal.gcs = mav::Channel(gcs_fd);

  copter.setup();
  checkpointing.set_crash_loop_fallback(fallback_depth, confirm_after);
  if (!checkpointing.init(method, checkpoint_path, checkpoint_every)) return 3;

  // The first sensor frame gives the time; restore after it so that the restored state and
  // the clock agree from the first loop on.
  mav::Frame frame;
  bool restored_pending = restore;
  while (hal.sim.receive(frame, kSensorTimeoutMs)) {
    if (frame.msgid != mav::SIM_SENSORS) continue;
    hal.apply_sensors(mav::read_payload<mav::SimSensors>(frame));
    if (restored_pending) {
      restored_pending = false;
      if (!checkpointing.restore()) return 4;
      copter.resume_after_restore();
    }
    copter.loop();
    if (!hal.send_motors(motors.outputs())) break;
  }
  return 0;
}
