#include "AC_PosControl.hpp"

#include "AP_Motors.hpp"
#include "Copter.hpp"

namespace {
constexpr float kPosP = 1.0f;
constexpr float kAccelMax = 3.0f;       // m/s^2 horizontal, for the sqrt controller
constexpr float kVelP = 2.0f;
constexpr float kVelI = 0.6f;
constexpr float kVelIMax = 3.0f;        // m/s^2 (wind and drag compensation)
constexpr float kLeanMax = 0.52f;       // 30 degrees
constexpr float kAltP = 1.0f;
constexpr float kVelZP = 3.0f;
constexpr float kAccelZI = 1.5f;
constexpr float kAccelZIMax = 4.0f;
}  // namespace

void AC_PosControl::init_at_current_position() {
  const Vector3f& pos = copter.ahrs.get_position_NED();
  _pos_target = pos;
  _alt_hold = true;
  _xy_velocity_mode = false;
  _vel_integrator = {0, 0};
}

void AC_PosControl::update(float dt, float yaw_target) {
  const AP_AHRS& ahrs = copter.ahrs;
  const Vector3f& pos = ahrs.get_position_NED();
  const Vector3f& vel = ahrs.get_velocity_NED();

  // Horizontal: the sqrt controller along the error direction, limited to the speed.
  const Vector2f error = (_pos_target - pos).xy();
  const float distance = error.length();
  Vector2f vel_target{0, 0};
  if (_xy_velocity_mode) {
    vel_target = _vel_target_xy;
    _pos_target.x = pos.x;  // so that a switch back to position mode holds here
    _pos_target.y = pos.y;
  } else if (distance > 1e-3f) {
    const float speed = constrain_value(sqrt_controller(distance, kPosP, kAccelMax, dt), 0.0f,
                                        _speed_xy);
    vel_target = error * (speed / distance);
  }
  const Vector2f vel_error = vel_target - vel.xy();
  _vel_integrator = _vel_integrator + vel_error * (kVelI * dt);
  const float i_len = _vel_integrator.length();
  if (i_len > kVelIMax) _vel_integrator = _vel_integrator * (kVelIMax / i_len);
  const Vector2f accel = vel_error * kVelP + _vel_integrator;

  // North/east acceleration -> lean angles in the vehicle's heading frame.
  const float cy = std::cos(ahrs.yaw), sy = std::sin(ahrs.yaw);
  const float accel_forward = accel.x * cy + accel.y * sy;
  const float accel_right = -accel.x * sy + accel.y * cy;
  const float pitch = constrain_value(-std::atan(accel_forward / GRAVITY_MSS), -kLeanMax, kLeanMax);
  const float roll = constrain_value(std::atan(accel_right / GRAVITY_MSS), -kLeanMax, kLeanMax);

  // Vertical (positive up).
  float climb_target = _climb_rate;
  if (_alt_hold) {
    climb_target = sqrt_controller(-(_pos_target.z - pos.z), kAltP, 2.5f, dt);
  }
  climb_target = constrain_value(climb_target, -_speed_down, _speed_up);
  const float climb_error = climb_target - (-vel.z);
  _accel_z_integrator =
      constrain_value(_accel_z_integrator + climb_error * kAccelZI * dt, -kAccelZIMax, kAccelZIMax);
  const float accel_up = climb_error * kVelZP + _accel_z_integrator;
  const float tilt = std::cos(ahrs.roll) * std::cos(ahrs.pitch);
  _thrust_n = motors.params.mass_kg * (GRAVITY_MSS + accel_up) / (tilt > 0.5f ? tilt : 0.5f);
  _thrust_n = constrain_value(_thrust_n, 0.0f, motors.thrust_max());

  attitude_control.input_euler_angle_roll_pitch_yaw(roll, pitch, yaw_target);
  attitude_control.set_throttle_out(_thrust_n);
}
