// Hand-written, non-intrusive serialize functions for the specimen's critical state, for
// cereal's and Boost.Serialization's binary archives: every field symcr saves (the fields of
// symcr-gen's report for `copter`, i.e. all but the SYMCR_SKIP ones), in declaration order.
// Written once (`fields`) and wrapped for each library, as a user supporting both would.
//
// What a user has to do by hand here and symcr derives: reach private members (access.hpp),
// split bit-fields through temporaries (an archive needs an lvalue), save the union
// AP_Mission::Content as raw bytes (as symcr does), and keep all of it in step with the
// classes: these functions are for V0 and silently wrong for V2..V4.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_SERIALIZERS_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_SERIALIZERS_HPP

#include <cstdint>
#include <type_traits>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/binary_object.hpp>
#include <boost/serialization/level.hpp>
#include <boost/serialization/tracking.hpp>
#include <cereal/archives/binary.hpp>
#include <cereal/types/common.hpp>

#include "Copter.hpp"
#include "access.hpp"

SPECIMEN_BENCH_GRANT(AP_AHRS, _status)
SPECIMEN_BENCH_GRANT(AP_AHRS, _q)
SPECIMEN_BENCH_GRANT(AP_AHRS, _omega_I)
SPECIMEN_BENCH_GRANT(AP_AHRS, _omega)
SPECIMEN_BENCH_GRANT(AP_AHRS, _accel_ef)
SPECIMEN_BENCH_GRANT(AP_AHRS, _error_rp)
SPECIMEN_BENCH_GRANT(AP_AHRS, _error_yaw)
SPECIMEN_BENCH_GRANT(AP_AHRS, _origin)
SPECIMEN_BENCH_GRANT(AP_AHRS, _position_ned)
SPECIMEN_BENCH_GRANT(AP_AHRS, _velocity_ned)
SPECIMEN_BENCH_GRANT(AP_AHRS, _baro_offset)
SPECIMEN_BENCH_GRANT(AP_AHRS, _gps_fix_count)
SPECIMEN_BENCH_GRANT(AP_AHRS, _last_gps_ms)

SPECIMEN_BENCH_GRANT(AP_Mission, _flags)
SPECIMEN_BENCH_GRANT(AP_Mission, _cmd_total)
SPECIMEN_BENCH_GRANT(AP_Mission, _nav_cmd)
SPECIMEN_BENCH_GRANT(AP_Mission, _do_cmd)
SPECIMEN_BENCH_GRANT(AP_Mission, _prev_nav_cmd_id)
SPECIMEN_BENCH_GRANT(AP_Mission, _prev_nav_cmd_index)
SPECIMEN_BENCH_GRANT(AP_Mission, _prev_nav_cmd_wp_index)
SPECIMEN_BENCH_GRANT(AP_Mission, _last_change_time_ms)
SPECIMEN_BENCH_GRANT(AP_Mission, _items)

SPECIMEN_BENCH_GRANT(Copter, mode_stabilize)
SPECIMEN_BENCH_GRANT(Copter, mode_auto)
SPECIMEN_BENCH_GRANT(Copter, mode_loiter)
SPECIMEN_BENCH_GRANT(Copter, mode_rtl)
SPECIMEN_BENCH_GRANT(Copter, mode_land)
SPECIMEN_BENCH_GRANT(Copter, flightmode)
SPECIMEN_BENCH_GRANT(Copter, control_mode_reason)
SPECIMEN_BENCH_GRANT(Copter, prev_control_mode)
SPECIMEN_BENCH_GRANT(Copter, auto_mode)
SPECIMEN_BENCH_GRANT(Copter, rtl_state)
SPECIMEN_BENCH_GRANT(Copter, ap)
SPECIMEN_BENCH_GRANT(Copter, home)
SPECIMEN_BENCH_GRANT(Copter, wp_target)
SPECIMEN_BENCH_GRANT(Copter, loiter_target)
SPECIMEN_BENCH_GRANT(Copter, takeoff_alt_m)
SPECIMEN_BENCH_GRANT(Copter, rtl_alt_m)
SPECIMEN_BENCH_GRANT(Copter, wp_speed_ms)
SPECIMEN_BENCH_GRANT(Copter, wp_radius_m)
SPECIMEN_BENCH_GRANT(Copter, auto_yaw_rad)
SPECIMEN_BENCH_GRANT(Copter, arm_time_ms)
SPECIMEN_BENCH_GRANT(Copter, mode_change_time_ms)
SPECIMEN_BENCH_GRANT(Copter, land_detector_count)
SPECIMEN_BENCH_GRANT(Copter, flight_time_ms)
SPECIMEN_BENCH_GRANT(Copter, failsafe)

namespace specimen_bench::serializers {

template <class A>
constexpr bool kCereal = std::is_base_of_v<cereal::detail::OutputArchiveBase, A> ||
                         std::is_base_of_v<cereal::detail::InputArchiveBase, A>;

// The values, in order: cereal's ar(a, b, ...) or Boost's ar & a & b ...
template <class A, class... T>
void io(A& ar, T&... values) {
  if constexpr (kCereal<A>) {
    ar(values...);
  } else {
    (ar & ... & values);
  }
}

// Raw bytes (the union).
template <class A>
void raw(A& ar, void* data, std::size_t size) {
  if constexpr (kCereal<A>) {
    ar(cereal::binary_data(data, size));
  } else {
    ar & boost::serialization::make_binary_object(data, size);
  }
}

template <class A>
void fields(A& ar, Vector3f& v) {
  io(ar, v.x, v.y, v.z);
}

template <class A>
void fields(A& ar, Quaternion& q) {
  io(ar, q.q1, q.q2, q.q3, q.q4);
}

template <class A>
void fields(A& ar, Location& l) {
  std::uint8_t relative_alt = l.relative_alt, loiter_ccw = l.loiter_ccw;  // bit-fields
  io(ar, relative_alt, loiter_ccw, l.alt, l.lat, l.lng);
  l.relative_alt = relative_alt & 1u;
  l.loiter_ccw = loiter_ccw & 1u;
}

template <class A>
void fields(A& ar, AP_Mission::Mission_Command& c) {
  io(ar, c.index, c.id, c.p1);
  raw(ar, &c.content, sizeof c.content);
}

template <class A>
void fields(A& ar, AP_AHRS& a) {
  using namespace access;
  io(ar, a.roll, a.pitch, a.yaw, member(a, AP_AHRS__status{}), member(a, AP_AHRS__q{}),
     member(a, AP_AHRS__omega_I{}), member(a, AP_AHRS__omega{}), member(a, AP_AHRS__accel_ef{}),
     member(a, AP_AHRS__error_rp{}), member(a, AP_AHRS__error_yaw{}),
     member(a, AP_AHRS__origin{}), member(a, AP_AHRS__position_ned{}),
     member(a, AP_AHRS__velocity_ned{}), member(a, AP_AHRS__baro_offset{}),
     member(a, AP_AHRS__gps_fix_count{}), member(a, AP_AHRS__last_gps_ms{}));
}

template <class A>
void fields(A& ar, AP_Mission& m) {
  using namespace access;
  auto& flags = member(m, AP_Mission__flags{});
  std::uint8_t nav_cmd_loaded = flags.nav_cmd_loaded, do_cmd_loaded = flags.do_cmd_loaded,
               do_cmd_all_done = flags.do_cmd_all_done;  // bit-fields
  io(ar, flags.state, nav_cmd_loaded, do_cmd_loaded, do_cmd_all_done);
  flags.nav_cmd_loaded = nav_cmd_loaded & 1u;
  flags.do_cmd_loaded = do_cmd_loaded & 1u;
  flags.do_cmd_all_done = do_cmd_all_done & 1u;
  io(ar, member(m, AP_Mission__cmd_total{}), member(m, AP_Mission__nav_cmd{}),
     member(m, AP_Mission__do_cmd{}), member(m, AP_Mission__prev_nav_cmd_id{}),
     member(m, AP_Mission__prev_nav_cmd_index{}), member(m, AP_Mission__prev_nav_cmd_wp_index{}),
     member(m, AP_Mission__last_change_time_ms{}), member(m, AP_Mission__items{}));
}

// The flight mode points at one of the vehicle's mode objects: saved by its mode number and
// pointed at the object with that number on load (symcr saves it as a reference by path).
template <class A>
void flight_mode(A& ar, Copter& c) {
  using namespace access;
  Mode*& flightmode = member(c, Copter_flightmode{});
  std::uint8_t number = flightmode->mode_number();
  io(ar, number);
  Mode* const modes[] = {&member(c, Copter_mode_stabilize{}), &member(c, Copter_mode_auto{}),
                         &member(c, Copter_mode_loiter{}), &member(c, Copter_mode_rtl{}),
                         &member(c, Copter_mode_land{})};
  for (Mode* mode : modes) {
    if (mode->mode_number() == number) flightmode = mode;
  }
}

// The constants (land speeds), the modes' references and the mission's callbacks are the
// build's own: not saved, as symcr leaves them out.
template <class A>
void fields(A& ar, Copter& c) {
  using namespace access;
  io(ar, c.ahrs, c.mission);
  flight_mode(ar, c);
  io(ar, member(c, Copter_control_mode_reason{}), member(c, Copter_prev_control_mode{}),
     member(c, Copter_auto_mode{}), member(c, Copter_rtl_state{}));
  auto& ap = member(c, Copter_ap{});
  io(ar, ap.motor_armed, ap.home_is_set, ap.auto_armed, ap.land_complete, ap.land_complete_maybe,
     ap.takeoff_complete, ap.mission_complete, ap.rtl_state_complete, ap.land_repositioning);
  io(ar, member(c, Copter_home{}), member(c, Copter_wp_target{}),
     member(c, Copter_loiter_target{}), member(c, Copter_takeoff_alt_m{}),
     member(c, Copter_rtl_alt_m{}), member(c, Copter_wp_speed_ms{}),
     member(c, Copter_wp_radius_m{}), member(c, Copter_auto_yaw_rad{}),
     member(c, Copter_arm_time_ms{}), member(c, Copter_mode_change_time_ms{}),
     member(c, Copter_land_detector_count{}), member(c, Copter_flight_time_ms{}));
  auto& failsafe = member(c, Copter_failsafe{});
  io(ar, failsafe.gcs, failsafe.ekf, failsafe.last_heartbeat_ms);
}

}  // namespace specimen_bench::serializers

// cereal: serialize(archive, value), found by ADL (the specimen's types are in the global
// namespace).
#define SPECIMEN_BENCH_SERIALIZE(T)                                       \
  template <class A>                                                      \
  void serialize(A& ar, T& value) {                                       \
    specimen_bench::serializers::fields(ar, value);                       \
  }                                                                       \
  namespace boost::serialization {                                        \
  template <class A>                                                      \
  void serialize(A& ar, T& value, unsigned) {                             \
    specimen_bench::serializers::fields(ar, value);                       \
  }                                                                       \
  }                                                                       \
  BOOST_CLASS_IMPLEMENTATION(T, boost::serialization::object_serializable) \
  BOOST_CLASS_TRACKING(T, boost::serialization::track_never)
// Boost: serialize(archive, value, version) in boost::serialization, where Boost looks (and
// cereal does not, which would otherwise find two candidates); its fastest configuration for
// plain structs: no class information, no object tracking.
SPECIMEN_BENCH_SERIALIZE(Vector3f)
SPECIMEN_BENCH_SERIALIZE(Quaternion)
SPECIMEN_BENCH_SERIALIZE(Location)
SPECIMEN_BENCH_SERIALIZE(AP_Mission::Mission_Command)
SPECIMEN_BENCH_SERIALIZE(AP_AHRS)
SPECIMEN_BENCH_SERIALIZE(AP_Mission)
SPECIMEN_BENCH_SERIALIZE(Copter)

#endif  // SYMCR_BENCHMARKS_SPECIMEN_SERIALIZERS_HPP
