// Attitude control: angle errors -> body-rate targets (P) -> angular accelerations (PID) ->
// torques for the mixer.
#ifndef AUTOPILOT_AC_ATTITUDECONTROL_HPP
#define AUTOPILOT_AC_ATTITUDECONTROL_HPP

#include "AP_Math.hpp"

struct AC_PID {
  AC_PID(float p, float i, float d, float integrator_max) : kp(p), ki(i), kd(d), imax(integrator_max) {}
  float kp, ki, kd, imax;
  float integrator = 0;
  float last_error = 0;
  float update(float error, float dt);
  void reset() { integrator = 0; last_error = 0; }
};

class AC_AttitudeControl {
 public:
  // Angles in radians; yaw is an absolute heading.
  void input_euler_angle_roll_pitch_yaw(float roll, float pitch, float yaw);
  void set_throttle_out(float thrust_n) { _thrust_n = thrust_n; }
  // Runs the rate loop and hands thrust and torques to the motors.
  void rate_controller_run(float dt);
  void relax();  // on the ground: forget integrators, follow the current attitude
  float get_target_yaw() const { return _target_yaw; }

 private:
  float _target_roll = 0, _target_pitch = 0, _target_yaw = 0;
  float _thrust_n = 0;
  AC_PID _rate_roll{20.0f, 8.0f, 0.15f, 30.0f};
  AC_PID _rate_pitch{20.0f, 8.0f, 0.15f, 30.0f};
  AC_PID _rate_yaw{8.0f, 2.0f, 0.0f, 10.0f};
};

extern AC_AttitudeControl attitude_control;

#endif  // AUTOPILOT_AC_ATTITUDECONTROL_HPP
