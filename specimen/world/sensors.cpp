#include "sensors.hpp"

#include <cmath>

#include "geo.hpp"

namespace world {

namespace {
constexpr double kGravity = 9.80665;
constexpr std::uint64_t kGpsPeriodUs = 100000;
}

Sensors::Sensors(const Home& home, unsigned seed) : home_(home), rng_(seed) {
  gyro_bias_ = {noise(0.01), noise(0.01), noise(0.01)};
}

void Sensors::accumulate_imu(const BodyState& state) {
  gyro_sum_ = gyro_sum_ + state.rates;
  // Specific force: what the accelerometer feels (gravity's reaction, not gravity).
  accel_sum_ = accel_sum_ + state.attitude.inverse_rotate(state.acceleration - Vec3{0, 0, kGravity});
  ++imu_samples_;
}

mav::SimSensors Sensors::sample(const BodyState& state, std::uint64_t time_us) {
  mav::SimSensors out{};
  out.time_us = time_us;
  Vec3 gyro = state.rates, accel = state.attitude.inverse_rotate(Vec3{0, 0, -kGravity});
  if (imu_samples_ > 0) {
    gyro = gyro_sum_ * (1.0 / imu_samples_);
    accel = accel_sum_ * (1.0 / imu_samples_);
  }
  gyro_sum_ = accel_sum_ = Vec3{};
  imu_samples_ = 0;
  out.gyro[0] = static_cast<float>(gyro.x + gyro_bias_.x + noise(0.005));
  out.gyro[1] = static_cast<float>(gyro.y + gyro_bias_.y + noise(0.005));
  out.gyro[2] = static_cast<float>(gyro.z + gyro_bias_.z + noise(0.005));
  out.accel[0] = static_cast<float>(accel.x + noise(0.05));
  out.accel[1] = static_cast<float>(accel.y + noise(0.05));
  out.accel[2] = static_cast<float>(accel.z + noise(0.05));

  double roll, pitch, yaw;
  state.attitude.euler(roll, pitch, yaw);
  out.mag_heading = static_cast<float>(std::remainder(yaw + noise(0.02), 2 * M_PI));
  baro_drift_ += noise(0.001);
  out.baro_alt = static_cast<float>(-state.position.z + baro_drift_ + noise(0.08));

  if (time_us >= next_gps_us_) {
    next_gps_us_ = time_us + kGpsPeriodUs;
    // A slowly wandering error, as a real receiver's multipath and ionosphere give.
    gps_error_ = gps_error_ * 0.98 + Vec3{noise(0.05), noise(0.05), noise(0.08)};
    const Vec3 p = state.position + gps_error_;
    geo::add_ne(home_.lat, home_.lng, p.x, p.y, out.gps_lat, out.gps_lng);
    out.gps_alt = static_cast<float>(-p.z);
    out.gps_vel[0] = static_cast<float>(state.velocity.x + noise(0.05));
    out.gps_vel[1] = static_cast<float>(state.velocity.y + noise(0.05));
    out.gps_vel[2] = static_cast<float>(state.velocity.z + noise(0.08));
    out.gps_new = 1;
    out.gps_fix = 3;
  }
  return out;
}

}  // namespace world
