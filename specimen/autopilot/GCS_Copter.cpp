#include "GCS_Copter.hpp"

#include <cstdio>
#include <cstring>

#include "Copter.hpp"
#include "messages.hpp"

namespace {
constexpr std::uint8_t kResultAccepted = 0;
constexpr std::uint8_t kResultFailed = 4;

bool send(const mav::Frame& frame) { return hal.gcs.send(frame); }
}  // namespace

void GCS_Copter::update_receive() {
  mav::Frame frame;
  while (hal.gcs.poll(frame)) {
    ++_frames_received;
    handle_message(frame);
  }
}

void GCS_Copter::handle_message(const mav::Frame& frame) {
  switch (frame.msgid) {
    case mav::HEARTBEAT:
      copter.failsafe.last_heartbeat_ms = hal.millis();
      break;
    case mav::MISSION_COUNT: handle_mission_count(frame); break;
    case mav::MISSION_ITEM_INT: handle_mission_item(frame); break;
    case mav::COMMAND_LONG: handle_command_long(frame); break;
    case mav::SET_MODE: handle_set_mode(frame); break;
    default: break;
  }
}

void GCS_Copter::handle_mission_count(const mav::Frame& frame) {
  const auto msg = mav::read_payload<mav::MissionCount>(frame);
  if (msg.count > AP_Mission::AP_MISSION_MAX_COMMANDS || !copter.mission.clear()) {
    send(mav::make_frame(mav::MISSION_ACK, mav::MissionAck{255, 0, 1}));
    return;
  }
  _receiving_mission = true;
  _upload_count = msg.count;
  _upload_next = 0;
  request_next_item();
}

void GCS_Copter::request_next_item() {
  send(mav::make_frame(mav::MISSION_REQUEST_INT, mav::MissionRequestInt{_upload_next, 255, 0}));
}

void GCS_Copter::handle_mission_item(const mav::Frame& frame) {
  const auto msg = mav::read_payload<mav::MissionItemInt>(frame);
  if (!_receiving_mission || msg.seq != _upload_next) return;
  AP_Mission::Mission_Command cmd{};
  cmd.id = msg.command;
  cmd.p1 = static_cast<std::uint16_t>(msg.param1);
  if (msg.command == mav::CMD_DO_CHANGE_SPEED) {
    cmd.content.speed.speed_type = static_cast<std::uint8_t>(msg.param1);
    cmd.content.speed.target_ms = msg.param2;
    cmd.content.speed.throttle_pct = msg.param3;
  } else {
    cmd.content.location = Location::make(msg.x, msg.y, static_cast<std::int32_t>(msg.z * 100.0f));
  }
  copter.mission.add_cmd(cmd);
  ++_upload_next;
  if (_upload_next < _upload_count) {
    request_next_item();
  } else {
    _receiving_mission = false;
    send(mav::make_frame(mav::MISSION_ACK, mav::MissionAck{255, 0, 0}));
  }
}

void GCS_Copter::handle_command_long(const mav::Frame& frame) {
  const auto msg = mav::read_payload<mav::CommandLong>(frame);
  bool ok = false;
  switch (msg.command) {
    case mav::CMD_COMPONENT_ARM_DISARM:
      if (msg.param[0] > 0.5f) {
        ok = copter.arm();
      } else {
        copter.disarm();
        ok = true;
      }
      break;
    case mav::CMD_MISSION_START:
      ok = copter.armed() && copter.set_mode(Mode::AUTO, ModeReason::GCS_COMMAND);
      break;
    case mav::CMD_NAV_LAND:
      ok = copter.set_mode(Mode::LAND, ModeReason::GCS_COMMAND);
      break;
    case mav::CMD_NAV_RETURN_TO_LAUNCH:
      ok = copter.set_mode(Mode::RTL, ModeReason::GCS_COMMAND);
      break;
    default:
      break;
  }
  send(mav::make_frame(mav::COMMAND_ACK,
                        mav::CommandAck{msg.command, ok ? kResultAccepted : kResultFailed}));
}

void GCS_Copter::handle_set_mode(const mav::Frame& frame) {
  const auto msg = mav::read_payload<mav::SetMode>(frame);
  bool ok = false;
  switch (msg.custom_mode) {
    case mav::MODE_AUTO: ok = copter.set_mode(Mode::AUTO, ModeReason::GCS_COMMAND); break;
    case mav::MODE_LOITER: ok = copter.set_mode(Mode::LOITER, ModeReason::GCS_COMMAND); break;
    case mav::MODE_RTL: ok = copter.set_mode(Mode::RTL, ModeReason::GCS_COMMAND); break;
    case mav::MODE_LAND: ok = copter.set_mode(Mode::LAND, ModeReason::GCS_COMMAND); break;
    case mav::MODE_STABILIZE: ok = copter.set_mode(Mode::STABILIZE, ModeReason::GCS_COMMAND); break;
    default: break;
  }
  send(mav::make_frame(mav::COMMAND_ACK,
                        mav::CommandAck{11, ok ? kResultAccepted : kResultFailed}));
}

void GCS_Copter::send_heartbeat() {
  mav::Heartbeat hb{};
  hb.custom_mode = static_cast<std::uint32_t>(copter.get_mode());
  hb.type = 2;        // MAV_TYPE_QUADROTOR
  hb.autopilot = 3;   // MAV_AUTOPILOT_ARDUPILOTMEGA
  hb.base_mode = copter.armed() ? mav::kBaseModeArmed : 0;
  hb.system_status = copter.armed() ? 4 : 3;  // ACTIVE : STANDBY
  hb.mavlink_version = 3;
  send(mav::make_frame(mav::HEARTBEAT, hb));
}

void GCS_Copter::send_mission_current(std::uint16_t seq) {
  send(mav::make_frame(mav::MISSION_CURRENT, mav::MissionSeq{seq}));
}

void GCS_Copter::send_mission_item_reached(std::uint16_t seq) {
  send(mav::make_frame(mav::MISSION_ITEM_REACHED, mav::MissionSeq{seq}));
}

void GCS_Copter::send_text(const char* text) {
  mav::StatusText msg{};
  msg.severity = 6;  // INFO
  std::snprintf(msg.text, sizeof(msg.text), "%s", text);
  send(mav::make_frame(mav::STATUSTEXT, msg));
}
