// Waypoint navigation: drives the position controller's target from an origin towards a
// destination at the waypoint speed, and says when the destination is reached.
#ifndef AUTOPILOT_AC_WPNAV_HPP
#define AUTOPILOT_AC_WPNAV_HPP

#include "AP_Math.hpp"
#include "Location.hpp"

class AC_WPNav {
 public:
  void set_speed_xy(float ms) { _speed_ms = ms; }
  float get_speed_xy() const { return _speed_ms; }
  void set_radius(float m) { _radius_m = m; }
  float get_radius() const { return _radius_m; }
  // Starts a leg from where the vehicle is to `destination`.
  void set_wp_destination(const Location& destination);
  void update(float dt);
  bool reached_wp_destination() const { return _reached; }
  float get_wp_distance_to_destination() const { return _distance_m; }
  float get_yaw() const { return _yaw; }

 private:
  Vector3f _origin{0, 0, 0};
  Vector3f _destination{0, 0, 0};
  float _speed_ms = 5.0f;
  float _radius_m = 2.0f;
  float _distance_m = 0;
  float _yaw = 0;
  bool _reached = false;
};

extern AC_WPNav wp_nav;

#endif  // AUTOPILOT_AC_WPNAV_HPP
