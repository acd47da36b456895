#include "AC_WPNav.hpp"

#include "AC_PosControl.hpp"
#include "Copter.hpp"

namespace {
constexpr float kDecel = 2.0f;        // m/s^2 when closing on the destination
constexpr float kCrossTrackP = 0.8f;  // m/s back towards the line per metre off it
constexpr float kCrossTrackMax = 3.0f;
}  // namespace

void AC_WPNav::set_wp_destination(const Location& destination) {
  _origin = copter.ahrs.get_position_NED();
  _destination = copter.ahrs.location_to_NED(destination);
  _reached = false;
  const Vector2f leg = (_destination - _origin).xy();
  if (leg.length() > 1.0f) _yaw = std::atan2(leg.y, leg.x);
}

void AC_WPNav::update(float /*dt*/) {
  const Vector3f& pos = copter.ahrs.get_position_NED();
  const Vector2f to_destination = (_destination - pos).xy();
  _distance_m = to_destination.length();
  if (_distance_m <= _radius_m) _reached = true;
  pos_control.set_alt_target(-_destination.z);

  const Vector2f leg = (_destination - _origin).xy();
  const float leg_length = leg.length();
  if (_reached || leg_length < 1.0f) {
    pos_control.set_pos_target_xy(_destination.xy());
    return;
  }
  // Fly along the line between the waypoints (not straight at the destination, so that a
  // gust does not make the vehicle cut the route), slowing to stop at the destination.
  const Vector2f unit = leg * (1.0f / leg_length);
  const Vector2f normal{-unit.y, unit.x};
  const float cross_track = (pos - _origin).xy() * normal;
  if ((pos - _origin).xy() * unit >= leg_length) {  // overshot: home in on the point itself
    pos_control.set_pos_target_xy(_destination.xy());
    return;
  }
  const float along_speed = std::fmin(_speed_ms, std::sqrt(2.0f * kDecel * _distance_m));
  const float correction =
      constrain_value(-cross_track * kCrossTrackP, -kCrossTrackMax, kCrossTrackMax);
  pos_control.set_vel_target_xy(unit * along_speed + normal * correction);
}
