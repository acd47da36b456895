#include "AP_Motors.hpp"

namespace {
// Per motor: roll factor (-y), pitch factor (+x), yaw factor (+1 CCW), for unit arm offsets.
constexpr float kRoll[4] = {-0.7071f, 0.7071f, 0.7071f, -0.7071f};
constexpr float kPitch[4] = {0.7071f, -0.7071f, 0.7071f, -0.7071f};
constexpr float kYaw[4] = {1.0f, 1.0f, -1.0f, -1.0f};
}  // namespace

void AP_Motors::output() {
  if (!_armed) {
    for (float& out : _out) out = 0.0f;
    _limit_high = false;
    return;
  }
  const float max_n = params.motor_thrust_max_n;
  const float idle_n = 0.05f * max_n;  // spin-when-armed
  float per_motor[kMotorCount];
  float roll_pitch_yaw[kMotorCount];
  float low = 1e9f, high = -1e9f;
  for (int i = 0; i < kMotorCount; ++i) {
    // Torque = sum(factor * arm * thrust_i), four motors share it.
    roll_pitch_yaw[i] = kRoll[i] * _torque.x / (4 * 0.7071f * 0.7071f * params.arm_length_m) +
                        kPitch[i] * _torque.y / (4 * 0.7071f * 0.7071f * params.arm_length_m) +
                        kYaw[i] * _torque.z / (4 * params.yaw_torque_per_n);
    low = roll_pitch_yaw[i] < low ? roll_pitch_yaw[i] : low;
    high = roll_pitch_yaw[i] > high ? roll_pitch_yaw[i] : high;
  }
  // Attitude first: shift the collective so that every motor stays within its range.
  float collective = _thrust / kMotorCount;
  _limit_high = false;
  if (collective + high > max_n) {
    collective = max_n - high;
    _limit_high = true;
  }
  if (collective + low < idle_n) collective = idle_n - low;
  for (int i = 0; i < kMotorCount; ++i) {
    per_motor[i] = constrain_value(collective + roll_pitch_yaw[i], idle_n, max_n);
    _out[i] = per_motor[i] / max_n;
  }
}
