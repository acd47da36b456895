// The hardware abstraction for software-in-the-loop: time comes from the world's sensor
// frames (lock-step), sensors are the latest SIM_SENSORS frame, outputs go back as SIM_MOTORS.
#ifndef AUTOPILOT_AP_HAL_HPP
#define AUTOPILOT_AP_HAL_HPP

#include <cstdint>

#include "AP_Math.hpp"
#include "Location.hpp"
#include "channel.hpp"

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
  std::uint64_t micros64() const { return now_us; }
  std::uint32_t millis() const { return static_cast<std::uint32_t>(now_us / 1000); }

  mav::Channel sim;  // sensors in, motor outputs out
  mav::Channel gcs;  // the ground-control link
  SensorSample sample{};
  std::uint64_t now_us = 0;
};

extern AP_HAL hal;

#endif  // AUTOPILOT_AP_HAL_HPP
