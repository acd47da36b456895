// The hardware abstraction for software-in-the-loop: time comes from the world's sensor
// frames (lock-step; the world counts it from this process's start), sensors are the latest SIM_SENSORS frame, outputs go back as SIM_MOTORS.
#ifndef AUTOPILOT_AP_HAL_HPP
#define AUTOPILOT_AP_HAL_HPP

#include <cstdint>

#include "AP_Math.hpp"
#include "Location.hpp"
#include "channel.hpp"
#include "messages.hpp"

// One loop's worth of sensor readings, as the drivers deliver them.
struct SensorSample {
  Vector3f gyro;      // rad/s, body
  Vector3f accel;     // m/s^2 specific force, body
  float mag_heading;  // rad
  float baro_alt;     // m above the boot elevation
  bool gps_new;       // a fix arrived this loop
  std::uint8_t gps_fix;
  Location gps_loc;   // alt in cm above the boot elevation
  Vector3f gps_vel;   // m/s NED
};

class AP_HAL {
 public:
  // One SIM_SENSORS frame from the world: this loop's readings and time.
  void apply_sensors(const mav::SimSensors& in) {
    sample.gyro = {in.gyro[0], in.gyro[1], in.gyro[2]};
    sample.accel = {in.accel[0], in.accel[1], in.accel[2]};
    sample.mag_heading = in.mag_heading;
    sample.baro_alt = in.baro_alt;
    sample.gps_new = in.gps_new != 0;
    sample.gps_fix = in.gps_fix;
    sample.gps_loc =
        Location::make(in.gps_lat, in.gps_lng, static_cast<std::int32_t>(in.gps_alt * 100.0f));
    sample.gps_vel = {in.gps_vel[0], in.gps_vel[1], in.gps_vel[2]};
    now_us = in.time_us;
  }

  // This loop's motor outputs to the world (4 of them, 0..1). False when the world is gone.
  bool send_motors(const float* outputs) {
    mav::SimMotors out{};
    for (int i = 0; i < 4; ++i) out.motor[i] = outputs[i];
    return sim.send(mav::make_frame(mav::SIM_MOTORS, out));
  }

  std::uint64_t micros64() const { return now_us; }
  std::uint32_t millis() const { return static_cast<std::uint32_t>(now_us / 1000); }

  mav::Channel sim;  // sensors in, motor outputs out
  mav::Channel gcs;  // the ground-control link
  SensorSample sample{};
  std::uint64_t now_us = 0;
};

extern AP_HAL hal;

// The clock as the autopilot's code reads it (ArduPilot's AP_HAL::millis()). It counts from
// this process's first sensor frame, as a flight controller's counts from its boot: a restart
// starts it again at zero. clocks.symcr names it, so that a restore moves the restored times.
inline std::uint32_t hal_millis() { return hal.millis(); }

#endif  // AUTOPILOT_AP_HAL_HPP
