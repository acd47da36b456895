#include "Copter.hpp"

#include "AC_AttitudeControl.hpp"
#include "AC_PosControl.hpp"
#include "AC_WPNav.hpp"
#include "AP_Checkpoint.hpp"
#include "AP_Motors.hpp"
#include "AP_Scheduler.hpp"

// The checkpoint root: the vehicle's state, by its source-level name.
SYMCR_CHECKPOINT Copter copter;

AP_HAL hal;
AP_Motors motors;
AC_AttitudeControl attitude_control;
AC_PosControl pos_control;
AC_WPNav wp_nav;

namespace {
constexpr std::uint32_t kGcsFailsafeMs = 5000;
constexpr float kLandedThrustRatio = 0.8f;  // of hover thrust: the ground carries the rest
constexpr std::uint32_t kLandDetectLoops = 100;

const AP_Scheduler::Task kTasks[] = {
    {&Copter::read_AHRS_task, 100, "read_AHRS"},
    {&Copter::gcs_update_task, 100, "gcs_update"},
    {&Copter::update_flight_mode_task, 100, "update_flight_mode"},
    {&Copter::update_land_detector_task, 100, "update_land_detector"},
    {&Copter::failsafe_check_task, 10, "failsafe_check"},
    {&Copter::gcs_heartbeat_task, 1, "gcs_heartbeat"},
    // Last: the state is consistent at the end of the loop.
    {&AP_Checkpoint::save_task, 100, "checkpoint"},
};
}  // namespace

void Copter::setup() {
  scheduler.init(kTasks, static_cast<std::uint8_t>(sizeof(kTasks) / sizeof(kTasks[0])));
  wp_nav.set_speed_xy(wp_speed_ms);
  wp_nav.set_radius(wp_radius_m);
  mission.clear();
}

void Copter::loop() {
  const std::uint64_t now = hal.micros64();
  G_Dt = last_loop_us == 0 ? 0.01f
                           : constrain_value((now - last_loop_us) * 1e-6f, 0.001f, 0.05f);
  last_loop_us = now;
  ++loop_count;
  scheduler.run();
}

void Copter::read_AHRS_task() { copter.ahrs.update(hal.sample, copter.G_Dt); }

void Copter::gcs_update_task() { copter.gcs.update_receive(); }

void Copter::gcs_heartbeat_task() { copter.gcs.send_heartbeat(); }

void Copter::update_flight_mode_task() {
  Copter& c = copter;
  if (!c.ap.motor_armed) {
    attitude_control.relax();
    motors.set_armed(false);
    motors.output();
    return;
  }
  c.flightmode->run();
  pos_control.update(c.G_Dt, c.auto_yaw_rad);
  attitude_control.rate_controller_run(c.G_Dt);
  motors.set_armed(true);
  motors.output();
  c.flight_time_ms += static_cast<std::uint32_t>(c.G_Dt * 1000.0f + 0.5f);
}

void Copter::update_land_detector_task() {
  Copter& c = copter;
  if (!c.ap.motor_armed) {
    c.ap.land_complete = true;
    c.land_detector_count = 0;
    return;
  }
  const float hover_n = motors.params.mass_kg * GRAVITY_MSS;
  const bool descending_phase = (c.get_mode() == Mode::LAND) ||
                                (c.get_mode() == Mode::AUTO && c.auto_mode == AutoMode::LAND &&
                                 !c.ap.land_repositioning) ||
                                (c.get_mode() == Mode::RTL &&
                                 c.rtl_state == RTLState::FinalDescent);
  const bool still = std::fabs(c.ahrs.get_velocity_NED().z) < 0.3f;
  if (descending_phase && still && pos_control.get_thrust_n() < kLandedThrustRatio * hover_n) {
    if (++c.land_detector_count >= kLandDetectLoops) c.ap.land_complete = true;
    c.ap.land_complete_maybe = c.land_detector_count > kLandDetectLoops / 4;
  } else {
    c.land_detector_count = 0;
    c.ap.land_complete = false;
    c.ap.land_complete_maybe = false;
  }
  if (c.ap.land_complete && (c.get_mode() == Mode::LAND || c.get_mode() == Mode::RTL)) {
    c.disarm();
  }
}

void Copter::failsafe_check_task() {
  Copter& c = copter;
  const std::uint32_t now = hal.millis();
  c.failsafe.ekf = c.ap.motor_armed && !c.ahrs.healthy();
  const bool gcs_lost =
      c.failsafe.last_heartbeat_ms != 0 && now - c.failsafe.last_heartbeat_ms > kGcsFailsafeMs;
  if (gcs_lost && !c.failsafe.gcs && c.ap.motor_armed && c.get_mode() != Mode::AUTO) {
    c.gcs.send_text("Failsafe: GCS lost, RTL");
    c.set_mode(Mode::RTL, ModeReason::FAILSAFE);
  }
  c.failsafe.gcs = gcs_lost;
}

bool Copter::arm() {
  if (ap.motor_armed) return true;
  if (!ahrs.healthy()) {
    gcs.send_text("Arm: AHRS not healthy");
    return false;
  }
  if (mission.num_commands() < 2 && get_mode() == Mode::AUTO) {
    gcs.send_text("Arm: no mission");
    return false;
  }
  Location here;
  ahrs.get_location(here);
  home = here;
  home.alt = 0;
  ap.home_is_set = true;
  ap.motor_armed = true;
  ap.land_complete = false;
  ap.mission_complete = false;
  arm_time_ms = hal.millis();
  flight_time_ms = 0;
  auto_yaw_rad = ahrs.yaw;
  pos_control.init_at_current_position();
  gcs.send_text("Armed");
  if (get_mode() == Mode::AUTO) mode_auto.init();
  return true;
}

void Copter::disarm() {
  if (!ap.motor_armed) return;
  ap.motor_armed = false;
  ap.auto_armed = false;
  motors.set_armed(false);
  gcs.send_text("Disarmed");
}

bool Copter::set_mode(Mode::Number number, ModeReason reason) {
  Mode* new_mode = mode_from_number(number);
  if (new_mode == nullptr) return false;
  if (new_mode == flightmode) return true;
  if (!new_mode->init()) return false;
  prev_control_mode = flightmode->mode_number();
  flightmode = new_mode;
  control_mode_reason = reason;
  mode_change_time_ms = hal.millis();
  return true;
}

void Copter::exit_mission() {
  ap.mission_complete = true;
  gcs.send_text("Mission complete");
  if (ap.land_complete) {
    disarm();
  } else {
    set_mode(Mode::LAND, ModeReason::MISSION_END);
  }
}

void Copter::resume_after_restore() {
  motors.set_armed(ap.motor_armed);
  wp_nav.set_speed_xy(wp_speed_ms);
  wp_nav.set_radius(wp_radius_m);
  if (!ap.motor_armed) return;
  pos_control.init_at_current_position();
  switch (get_mode()) {
    case Mode::AUTO:
      if (auto_mode == AutoMode::WP || (auto_mode == AutoMode::LAND && ap.land_repositioning)) {
        wp_nav.set_wp_destination(wp_target);
      }
      break;
    case Mode::RTL:
      if (rtl_state == RTLState::ReturnHome) wp_nav.set_wp_destination(wp_target);
      break;
    default:
      break;
  }
  gcs.send_mission_current(mission.get_current_nav_index());
}
