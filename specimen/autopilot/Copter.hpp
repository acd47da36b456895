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

class AC_PosControl;
class AC_WPNav;
class Copter;

// A flight mode (ArduCopter's Mode): one object per mode, each a member of Copter, and
// Copter::flightmode points at the one flying. The references bind a mode to the vehicle and
// to the controllers it drives; the new build binds them again, so they are not saved.
class Mode {
 public:
  // ArduCopter's mode numbers (MAVLink's custom_mode).
  enum Number : std::uint8_t {
    STABILIZE = 0,
    AUTO = 3,
    LOITER = 5,
    RTL = 6,
    LAND = 9,
  };

  explicit Mode(Copter& vehicle);
  virtual ~Mode() = default;

  virtual Number mode_number() const = 0;
  // Entering the mode; false refuses it, and the vehicle stays in its current mode.
  virtual bool init() = 0;
  // One 100 Hz loop in the mode.
  virtual void run() = 0;

 protected:
  Copter& copter;
  AC_PosControl& pos_control;
  AC_WPNav& wp_nav;
};

class ModeStabilize : public Mode {
 public:
  using Mode::Mode;
  Number mode_number() const override { return STABILIZE; }
  bool init() override;
  void run() override;
};

class ModeAuto : public Mode {
 public:
  using Mode::Mode;
  Number mode_number() const override { return AUTO; }
  bool init() override;
  void run() override;
};

class ModeLoiter : public Mode {
 public:
  using Mode::Mode;
  Number mode_number() const override { return LOITER; }
  bool init() override;
  void run() override;
};

class ModeRTL : public Mode {
 public:
  using Mode::Mode;
  Number mode_number() const override { return RTL; }
  bool init() override;
  void run() override;
};

class ModeLand : public Mode {
 public:
  using Mode::Mode;
  Number mode_number() const override { return LAND; }
  bool init() override;
  void run() override;
};

class Copter {
 public:
  // Start-up: scheduler tasks, parameters.
  void setup();
  // One 100 Hz loop, after hal.sample was filled.
  void loop();
  // After a checkpoint was restored: rebuild what is derived from the critical state.
  void resume_after_restore();

  bool set_mode(Mode::Number number, ModeReason reason);
  bool arm();
  void disarm();

  // AP_Mission's callbacks.
  bool start_command(const AP_Mission::Mission_Command& cmd);
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

  Mode::Number get_mode() const { return flightmode->mode_number(); }
  bool armed() const { return ap.motor_armed; }
  bool mission_complete() const { return ap.mission_complete; }

  AP_AHRS ahrs;
  AP_Mission mission{{this, &Copter::start_command}, {this, &Copter::verify_command},
                     {this, &Copter::exit_mission}};
  GCS_Copter gcs SYMCR_SKIP;

 private:
  friend class GCS_Copter;
  friend class ModeStabilize;
  friend class ModeAuto;
  friend class ModeLoiter;
  friend class ModeRTL;
  friend class ModeLand;

  Mode* mode_from_number(Mode::Number number);

  // What the modes fly (modes.cpp).
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

  // Flight modes, and the one flying: restored as a reference to the same mode's object.
  ModeStabilize mode_stabilize{*this};
  ModeAuto mode_auto{*this};
  ModeLoiter mode_loiter{*this};
  ModeRTL mode_rtl{*this};
  ModeLand mode_land{*this};
  Mode* flightmode = &mode_stabilize;
  ModeReason control_mode_reason = ModeReason::UNKNOWN;
  Mode::Number prev_control_mode = Mode::STABILIZE;
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
  // Constants of this build: a new build keeps its own.
  const float land_speed_ms = 0.5f;
  const float land_speed_high_ms = 1.5f;
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
