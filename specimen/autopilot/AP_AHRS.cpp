#include "AP_AHRS.hpp"

namespace {
constexpr std::uint16_t kAlignSamples = 50;  // 0.5 s at 100 Hz
constexpr float kRollPitchP = 1.0f;          // rad/s per unit gravity-vector error
constexpr float kGyroBiasI = 0.02f;
constexpr float kYawP = 0.6f;
constexpr float kGpsPosGain = 0.25f;         // per fix (10 Hz)
constexpr float kGpsVelGain = 0.35f;
constexpr float kGpsPosToVelGain = 0.08f;
constexpr float kBaroGain = 0.02f;           // per loop
constexpr float kAccelFilter = 0.3f;         // low-pass of the GPS-derived acceleration
}  // namespace

void AP_AHRS::update(const SensorSample& sample, float dt) {
  _last_sample = sample;
  if (_status == Status::NOT_INITIALISED) {
    align(sample);
    return;
  }
  update_attitude(sample, dt);
  update_position(sample, dt);
}

void AP_AHRS::align(const SensorSample& sample) {
  _align_accel_sum += sample.accel;
  _align_heading_sum.x += std::cos(sample.mag_heading);
  _align_heading_sum.y += std::sin(sample.mag_heading);
  if (++_align_count < kAlignSamples) return;
  const Vector3f a = _align_accel_sum * (1.0f / _align_count);
  const float r = std::atan2(-a.y, -a.z);
  const float p = std::atan2(a.x, std::sqrt(a.y * a.y + a.z * a.z));
  _q = Quaternion::from_euler(r, p, std::atan2(_align_heading_sum.y, _align_heading_sum.x));
  _q.to_euler(roll, pitch, yaw);
  _status = Status::ALIGNED;
}

void AP_AHRS::update_attitude(const SensorSample& sample, float dt) {
  // Gravity check: what the accelerometer should read given our attitude and acceleration.
  const Vector3f expected_ef = _accel_ef - Vector3f{0, 0, GRAVITY_MSS};
  Vector3f expected_bf = _q.earth_to_body(expected_ef);
  Vector3f measured = sample.accel;
  const float measured_len = measured.length(), expected_len = expected_bf.length();
  Vector3f error{0, 0, 0};
  if (measured_len > 1.0f && expected_len > 1.0f) {
    measured = measured * (1.0f / measured_len);
    expected_bf = expected_bf * (1.0f / expected_len);
    error = measured % expected_bf;
  }
  const float yaw_error = wrap_PI(sample.mag_heading - yaw);
  const Vector3f yaw_correction = _q.earth_to_body(Vector3f{0, 0, kYawP * yaw_error});

  _omega_I += error * (kGyroBiasI * dt);
  _omega = sample.gyro + _omega_I;
  _q.rotate((_omega + error * kRollPitchP + yaw_correction) * dt);
  _q.to_euler(roll, pitch, yaw);
  _error_rp = 0.98f * _error_rp + 0.02f * error.length();
  _error_yaw = 0.98f * _error_yaw + 0.02f * std::fabs(yaw_error);
}

void AP_AHRS::update_position(const SensorSample& sample, float dt) {
  if (sample.gps_new && sample.gps_fix >= 3) {
    if (_status == Status::ALIGNED) {
      _origin = sample.gps_loc;
      _origin.alt = 0;
      _baro_offset = sample.baro_alt;
      _position_ned = {0, 0, -sample.gps_loc.alt * 0.01f};
      _velocity_ned = sample.gps_vel;
      _last_gps_vel = sample.gps_vel;
      _status = Status::HEALTHY;
    }
    const Vector3f gps_pos = location_to_NED(sample.gps_loc);
    const Vector2f pos_error = (gps_pos - _position_ned).xy();
    const Vector3f vel_error = sample.gps_vel - _velocity_ned;
    _position_ned.x += pos_error.x * kGpsPosGain;
    _position_ned.y += pos_error.y * kGpsPosGain;
    _velocity_ned.x += vel_error.x * kGpsVelGain + pos_error.x * kGpsPosToVelGain;
    _velocity_ned.y += vel_error.y * kGpsVelGain + pos_error.y * kGpsPosToVelGain;
    _velocity_ned.z += vel_error.z * kGpsVelGain;
    const std::uint32_t now_ms = hal.millis();
    if (_last_gps_ms != 0 && now_ms > _last_gps_ms) {
      const float gps_dt = (now_ms - _last_gps_ms) * 0.001f;
      const Vector3f accel = (sample.gps_vel - _last_gps_vel) * (1.0f / gps_dt);
      _accel_ef = _accel_ef * (1.0f - kAccelFilter) + accel * kAccelFilter;
    }
    _last_gps_vel = sample.gps_vel;
    _last_gps_ms = now_ms;
    ++_gps_fix_count;
  }
  if (_status != Status::HEALTHY) return;

  // Predict with the accelerometer, correct height with the barometer.
  const Vector3f accel_ned = _q.body_to_earth(sample.accel) + Vector3f{0, 0, GRAVITY_MSS};
  _velocity_ned += accel_ned * dt;
  _position_ned += _velocity_ned * dt;
  const float baro_down = -(sample.baro_alt - _baro_offset);
  const float baro_error = baro_down - _position_ned.z;
  _position_ned.z += baro_error * kBaroGain;
  _velocity_ned.z += baro_error * kBaroGain * 0.5f;
}

bool AP_AHRS::get_location(Location& out) const {
  if (_status != Status::HEALTHY) return false;
  out = _origin;
  out.offset(_position_ned.x, _position_ned.y);
  out.alt = static_cast<std::int32_t>(std::lround(-_position_ned.z * 100.0f));
  return true;
}

Vector3f AP_AHRS::location_to_NED(const Location& loc) const {
  const Vector2f ne = _origin.get_distance_NE(loc);
  return {ne.x, ne.y, -loc.alt * 0.01f};
}
