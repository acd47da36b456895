// See flight.hpp. The loop is sitl_world's (World::autopilot_loop, GroundStation::update,
// World::step_world) with the autopilot called directly instead of over the sensor link.
#include "flight.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "AP_Motors.hpp"
#include "Copter.hpp"
#include "ground_station.hpp"
#include "messages.hpp"
#include "mission_file.hpp"
#include "physics.hpp"
#include "sensors.hpp"

namespace specimen_bench {
namespace {

constexpr std::uint64_t kLoopUs = 10000;  // autopilot loop: 100 Hz
constexpr int kPhysicsSubsteps = 4;       // physics: 400 Hz

// As the autopilot's main.cpp does with each SIM_SENSORS frame.
void apply_sensors(const mav::SimSensors& in) {
  SensorSample& s = hal.sample;
  s.gyro = {in.gyro[0], in.gyro[1], in.gyro[2]};
  s.accel = {in.accel[0], in.accel[1], in.accel[2]};
  s.mag_heading = in.mag_heading;
  s.baro_alt = in.baro_alt;
  s.gps_new = in.gps_new != 0;
  s.gps_fix = in.gps_fix;
  s.gps_loc =
      Location::make(in.gps_lat, in.gps_lng, static_cast<std::int32_t>(in.gps_alt * 100.0f));
  s.gps_vel = {in.gps_vel[0], in.gps_vel[1], in.gps_vel[2]};
  hal.now_us = in.time_us;
}

}  // namespace

FlightResult fly(const std::string& mission_file, int until_item, double limit_s) {
  FlightResult result;
  world::Mission mission;
  if (!world::load_mission(mission_file, mission, result.error)) return result;
  world::Home home;
  home.lat = static_cast<std::int32_t>(std::lround(mission.items[0].lat * 1e7));
  home.lng = static_cast<std::int32_t>(std::lround(mission.items[0].lng * 1e7));

  // The ground-control link, as sitl_world gives it to the autopilot (a stream socket pair);
  // both ends stay open for the life of the process (the copter keeps its end in `hal`).
  int gcs_pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, gcs_pair) != 0) {
    result.error = std::string("socketpair: ") + std::strerror(errno);
    return result;
  }
  hal.gcs = mav::Channel(gcs_pair[0]);
  static mav::Channel station_link;
  station_link = mav::Channel(gcs_pair[1]);

  world::WindModel wind;
  wind.mean = {1.5, -1.0, 0};  // a steady breeze with gusts: the controllers have work to do
  world::Physics physics(world::Airframe{}, wind, 1);
  world::Sensors sensors(home, 1 * 7919u + 1u);
  world::GroundStation station(mission);

  copter.setup();
  std::uint64_t time_us = 0;
  std::array<double, 4> command{};
  while (time_us * 1e-6 < limit_s) {
    apply_sensors(sensors.sample(physics.state(), time_us));
    copter.loop();
    const float* out = motors.outputs();
    for (int i = 0; i < 4; ++i) command[static_cast<std::size_t>(i)] = out[i];
    station.update(station_link, time_us * 1e-6);
    const double dt = kLoopUs * 1e-6 / kPhysicsSubsteps;
    for (int i = 0; i < kPhysicsSubsteps; ++i) {
      physics.step(command, dt);
      sensors.accumulate_imu(physics.state());
    }
    time_us += kLoopUs;
    if (physics.crashed()) {
      result.error = std::string("crashed: ") + physics.crash_reason();
      return result;
    }
    if (station.mission_started() && station.mission_current() >= until_item) break;
  }
  result.seconds = time_us * 1e-6;
  result.mission_items = copter.mission.num_commands();
  result.current_item = station.mission_current();
  if (!copter.armed() || copter.get_mode() != Mode::AUTO || result.current_item < until_item) {
    result.error = "the copter is not flying the mission (armed " +
                   std::to_string(copter.armed()) + ", mode " +
                   std::to_string(static_cast<int>(copter.get_mode())) + ", current item " +
                   std::to_string(result.current_item) + " after " +
                   std::to_string(result.seconds) + " s)";
    return result;
  }
  result.ok = true;
  return result;
}

}  // namespace specimen_bench
