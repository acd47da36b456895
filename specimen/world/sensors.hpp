// Sensor models: IMU (gyro bias + noise, accelerometer noise), compass, barometer and a
// 10 Hz GPS with slowly wandering position error. Seeded: a run is reproducible.
#ifndef WORLD_SENSORS_HPP
#define WORLD_SENSORS_HPP

#include <cstdint>
#include <random>

#include "messages.hpp"
#include "physics.hpp"

namespace world {

struct Home {
  std::int32_t lat = 0;
  std::int32_t lng = 0;
};

class Sensors {
 public:
  Sensors(const Home& home, unsigned seed);
  // Accumulates the IMU over the physics steps of one autopilot loop.
  void accumulate_imu(const BodyState& state);
  // The frame for the loop that starts at `time_us`.
  mav::SimSensors sample(const BodyState& state, std::uint64_t time_us);

 private:
  double noise(double sigma) { return sigma * normal_(rng_); }

  Home home_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Vec3 gyro_bias_;
  Vec3 gyro_sum_, accel_sum_;
  int imu_samples_ = 0;
  Vec3 gps_error_;
  double baro_drift_ = 0;
  std::uint64_t next_gps_us_ = 0;
};

}  // namespace world

#endif  // WORLD_SENSORS_HPP
