// The vehicle: flight modes, arming, mission execution, landing detection. Like ArduCopter's
// Copter class it owns the estimator (ahrs) and the mission; the controllers, motors and
// scheduler are process machinery outside it.
//
// Checkpointing: `copter` is the root (SYMCR_CHECKPOINT in Copter.cpp). Everything in it is
// critical state carried across a restart, except what is marked SYMCR_SKIP: timing, loop
// statistics and the ground-control link state, which the new process re-creates.
#ifndef AUTOPILOT_COPTER_HPP
#define AUTOPILOT_COPTER_HPP

#include <cstdint>

#include <symcr/symcr.hpp>

#include "AP_AHRS.hpp"
#include "AP_Mission.hpp"
#include "GCS_Copter.hpp"
#include "Location.hpp"

// ArduCopter's flight mode numbers.
enum class Mode : std::uint8_t {
  STABILIZE = 0,
  AUTO = 3,
  LOITER = 5,
  RTL = 6,
  LAND = 9,
};

enum class ModeReason : std::uint8_t {
  UNKNOWN = 0,
  GCS_COMMAND = 2,
  MISSION_END = 5,
  FAILSAFE = 8,
};

enum class AutoMode : std::uint8_t {
  TAKEOFF,
  WP,
  LAND,
  RTL,
};

enum class RTLState : std::uint8_t {
  InitialClimb,
  ReturnHome,
  FinalDescent,
};

class Copter {
 public:
  // Start-up: scheduler tasks, parameters.
  void setup();
  // One 100 Hz loop, after hal.sample was filled.
  void loop();
  // After a checkpoint was restored: rebuild what is derived from the critical state.
  void resume_after_restore();

  bool set_mode(Mode mode, ModeReason reason);
  bool arm();
  void disarm();

  // AP_Mission callbacks.
  void start_command(const AP_Mission::Mission_Command& cmd);
  bool verify_command(const AP_Mission::Mission_Command& cmd);
  void exit_mission();
  void gcs_send_mission_current(std::uint16_t seq) { gcs.send_mission_current(seq); }
  void gcs_send_mission_item_reached(std::uint16_t seq) { gcs.send_mission_item_reached(seq); }

  // Scheduler tasks.
  static void read_AHRS_task();
  static void gcs_update_task();
  static void update_flight_mode_task();
  static void update_land_detector_task();
  static void failsafe_check_task();
  static void gcs_heartbeat_task();

  Mode get_mode() const { return control_mode; }
  bool armed() const { return ap.motor_armed; }
  bool mission_complete() const { return ap.mission_complete; }

  AP_AHRS ahrs;
  AP_Mission mission;
  GCS_Copter gcs SYMCR_SKIP;

 private:
  friend class GCS_Copter;

  // Mode implementations (modes.cpp).
  bool mode_enter(Mode mode);
  void auto_run();
  void auto_takeoff_start(float alt_m);
  void auto_wp_start(const Location& destination);
  void auto_land_start(const Location& location);
  void auto_rtl_start();
  void loiter_run();
  void rtl_run();
  void land_run(bool repositioning);
  void takeoff_run();
  void hold_position_here();
  bool reached_altitude(float alt_m) const;

  // Flight mode.
  Mode control_mode = Mode::STABILIZE;
  ModeReason control_mode_reason = ModeReason::UNKNOWN;
  Mode prev_control_mode = Mode::STABILIZE;
  AutoMode auto_mode = AutoMode::TAKEOFF;
  RTLState rtl_state = RTLState::InitialClimb;

  // Vehicle flags (ArduCopter's `ap` bit-field union, as plain flags).
  struct AP_Flags {
    bool motor_armed;
    bool home_is_set;
    bool auto_armed;           // the mission may run (armed with AUTO selected)
    bool land_complete;
    bool land_complete_maybe;
    bool takeoff_complete;
    bool mission_complete;
    bool rtl_state_complete;
    bool land_repositioning;   // flying to a LAND command's location before descending
  } ap{};

  Location home{};
  Location wp_target{};      // destination of the current leg
  Location loiter_target{};  // position held in LOITER, TAKEOFF and LAND
  float takeoff_alt_m = 0;
  float rtl_alt_m = 15.0f;
  float wp_speed_ms = 5.0f;
  float wp_radius_m = 2.0f;
  float land_speed_ms = 0.5f;
  float land_speed_high_ms = 1.5f;
  float auto_yaw_rad = 0;    // heading flown in AUTO and RTL

  std::uint32_t arm_time_ms = 0;
  std::uint32_t mode_change_time_ms = 0;
  std::uint32_t land_detector_count = 0;
  std::uint32_t flight_time_ms = 0;

  struct Failsafe {
    bool gcs;
    bool ekf;
    std::uint32_t last_heartbeat_ms;
  } failsafe{};

  // Loop timing and statistics: meaningful only within one process.
  std::uint64_t last_loop_us SYMCR_SKIP = 0;
  float G_Dt SYMCR_SKIP = 0.01f;
  std::uint32_t loop_count SYMCR_SKIP = 0;
  std::uint32_t max_loop_us SYMCR_SKIP = 0;
};

extern Copter copter;

#endif  // AUTOPILOT_COPTER_HPP
