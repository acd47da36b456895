// The mission: a list of commands uploaded by the ground station, and the state machine that
// walks it (ArduPilot's AP_Mission). Navigation commands are handed to the vehicle one at a
// time; "do" commands between them run when the mission advances past them.
#ifndef AUTOPILOT_AP_MISSION_HPP
#define AUTOPILOT_AP_MISSION_HPP

#include <cstdint>

#include <symcr/symcr.hpp>

#include "AP_Functor.hpp"
#include "Location.hpp"

class Copter;

class AP_Mission {
 public:
  static constexpr std::uint16_t AP_MISSION_MAX_COMMANDS = 64;
  static constexpr std::uint16_t AP_MISSION_CMD_INDEX_NONE = 65535;

  enum mission_state : std::uint8_t {
    MISSION_STOPPED = 0,
    MISSION_RUNNING = 1,
    MISSION_COMPLETE = 2,
  };

  struct Change_Speed_Command {
    std::uint8_t speed_type;  // 0 = airspeed, 1 = ground speed
    float target_ms;
    float throttle_pct;
  };

  union Content {
    Location location;
    Change_Speed_Command speed;
  };

  struct Mission_Command {
    std::uint16_t index;  // position in the command list
    std::uint16_t id;     // MAV_CMD
    std::uint16_t p1;     // first parameter (e.g. loiter time)
    Content content;
  };

  // The vehicle's callbacks: start a navigation command, verify that it is done (true moves
  // the mission on), and the mission's end.
  using mission_cmd_fn_t = Functor<Copter, bool, const Mission_Command&>;
  using mission_complete_fn_t = Functor<Copter, void>;

  AP_Mission(mission_cmd_fn_t cmd_start_fn, mission_cmd_fn_t cmd_verify_fn,
             mission_complete_fn_t mission_complete_fn)
      : _cmd_start_fn(cmd_start_fn),
        _cmd_verify_fn(cmd_verify_fn),
        _mission_complete_fn(mission_complete_fn) {}

  // Replaces the command list (ground-station upload). Refused while running.
  bool clear();
  bool add_cmd(const Mission_Command& cmd);
  std::uint16_t num_commands() const { return _cmd_total; }
  bool get_cmd(std::uint16_t index, Mission_Command& out) const;

  void start();
  void stop() { _flags.state = MISSION_STOPPED; }
  void resume();
  // Runs the current navigation command; advances when the vehicle reports it complete.
  void update();

  mission_state state() const { return _flags.state; }
  const Mission_Command& get_current_nav_cmd() const { return _nav_cmd; }
  std::uint16_t get_current_nav_index() const { return _nav_cmd.index; }
  std::uint16_t get_prev_nav_cmd_index() const { return _prev_nav_cmd_index; }
  static bool is_nav_cmd(const Mission_Command& cmd);

 private:
  bool advance_current_nav_cmd(std::uint16_t start_index);
  void complete();

  mission_cmd_fn_t _cmd_start_fn;
  mission_cmd_fn_t _cmd_verify_fn;
  mission_complete_fn_t _mission_complete_fn;

  struct Mission_Flags {
    mission_state state;
    std::uint8_t nav_cmd_loaded : 1;
    std::uint8_t do_cmd_loaded : 1;
    std::uint8_t do_cmd_all_done : 1;
  } _flags{MISSION_STOPPED, 0, 0, 0};

  std::uint16_t _cmd_total = 0;
  Mission_Command _nav_cmd{};  // the navigation command being run
  Mission_Command _do_cmd{};   // the last "do" command run
  std::uint16_t _prev_nav_cmd_id = 0;
  std::uint16_t _prev_nav_cmd_index = AP_MISSION_CMD_INDEX_NONE;
  std::uint16_t _prev_nav_cmd_wp_index = AP_MISSION_CMD_INDEX_NONE;
  std::uint32_t _last_change_time_ms = 0;
  Mission_Command _items[AP_MISSION_MAX_COMMANDS]{};  // ArduPilot keeps these in storage
};

#endif  // AUTOPILOT_AP_MISSION_HPP
