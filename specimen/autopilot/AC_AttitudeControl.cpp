#include "AC_AttitudeControl.hpp"

#include "AP_Motors.hpp"
#include "Copter.hpp"

namespace {
constexpr float kAngleP = 6.0f;         // rad/s per rad
constexpr float kMaxRollPitchRate = 3.0f;
constexpr float kMaxYawRate = 1.5f;
}  // namespace

float AC_PID::update(float error, float dt) {
  integrator = constrain_value(integrator + error * ki * dt, -imax, imax);
  const float derivative = dt > 0 ? (error - last_error) / dt : 0.0f;
  last_error = error;
  return kp * error + integrator + kd * derivative;
}

void AC_AttitudeControl::input_euler_angle_roll_pitch_yaw(float roll, float pitch, float yaw) {
  _target_roll = roll;
  _target_pitch = pitch;
  _target_yaw = wrap_PI(yaw);
}

void AC_AttitudeControl::relax() {
  _rate_roll.reset();
  _rate_pitch.reset();
  _rate_yaw.reset();
  _target_roll = copter.ahrs.roll;
  _target_pitch = copter.ahrs.pitch;
  _target_yaw = copter.ahrs.yaw;
}

void AC_AttitudeControl::rate_controller_run(float dt) {
  const AP_AHRS& ahrs = copter.ahrs;
  // Euler-angle errors mapped to body rates (small-angle approximation, fine below 45 deg).
  const float roll_rate = constrain_value(kAngleP * (_target_roll - ahrs.roll),
                                          -kMaxRollPitchRate, kMaxRollPitchRate);
  const float pitch_rate = constrain_value(kAngleP * (_target_pitch - ahrs.pitch),
                                           -kMaxRollPitchRate, kMaxRollPitchRate);
  const float yaw_rate = constrain_value(kAngleP * 0.5f * wrap_PI(_target_yaw - ahrs.yaw),
                                         -kMaxYawRate, kMaxYawRate);
  const Vector3f& gyro = ahrs.get_gyro();
  const Vector3f& inertia = motors.params.inertia;
  const Vector3f torque{inertia.x * _rate_roll.update(roll_rate - gyro.x, dt),
                        inertia.y * _rate_pitch.update(pitch_rate - gyro.y, dt),
                        inertia.z * _rate_yaw.update(yaw_rate - gyro.z, dt)};
  motors.set_torque(torque);
  motors.set_thrust(_thrust_n);
}
