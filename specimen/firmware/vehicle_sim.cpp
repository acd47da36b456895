#include "vehicle_sim.hpp"

#include "AP_HAL.hpp"
#include "Copter.hpp"
#include "messages.hpp"

namespace firmware {
namespace {

constexpr std::int32_t kFieldLat = -353632610;  // 1e-7 deg
constexpr std::int32_t kFieldLng = 1491652300;
constexpr std::uint64_t kLoopMicros = 10000;

void sense() {
  SensorSample& s = hal.sample;
  s.gyro = {0.0f, 0.0f, 0.0f};
  s.accel = {0.0f, 0.0f, -9.80665f};
  s.mag_heading = 0.5f;
  s.baro_alt = 0.0f;
  s.gps_new = (hal.now_us / kLoopMicros) % 20 == 0;  // 5 Hz
  s.gps_fix = 3;
  s.gps_loc = Location::make(kFieldLat, kFieldLng, 0);
  s.gps_vel = {0.0f, 0.0f, 0.0f};
}

AP_Mission::Mission_Command command(std::uint16_t id, std::int32_t north, std::int32_t east,
                                    std::int32_t alt_cm) {
  AP_Mission::Mission_Command cmd{};
  cmd.id = id;
  cmd.content.location = Location::make(kFieldLat + north, kFieldLng + east, alt_cm);
  return cmd;
}

}  // namespace

bool start_mission() {
  fly(300);  // the estimator aligns and takes its GPS origin
  if (!copter.mission.clear()) return false;
  copter.mission.add_cmd(command(mav::CMD_NAV_TAKEOFF, 0, 0, 1000));
  copter.mission.add_cmd(command(mav::CMD_NAV_WAYPOINT, 2000, 0, 1500));
  copter.mission.add_cmd(command(mav::CMD_NAV_WAYPOINT, 2000, 3000, 1500));
  copter.mission.add_cmd(command(mav::CMD_NAV_LAND, 0, 0, 0));
  return copter.set_mode(Mode::AUTO, ModeReason::GCS_COMMAND) && copter.arm();
}

void fly(unsigned loops) {
  for (unsigned i = 0; i < loops; ++i) {
    hal.now_us += kLoopMicros;
    sense();
    copter.loop();
  }
}

}  // namespace firmware
