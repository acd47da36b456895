// Position control, cascaded: position error -> velocity target (sqrt controller) ->
// acceleration (PI) -> lean angles and thrust for the attitude controller.
#ifndef AUTOPILOT_AC_POSCONTROL_HPP
#define AUTOPILOT_AC_POSCONTROL_HPP

#include "AC_AttitudeControl.hpp"
#include "AP_Math.hpp"

class AC_PosControl {
 public:
  // Targets in metres north/east/down of the AHRS origin.
  void set_pos_target_xy(const Vector2f& ne) {
    _pos_target.x = ne.x;
    _pos_target.y = ne.y;
    _xy_velocity_mode = false;
  }
  // Horizontal velocity demand instead of a position (waypoint legs).
  void set_vel_target_xy(const Vector2f& ne) { _vel_target_xy = ne; _xy_velocity_mode = true; }
  void set_alt_target(float alt_m) { _pos_target.z = -alt_m; _alt_hold = true; }
  // Vertical speed demand instead of an altitude (positive up), e.g. while landing.
  void set_climb_rate(float up_ms) { _climb_rate = up_ms; _alt_hold = false; }
  void set_max_speed_xy(float ms) { _speed_xy = ms; }
  void set_max_speed_z(float up_ms, float down_ms) { _speed_up = up_ms; _speed_down = down_ms; }
  const Vector3f& get_pos_target() const { return _pos_target; }
  // Holds where the vehicle is now; forgets integrators.
  void init_at_current_position();
  void update(float dt, float yaw_target);
  float get_thrust_n() const { return _thrust_n; }

 private:
  Vector3f _pos_target{0, 0, 0};
  bool _alt_hold = true;
  bool _xy_velocity_mode = false;
  Vector2f _vel_target_xy{0, 0};
  float _climb_rate = 0;
  float _speed_xy = 5.0f, _speed_up = 2.5f, _speed_down = 1.5f;
  Vector2f _vel_integrator{0, 0};
  float _accel_z_integrator = 0;
  float _thrust_n = 0;
};

extern AC_PosControl pos_control;

#endif  // AUTOPILOT_AC_POSCONTROL_HPP
