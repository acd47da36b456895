// Flight modes: AUTO (mission), LOITER, RTL and LAND.
#include "AC_PosControl.hpp"
#include "AC_WPNav.hpp"
#include "Copter.hpp"
#include "messages.hpp"

namespace {
constexpr float kLandSlowAltM = 5.0f;     // below this, descend at the final landing speed
constexpr float kAltReachedM = 0.5f;
constexpr float kRtlCloseEnoughM = 2.0f;
}  // namespace

bool Copter::mode_enter(Mode mode) {
  switch (mode) {
    case Mode::AUTO:
      if (ap.motor_armed) {
        if (mission.num_commands() < 2) return false;
        ap.auto_armed = true;
        if (mission.state() == AP_Mission::MISSION_COMPLETE ||
            mission.state() == AP_Mission::MISSION_STOPPED) {
          mission.start();
        } else {
          mission.resume();
        }
      }
      return true;
    case Mode::LOITER:
      hold_position_here();
      return true;
    case Mode::RTL:
      if (!ap.home_is_set) return false;
      rtl_state = RTLState::InitialClimb;
      ap.rtl_state_complete = false;
      hold_position_here();
      return true;
    case Mode::LAND:
      hold_position_here();
      land_detector_count = 0;
      return true;
    case Mode::STABILIZE:
      return !ap.motor_armed;  // no pilot: only on the ground
  }
  return false;
}

void Copter::hold_position_here() {
  Location here;
  if (ahrs.get_location(here)) loiter_target = here;
  pos_control.init_at_current_position();
}

bool Copter::reached_altitude(float alt_m) const {
  return ahrs.get_altitude() >= alt_m - kAltReachedM;
}

// --- AUTO ----------------------------------------------------------------------------------

void Copter::start_command(const AP_Mission::Mission_Command& cmd) {
  switch (cmd.id) {
    case mav::CMD_NAV_TAKEOFF:
      auto_takeoff_start(cmd.content.location.alt * 0.01f);
      break;
    case mav::CMD_NAV_WAYPOINT:
      auto_wp_start(cmd.content.location);
      break;
    case mav::CMD_NAV_LAND:
      auto_land_start(cmd.content.location);
      break;
    case mav::CMD_NAV_RETURN_TO_LAUNCH:
      auto_rtl_start();
      break;
    case mav::CMD_DO_CHANGE_SPEED:
      if (cmd.content.speed.target_ms > 0.0f) {
        wp_speed_ms = cmd.content.speed.target_ms;
        wp_nav.set_speed_xy(wp_speed_ms);
      }
      break;
    default:
      break;
  }
}

bool Copter::verify_command(const AP_Mission::Mission_Command& cmd) {
  switch (cmd.id) {
    case mav::CMD_NAV_TAKEOFF:
      if (reached_altitude(takeoff_alt_m)) ap.takeoff_complete = true;
      return ap.takeoff_complete;
    case mav::CMD_NAV_WAYPOINT:
      return wp_nav.reached_wp_destination();
    case mav::CMD_NAV_LAND:
    case mav::CMD_NAV_RETURN_TO_LAUNCH:
      return ap.land_complete;
    default:
      return true;
  }
}

void Copter::auto_takeoff_start(float alt_m) {
  auto_mode = AutoMode::TAKEOFF;
  takeoff_alt_m = alt_m;
  ap.takeoff_complete = false;
  hold_position_here();
}

void Copter::auto_wp_start(const Location& destination) {
  auto_mode = AutoMode::WP;
  wp_target = destination;
  if (wp_target.alt == 0) {
    wp_target.alt = static_cast<std::int32_t>(ahrs.get_altitude() * 100.0f);
  }
  wp_nav.set_wp_destination(wp_target);
  auto_yaw_rad = wp_nav.get_yaw();
}

void Copter::auto_land_start(const Location& location) {
  auto_mode = AutoMode::LAND;
  land_detector_count = 0;
  ap.land_repositioning = !location.is_zero();
  if (ap.land_repositioning) {
    wp_target = location;
    wp_target.alt = static_cast<std::int32_t>(ahrs.get_altitude() * 100.0f);
    wp_nav.set_wp_destination(wp_target);
  } else {
    hold_position_here();
  }
}

void Copter::auto_rtl_start() {
  auto_mode = AutoMode::RTL;
  rtl_state = RTLState::InitialClimb;
  ap.rtl_state_complete = false;
  hold_position_here();
}

void Copter::auto_run() {
  if (!ap.auto_armed) {
    hold_position_here();
    return;
  }
  switch (auto_mode) {
    case AutoMode::TAKEOFF:
      takeoff_run();
      break;
    case AutoMode::WP:
      wp_nav.update(G_Dt);
      auto_yaw_rad = wp_nav.get_yaw();
      break;
    case AutoMode::LAND:
      if (ap.land_repositioning) {
        wp_nav.update(G_Dt);
        if (wp_nav.reached_wp_destination()) {
          ap.land_repositioning = false;
          loiter_target = wp_target;
        }
      } else {
        land_run(false);
      }
      break;
    case AutoMode::RTL:
      rtl_run();
      break;
  }
  mission.update();
}

void Copter::takeoff_run() {
  const Vector3f target = ahrs.location_to_NED(loiter_target);
  pos_control.set_pos_target_xy(target.xy());
  pos_control.set_alt_target(takeoff_alt_m);
}

// --- LOITER, LAND, RTL ---------------------------------------------------------------------

void Copter::loiter_run() {
  const Vector3f target = ahrs.location_to_NED(loiter_target);
  pos_control.set_pos_target_xy(target.xy());
  pos_control.set_alt_target(loiter_target.alt * 0.01f);
}

void Copter::land_run(bool /*repositioning*/) {
  const Vector3f target = ahrs.location_to_NED(loiter_target);
  pos_control.set_pos_target_xy(target.xy());
  const float speed = ahrs.get_altitude() > kLandSlowAltM ? land_speed_high_ms : land_speed_ms;
  pos_control.set_climb_rate(-speed);
}

void Copter::rtl_run() {
  switch (rtl_state) {
    case RTLState::InitialClimb: {
      const float alt = rtl_alt_m > loiter_target.alt * 0.01f ? rtl_alt_m : loiter_target.alt * 0.01f;
      loiter_target.alt = static_cast<std::int32_t>(alt * 100.0f);
      loiter_run();
      if (reached_altitude(alt)) {
        rtl_state = RTLState::ReturnHome;
        wp_target = home;
        wp_target.alt = loiter_target.alt;
        wp_nav.set_wp_destination(wp_target);
      }
      break;
    }
    case RTLState::ReturnHome:
      wp_nav.update(G_Dt);
      auto_yaw_rad = wp_nav.get_yaw();
      if (wp_nav.reached_wp_destination() ||
          ahrs.get_position_NED().xy().length() < kRtlCloseEnoughM) {
        rtl_state = RTLState::FinalDescent;
        loiter_target = home;
      }
      break;
    case RTLState::FinalDescent:
      land_run(false);
      ap.rtl_state_complete = ap.land_complete;
      break;
  }
}
