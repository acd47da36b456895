#include "AP_Mission.hpp"

#include "AP_HAL.hpp"
#include "Copter.hpp"
#include "messages.hpp"

bool AP_Mission::clear() {
  if (_flags.state == MISSION_RUNNING) return false;
  _cmd_total = 0;
  _flags.nav_cmd_loaded = 0;
  _flags.do_cmd_loaded = 0;
  _nav_cmd = {};
  _nav_cmd.index = AP_MISSION_CMD_INDEX_NONE;
  return true;
}

bool AP_Mission::add_cmd(const Mission_Command& cmd) {
  if (_cmd_total >= AP_MISSION_MAX_COMMANDS) return false;
  _items[_cmd_total] = cmd;
  _items[_cmd_total].index = _cmd_total;
  ++_cmd_total;
  return true;
}

bool AP_Mission::get_cmd(std::uint16_t index, Mission_Command& out) const {
  if (index >= _cmd_total) return false;
  out = _items[index];
  return true;
}

bool AP_Mission::is_nav_cmd(const Mission_Command& cmd) {
  return cmd.id == mav::CMD_NAV_WAYPOINT || cmd.id == mav::CMD_NAV_TAKEOFF ||
         cmd.id == mav::CMD_NAV_LAND || cmd.id == mav::CMD_NAV_RETURN_TO_LAUNCH;
}

void AP_Mission::start() {
  _flags.state = MISSION_RUNNING;
  _flags.nav_cmd_loaded = 0;
  _flags.do_cmd_all_done = 0;
  _prev_nav_cmd_id = 0;
  _prev_nav_cmd_index = AP_MISSION_CMD_INDEX_NONE;
  _prev_nav_cmd_wp_index = AP_MISSION_CMD_INDEX_NONE;
  // Command 0 is home; the mission proper starts at 1.
  if (!advance_current_nav_cmd(1)) complete();
}

void AP_Mission::resume() {
  if (_flags.state == MISSION_COMPLETE || _cmd_total == 0) return;
  _flags.state = MISSION_RUNNING;
  if (!_flags.nav_cmd_loaded) {
    if (!advance_current_nav_cmd(1)) complete();
    return;
  }
  _cmd_start_fn(_nav_cmd);
}

void AP_Mission::update() {
  if (_flags.state != MISSION_RUNNING || _cmd_total == 0) return;
  if (!_flags.nav_cmd_loaded) {
    if (!advance_current_nav_cmd(_nav_cmd.index == AP_MISSION_CMD_INDEX_NONE ? 1
                                                                              : _nav_cmd.index + 1)) {
      complete();
    }
    return;
  }
  if (_cmd_verify_fn(_nav_cmd)) {
    copter.gcs_send_mission_item_reached(_nav_cmd.index);
    _flags.nav_cmd_loaded = 0;
    if (!advance_current_nav_cmd(_nav_cmd.index + 1)) complete();
  }
}

bool AP_Mission::advance_current_nav_cmd(std::uint16_t start_index) {
  for (std::uint16_t index = start_index; index < _cmd_total; ++index) {
    const Mission_Command& cmd = _items[index];
    if (!is_nav_cmd(cmd)) {
      // "Do" commands run as the mission passes them.
      _do_cmd = cmd;
      _flags.do_cmd_loaded = 1;
      _cmd_start_fn(cmd);
      continue;
    }
    if (_flags.nav_cmd_loaded) {
      _prev_nav_cmd_id = _nav_cmd.id;
      _prev_nav_cmd_index = _nav_cmd.index;
      if (_nav_cmd.id == mav::CMD_NAV_WAYPOINT) _prev_nav_cmd_wp_index = _nav_cmd.index;
    } else if (_nav_cmd.index != AP_MISSION_CMD_INDEX_NONE && _nav_cmd.index < index) {
      _prev_nav_cmd_id = _nav_cmd.id;
      _prev_nav_cmd_index = _nav_cmd.index;
    }
    _nav_cmd = cmd;
    _flags.nav_cmd_loaded = 1;
    _last_change_time_ms = hal.millis();
    copter.gcs_send_mission_current(index);
    _cmd_start_fn(_nav_cmd);
    return true;
  }
  _flags.do_cmd_all_done = 1;
  return false;
}

void AP_Mission::complete() {
  _flags.state = MISSION_COMPLETE;
  _flags.nav_cmd_loaded = 0;
  _mission_complete_fn();
}
