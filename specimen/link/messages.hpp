// Message ids and payloads. Ground-control messages follow MAVLink common.xml's ids and field
// order (ids, not wire compatibility: no CRC_EXTRA, no truncation). SIM_* messages carry the
// lock-step sensor/actuator exchange between the world and the autopilot.
#ifndef SPECIMEN_LINK_MESSAGES_HPP
#define SPECIMEN_LINK_MESSAGES_HPP

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "frame.hpp"

namespace mav {

enum MsgId : std::uint8_t {
  HEARTBEAT = 0,
  SET_MODE = 11,
  MISSION_CURRENT = 42,
  MISSION_COUNT = 44,
  MISSION_ITEM_REACHED = 46,
  MISSION_ACK = 47,
  MISSION_REQUEST_INT = 51,
  MISSION_ITEM_INT = 73,
  COMMAND_LONG = 76,
  COMMAND_ACK = 77,
  SIM_SENSORS = 150,
  SIM_MOTORS = 151,
  SIM_CHECKPOINT = 152,
  SIM_UPDATE = 153,  // world -> a live autopilot: switch to the patched build now (no payload)
  NAMED_VALUE_FLOAT = 251,
  STATUSTEXT = 253,
};

// MAV_CMD values used by missions and commands.
enum Command : std::uint16_t {
  CMD_NAV_WAYPOINT = 16,
  CMD_NAV_RETURN_TO_LAUNCH = 20,
  CMD_NAV_LAND = 21,
  CMD_NAV_TAKEOFF = 22,
  CMD_DO_CHANGE_SPEED = 178,
  CMD_MISSION_START = 300,
  CMD_COMPONENT_ARM_DISARM = 400,
};

// ArduCopter's custom_mode numbers, as a ground station sends them.
enum CustomMode : std::uint32_t {
  MODE_STABILIZE = 0,
  MODE_AUTO = 3,
  MODE_LOITER = 5,
  MODE_RTL = 6,
  MODE_LAND = 9,
  MODE_BRAKE = 17,
};

constexpr std::uint8_t kBaseModeArmed = 0x80;

#pragma pack(push, 1)
struct Heartbeat {
  std::uint32_t custom_mode;
  std::uint8_t type;
  std::uint8_t autopilot;
  std::uint8_t base_mode;
  std::uint8_t system_status;
  std::uint8_t mavlink_version;
};

struct SetMode {
  std::uint32_t custom_mode;
  std::uint8_t target_system;
  std::uint8_t base_mode;
};

struct CommandLong {
  float param[7];
  std::uint16_t command;
  std::uint8_t target_system;
  std::uint8_t target_component;
  std::uint8_t confirmation;
};

struct CommandAck {
  std::uint16_t command;
  std::uint8_t result;  // 0 = accepted, 4 = failed
};

struct MissionCount {
  std::uint16_t count;
  std::uint8_t target_system;
  std::uint8_t target_component;
};

struct MissionRequestInt {
  std::uint16_t seq;
  std::uint8_t target_system;
  std::uint8_t target_component;
};

struct MissionItemInt {
  float param1, param2, param3, param4;
  std::int32_t x;  // latitude * 1e7
  std::int32_t y;  // longitude * 1e7
  float z;         // altitude (m) in `frame`
  std::uint16_t seq;
  std::uint16_t command;
  std::uint8_t target_system;
  std::uint8_t target_component;
  std::uint8_t frame;
  std::uint8_t current;
  std::uint8_t autocontinue;
};

struct MissionAck {
  std::uint8_t target_system;
  std::uint8_t target_component;
  std::uint8_t type;  // 0 = accepted
};

struct MissionSeq {  // MISSION_CURRENT, MISSION_ITEM_REACHED
  std::uint16_t seq;
};

struct NamedValueFloat {
  std::uint32_t time_boot_ms;
  float value;
  char name[10];
};

struct StatusText {
  std::uint8_t severity;
  char text[50];
};

// World -> autopilot, once per autopilot loop. Body frame FRD, NED earth frame.
struct SimSensors {
  std::uint64_t time_us;
  float gyro[3];        // rad/s
  float accel[3];       // m/s^2, specific force
  float mag_heading;    // rad, compass heading
  float baro_alt;       // m above the home elevation
  std::int32_t gps_lat;  // 1e-7 deg
  std::int32_t gps_lng;
  float gps_alt;        // m above the home elevation
  float gps_vel[3];     // m/s NED
  std::uint8_t gps_new;  // a fresh GPS fix arrived this loop
  std::uint8_t gps_fix;  // 3 = 3D fix
};

// Autopilot -> world, once per loop: the PWM outputs, normalised to 0..1.
struct SimMotors {
  float motor[4];
};

// Autopilot -> world: what the checkpoint machinery did this loop (for the experiment).
enum CheckpointEvent : std::uint8_t {
  CKPT_SAVED = 1,
  CKPT_RESTORED = 2,
  CKPT_RESTORE_FAILED = 3,
};

struct SimCheckpoint {
  std::uint8_t event;
  std::uint32_t sequence;
  std::uint32_t micros;  // duration of the save or restore, in microseconds (x100 for 0.01)
  std::uint32_t nanos;   // the same duration in nanoseconds, saturating
  std::uint32_t bytes;   // bytes of one checkpoint
};
#pragma pack(pop)

template <class Payload>
Frame make_frame(MsgId id, const Payload& payload) {
  static_assert(std::is_trivially_copyable<Payload>::value && sizeof(Payload) <= kMaxPayload,
                "a payload is a plain struct that fits one frame");
  Frame frame;
  frame.msgid = id;
  frame.len = static_cast<std::uint8_t>(sizeof(Payload));
  std::memcpy(frame.payload, &payload, sizeof(Payload));
  return frame;
}

// Copies a frame's payload into `out`; a shorter payload is zero-extended (as MAVLink 2 does).
template <class Payload>
Payload read_payload(const Frame& frame) {
  static_assert(std::is_trivially_copyable<Payload>::value, "a payload is a plain struct");
  Payload out;
  std::memset(&out, 0, sizeof(out));
  const std::size_t n = frame.len < sizeof(Payload) ? frame.len : sizeof(Payload);
  std::memcpy(&out, frame.payload, n);
  return out;
}

}  // namespace mav

#endif  // SPECIMEN_LINK_MESSAGES_HPP
