// Flight modes: STABILIZE, AUTO (mission), LOITER, RTL and LAND.
#include "AC_PosControl.hpp"
#include "AC_WPNav.hpp"
#include "Copter.hpp"
#include "messages.hpp"

namespace {
constexpr float kLandSlowAltM = 5.0f;     // below this, descend at the final landing speed
constexpr float kAltReachedM = 0.5f;
constexpr float kRtlCloseEnoughM = 2.0f;
}  // namespace

Mode::Mode(Copter& vehicle)
    : copter(vehicle), pos_control(::pos_control), wp_nav(::wp_nav) {}

Mode* Copter::mode_from_number(Mode::Number number) {
  switch (number) {
    case Mode::STABILIZE: return &mode_stabilize;
    case Mode::AUTO: return &mode_auto;
    case Mode::LOITER: return &mode_loiter;
    case Mode::RTL: return &mode_rtl;
    case Mode::LAND: return &mode_land;
  }
  return nullptr;
}

// --- STABILIZE: no pilot here, so only on the ground, holding position if airborne ---------

bool ModeStabilize::init() { return !copter.ap.motor_armed; }

void ModeStabilize::run() { copter.hold_position_here(); }

// --- AUTO ----------------------------------------------------------------------------------

bool ModeAuto::init() {
  if (copter.ap.motor_armed) {
    if (copter.mission.num_commands() < 2) return false;
    copter.ap.auto_armed = true;
    if (copter.mission.state() == AP_Mission::MISSION_COMPLETE ||
        copter.mission.state() == AP_Mission::MISSION_STOPPED) {
      copter.mission.start();
    } else {
      copter.mission.resume();
    }
  }
  return true;
}

void ModeAuto::run() { copter.auto_run(); }

// --- LOITER, RTL, LAND ---------------------------------------------------------------------

bool ModeLoiter::init() {
  copter.hold_position_here();
  return true;
}

void ModeLoiter::run() { copter.loiter_run(); }

bool ModeRTL::init() {
  if (!copter.ap.home_is_set) return false;
  copter.rtl_state = RTLState::InitialClimb;
  copter.ap.rtl_state_complete = false;
  copter.hold_position_here();
  return true;
}

void ModeRTL::run() { copter.rtl_run(); }

bool ModeLand::init() {
  copter.hold_position_here();
  copter.land_detector_count = 0;
  return true;
}

void ModeLand::run() { copter.land_run(false); }

// --- What the modes fly --------------------------------------------------------------------

void Copter::hold_position_here() {
  Location here;
  if (ahrs.get_location(here)) loiter_target = here;
  pos_control.init_at_current_position();
}

bool Copter::reached_altitude(float alt_m) const {
  return ahrs.get_altitude() >= alt_m - kAltReachedM;
}

bool Copter::start_command(const AP_Mission::Mission_Command& cmd) {
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
  return true;
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
