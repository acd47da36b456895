// Quad-X mixer: total thrust and body torques to four motor outputs (0..1), with ArduPilot's
// motor order (1 front-right CCW, 2 rear-left CCW, 3 front-left CW, 4 rear-right CW).
#ifndef AUTOPILOT_AP_MOTORS_HPP
#define AUTOPILOT_AP_MOTORS_HPP

#include "AP_Math.hpp"

struct FrameParams {  // the airframe as tuned by the operator (ArduPilot keeps these as params)
  float mass_kg = 1.5f;
  float motor_thrust_max_n = 7.5f;
  float arm_length_m = 0.25f;  // centre to motor
  float yaw_torque_per_n = 0.016f;
  Vector3f inertia{0.015f, 0.015f, 0.028f};
};

class AP_Motors {
 public:
  static constexpr int kMotorCount = 4;

  void set_armed(bool armed) { _armed = armed; }
  bool armed() const { return _armed; }
  void set_thrust(float newtons) { _thrust = newtons; }
  void set_torque(const Vector3f& newton_metres) { _torque = newton_metres; }
  // Mixes the demands into outputs, giving attitude priority over thrust near the limits.
  void output();
  const float* outputs() const { return _out; }
  float thrust_max() const { return params.motor_thrust_max_n * kMotorCount; }
  bool limit_thrust_high() const { return _limit_high; }

  FrameParams params;

 private:
  bool _armed = false;
  float _thrust = 0;
  Vector3f _torque{0, 0, 0};
  float _out[kMotorCount] = {};
  bool _limit_high = false;
};

extern AP_Motors motors;

#endif  // AUTOPILOT_AP_MOTORS_HPP
