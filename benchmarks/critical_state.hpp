// The specimen-sized critical state shared by the benchmarks (benchmarks/README.md): about 300 bytes
// of values in about 100 fields of nested structs, arrays (one two-dimensional) and enums, in
// the shape of ArduPilot's Copter / AP_AHRS / AP_Mission, described by a hand-written schema in
// the form symcr-gen emits (see tests/runtime/handwritten_schemas.hpp).
//
// Two builds of it: `critical` (V0, the writer) and `critical::v1` (a patched build, the reader
// of the schema-change benchmarks) whose structs really differ: fields moved, renamed, retyped,
// added and removed, an enum renumbered and widened, an array lengthened.
//
// Used until the specimen is wired to symcr; then the specimen's own generated schema is the
// thing to measure (benchmarks/run picks up its code size automatically).
#ifndef SYMCR_BENCHMARKS_CRITICAL_STATE_HPP
#define SYMCR_BENCHMARKS_CRITICAL_STATE_HPP

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "schema_tables.hpp"
#include "symcr/generated.hpp"

namespace critical {

// ---- the state ---------------------------------------------------------------------------------
enum class FlightMode : std::uint8_t { Stabilize, AltHold, Loiter, Auto, Rtl, Land };
enum class MissionState : std::uint8_t { Idle, Running, Paused, Complete };

struct Vec3 {
  float x, y, z;
};

struct Ahrs {          // 16 values, 64 bytes
  Vec3 position;
  Vec3 velocity;
  Vec3 euler;
  Vec3 gyro_bias;
  float quaternion[4];
};

struct Waypoint {      // 5 values, 15 bytes on the wire
  std::int32_t lat;
  std::int32_t lon;
  float alt;
  std::uint16_t command;
  std::uint8_t flags;
};

struct Mission {       // 43 values, 125 bytes
  Waypoint items[8];
  std::uint16_t current;
  std::uint16_t count;
  MissionState state;
};

struct Copter {        // 26 values, 84 bytes
  FlightMode mode;
  bool armed;
  std::uint32_t ticks;
  std::int16_t throttle;
  float pid_gains[3][3];
  std::uint8_t failsafe_flags[8];
  double home_lat;
  double home_lon;
  std::uint64_t armed_ms;
  std::int32_t battery_mah;
  float battery_volts;
};

struct Telemetry {     // 11 values, 28 bytes
  std::uint32_t frames;
  std::uint16_t drops;
  std::int8_t rssi;
  std::uint8_t link_quality;
  float rates[4];
  std::uint16_t sequence;
  std::uint8_t system_id;
  std::uint8_t component_id;
};

inline Copter copter;
inline Ahrs ahrs;
inline Mission mission;
inline Telemetry telemetry;

// ---- its schema --------------------------------------------------------------------------------
using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

enum : std::uint32_t {
  kBool, kInt8, kInt16, kInt32, kUInt8, kUInt16, kUInt32, kUInt64, kFloat32, kFloat64,
  kFlightMode, kMissionState, kVec3, kFloat4, kFloat3, kFloat3x3, kUInt8x8, kWaypoint,
  kWaypoint8, kAhrs, kMission, kCopter, kTelemetry, kTypeCount
};

inline const symcr::EnumeratorInfo flight_modes[] = {{"Stabilize", 0}, {"AltHold", 1}, {"Loiter", 2},
                                              {"Auto", 3},      {"Rtl", 4},     {"Land", 5}};
inline const symcr::EnumeratorInfo mission_states[] = {
    {"Idle", 0}, {"Running", 1}, {"Paused", 2}, {"Complete", 3}};

inline const symcr::FieldInfo vec3_fields[] = {
    field("x", kFloat32, offsetof(Vec3, x)),
    field("y", kFloat32, offsetof(Vec3, y)),
    field("z", kFloat32, offsetof(Vec3, z)),
};
inline const symcr::FieldInfo ahrs_fields[] = {
    field("position", kVec3, offsetof(Ahrs, position)),
    field("velocity", kVec3, offsetof(Ahrs, velocity)),
    field("euler", kVec3, offsetof(Ahrs, euler)),
    field("gyro_bias", kVec3, offsetof(Ahrs, gyro_bias)),
    field("quaternion", kFloat4, offsetof(Ahrs, quaternion)),
};
inline const symcr::FieldInfo waypoint_fields[] = {
    field("lat", kInt32, offsetof(Waypoint, lat)),
    field("lon", kInt32, offsetof(Waypoint, lon)),
    field("alt", kFloat32, offsetof(Waypoint, alt)),
    field("command", kUInt16, offsetof(Waypoint, command)),
    field("flags", kUInt8, offsetof(Waypoint, flags)),
};
inline const symcr::FieldInfo mission_fields[] = {
    field("items", kWaypoint8, offsetof(Mission, items)),
    field("current", kUInt16, offsetof(Mission, current)),
    field("count", kUInt16, offsetof(Mission, count)),
    field("state", kMissionState, offsetof(Mission, state)),
};
inline const symcr::FieldInfo copter_fields[] = {
    field("mode", kFlightMode, offsetof(Copter, mode)),
    field("armed", kBool, offsetof(Copter, armed)),
    field("ticks", kUInt32, offsetof(Copter, ticks)),
    field("throttle", kInt16, offsetof(Copter, throttle)),
    field("pid_gains", kFloat3x3, offsetof(Copter, pid_gains)),
    field("failsafe_flags", kUInt8x8, offsetof(Copter, failsafe_flags)),
    field("home_lat", kFloat64, offsetof(Copter, home_lat)),
    field("home_lon", kFloat64, offsetof(Copter, home_lon)),
    field("armed_ms", kUInt64, offsetof(Copter, armed_ms)),
    field("battery_mah", kInt32, offsetof(Copter, battery_mah)),
    field("battery_volts", kFloat32, offsetof(Copter, battery_volts)),
};
inline const symcr::FieldInfo telemetry_fields[] = {
    field("frames", kUInt32, offsetof(Telemetry, frames)),
    field("drops", kUInt16, offsetof(Telemetry, drops)),
    field("rssi", kInt8, offsetof(Telemetry, rssi)),
    field("link_quality", kUInt8, offsetof(Telemetry, link_quality)),
    field("rates", kFloat4, offsetof(Telemetry, rates)),
    field("sequence", kUInt16, offsetof(Telemetry, sequence)),
    field("system_id", kUInt8, offsetof(Telemetry, system_id)),
    field("component_id", kUInt8, offsetof(Telemetry, component_id)),
};

inline const symcr::TypeInfo types[] = {
    scalar("bool", symcr::Kind::Bool, 1),
    scalar("int8", symcr::Kind::Int, 1),
    scalar("int16", symcr::Kind::Int, 2),
    scalar("int32", symcr::Kind::Int, 4),
    scalar("uint8", symcr::Kind::UInt, 1),
    scalar("uint16", symcr::Kind::UInt, 2),
    scalar("uint32", symcr::Kind::UInt, 4),
    scalar("uint64", symcr::Kind::UInt, 8),
    scalar("float32", symcr::Kind::Float, 4),
    scalar("float64", symcr::Kind::Float, 8),
    enumeration("FlightMode", 1, kUInt8, flight_modes, 6),
    enumeration("MissionState", 1, kUInt8, mission_states, 4),
    record("Vec3", sizeof(Vec3), alignof(Vec3), vec3_fields, 3),
    array("float32[4]", kFloat32, 4, sizeof(float[4]), alignof(float)),
    array("float32[3]", kFloat32, 3, sizeof(float[3]), alignof(float)),
    array("float32[3][3]", kFloat3, 3, sizeof(float[3][3]), alignof(float)),
    array("uint8[8]", kUInt8, 8, 8, 1),
    record("Waypoint", sizeof(Waypoint), alignof(Waypoint), waypoint_fields, 5),
    array("Waypoint[8]", kWaypoint, 8, sizeof(Waypoint[8]), alignof(Waypoint)),
    record("Ahrs", sizeof(Ahrs), alignof(Ahrs), ahrs_fields, 5),
    record("Mission", sizeof(Mission), alignof(Mission), mission_fields, 4),
    record("Copter", sizeof(Copter), alignof(Copter), copter_fields, 11),
    record("Telemetry", sizeof(Telemetry), alignof(Telemetry), telemetry_fields, 8),
};
static_assert(sizeof(types) / sizeof(types[0]) == kTypeCount, "one entry per index");

inline const symcr::RootInfo roots[] = {
    {"copter", kCopter, &copter, 0, nullptr},
    {"ahrs", kAhrs, &ahrs, 0, nullptr},
    {"mission", kMission, &mission, 0, nullptr},
    {"telemetry", kTelemetry, &telemetry, 0, nullptr},
};
inline const symcr::Schema schema{types, kTypeCount, roots, 4, nullptr};

// Wire bytes of the state's values, without padding (docs/format.md §3): what a raw write of
// the same information costs.
constexpr std::size_t kValueBytes = 84 + 64 + 125 + 28;

inline void fill_state(std::uint32_t tick) {
  copter.mode = FlightMode::Auto;
  copter.armed = true;
  copter.ticks = tick;
  copter.throttle = 1500;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) copter.pid_gains[i][j] = 0.1f * static_cast<float>(i + j);
  for (int i = 0; i < 8; ++i) copter.failsafe_flags[i] = static_cast<std::uint8_t>(i & 1);
  copter.home_lat = 42.2808;
  copter.home_lon = -83.7430;
  copter.armed_ms = 123456789;
  copter.battery_mah = 5200;
  copter.battery_volts = 15.4f;
  ahrs.position = {1.0f, 2.0f, static_cast<float>(tick)};
  ahrs.velocity = {0.5f, -0.5f, 0.0f};
  ahrs.euler = {0.01f, 0.02f, 1.57f};
  ahrs.gyro_bias = {0.001f, 0.002f, 0.003f};
  for (int i = 0; i < 4; ++i) ahrs.quaternion[i] = 0.5f;
  for (int i = 0; i < 8; ++i) {
    mission.items[i] = Waypoint{422808000 + i * 1000, -837430000 - i * 1000,
                                30.0f + static_cast<float>(i), 16, 1};
  }
  mission.current = 3;
  mission.count = 8;
  mission.state = MissionState::Running;
  telemetry = Telemetry{tick, 2, -60, 98, {1, 2, 3, 4}, 77, 1, 1};
}


// A scratch file name under $TMPDIR (else /tmp), unique per process.
inline std::string scratch_path(const char* name) {
  const char* base = std::getenv("TMPDIR");
  return std::string(base && *base ? base : "/tmp") + "/symcr-bench-" +
         std::to_string(::getpid()) + "-" + name;
}

// ---- V1: the patched build ---------------------------------------------------------------------
// Against V0: FlightMode renumbered, widened to int32 and given a new enumerator; Ahrs.euler
// renamed `attitude` and a field added; Waypoint reordered with alt float -> double; Mission
// reordered with 12 items instead of 8; Copter reordered, throttle renamed `throttle_out` and
// widened int16 -> int32, battery_volts float -> double, a field added; Telemetry lost `drops`
// and rssi became int16.
namespace v1 {

enum class FlightMode : std::int32_t { Land = 0, Stabilize = 1, AltHold = 2, Loiter = 3,
                                       Auto = 4, Rtl = 5, Guided = 6 };
enum class MissionState : std::uint8_t { Idle, Running, Paused, Complete };

struct Vec3 {
  float x, y, z;
};

struct Ahrs {
  Vec3 position;
  Vec3 attitude;  // was `euler`
  Vec3 velocity;
  Vec3 gyro_bias;
  float quaternion[4];
  float accel_bias[3];  // added
};

struct Waypoint {
  std::int32_t lon;
  std::int32_t lat;
  double alt;  // was float
  std::uint8_t flags;
  std::uint16_t command;
};

struct Mission {
  MissionState state;
  std::uint16_t count;
  std::uint16_t current;
  Waypoint items[12];  // was 8
};

struct Copter {
  bool armed;
  FlightMode mode;
  std::int32_t throttle_out;  // was int16 `throttle`
  std::uint32_t ticks;
  double battery_volts;  // was float
  std::int32_t battery_mah;
  float pid_gains[3][3];
  std::uint8_t failsafe_flags[8];
  double home_lat;
  double home_lon;
  std::uint64_t armed_ms;
  std::uint32_t land_timeout_ms;  // added
};

struct Telemetry {
  std::uint32_t frames;
  std::int16_t rssi;  // was int8; `drops` removed
  std::uint8_t link_quality;
  float rates[4];
  std::uint16_t sequence;
  std::uint8_t system_id;
  std::uint8_t component_id;
};

inline Copter copter;
inline Ahrs ahrs;
inline Mission mission;
inline Telemetry telemetry;

enum : std::uint32_t {
  kBool, kInt8, kInt16, kInt32, kUInt8, kUInt16, kUInt32, kUInt64, kFloat32, kFloat64,
  kFlightMode, kMissionState, kVec3, kFloat4, kFloat3, kFloat3x3, kUInt8x8, kWaypoint,
  kWaypoint12, kAhrs, kMission, kCopter, kTelemetry, kTypeCount
};

inline const symcr::EnumeratorInfo flight_modes[] = {
    {"Land", 0}, {"Stabilize", 1}, {"AltHold", 2}, {"Loiter", 3},
    {"Auto", 4}, {"Rtl", 5},       {"Guided", 6}};
inline const symcr::EnumeratorInfo mission_states[] = {
    {"Idle", 0}, {"Running", 1}, {"Paused", 2}, {"Complete", 3}};
inline const char* const euler_names[] = {"euler", nullptr};
inline const char* const throttle_names[] = {"throttle", nullptr};

inline const symcr::FieldInfo vec3_fields[] = {
    field("x", kFloat32, offsetof(Vec3, x)),
    field("y", kFloat32, offsetof(Vec3, y)),
    field("z", kFloat32, offsetof(Vec3, z)),
};
inline const symcr::FieldInfo ahrs_fields[] = {
    field("position", kVec3, offsetof(Ahrs, position)),
    field("attitude", kVec3, offsetof(Ahrs, attitude), euler_names),
    field("velocity", kVec3, offsetof(Ahrs, velocity)),
    field("gyro_bias", kVec3, offsetof(Ahrs, gyro_bias)),
    field("quaternion", kFloat4, offsetof(Ahrs, quaternion)),
    field("accel_bias", kFloat3, offsetof(Ahrs, accel_bias)),
};
inline const symcr::FieldInfo waypoint_fields[] = {
    field("lon", kInt32, offsetof(Waypoint, lon)),
    field("lat", kInt32, offsetof(Waypoint, lat)),
    field("alt", kFloat64, offsetof(Waypoint, alt)),
    field("flags", kUInt8, offsetof(Waypoint, flags)),
    field("command", kUInt16, offsetof(Waypoint, command)),
};
inline const symcr::FieldInfo mission_fields[] = {
    field("state", kMissionState, offsetof(Mission, state)),
    field("count", kUInt16, offsetof(Mission, count)),
    field("current", kUInt16, offsetof(Mission, current)),
    field("items", kWaypoint12, offsetof(Mission, items)),
};
inline const symcr::FieldInfo copter_fields[] = {
    field("armed", kBool, offsetof(Copter, armed)),
    field("mode", kFlightMode, offsetof(Copter, mode)),
    field("throttle_out", kInt32, offsetof(Copter, throttle_out), throttle_names),
    field("ticks", kUInt32, offsetof(Copter, ticks)),
    field("battery_volts", kFloat64, offsetof(Copter, battery_volts)),
    field("battery_mah", kInt32, offsetof(Copter, battery_mah)),
    field("pid_gains", kFloat3x3, offsetof(Copter, pid_gains)),
    field("failsafe_flags", kUInt8x8, offsetof(Copter, failsafe_flags)),
    field("home_lat", kFloat64, offsetof(Copter, home_lat)),
    field("home_lon", kFloat64, offsetof(Copter, home_lon)),
    field("armed_ms", kUInt64, offsetof(Copter, armed_ms)),
    field("land_timeout_ms", kUInt32, offsetof(Copter, land_timeout_ms)),
};
inline const symcr::FieldInfo telemetry_fields[] = {
    field("frames", kUInt32, offsetof(Telemetry, frames)),
    field("rssi", kInt16, offsetof(Telemetry, rssi)),
    field("link_quality", kUInt8, offsetof(Telemetry, link_quality)),
    field("rates", kFloat4, offsetof(Telemetry, rates)),
    field("sequence", kUInt16, offsetof(Telemetry, sequence)),
    field("system_id", kUInt8, offsetof(Telemetry, system_id)),
    field("component_id", kUInt8, offsetof(Telemetry, component_id)),
};

inline const symcr::TypeInfo types[] = {
    scalar("bool", symcr::Kind::Bool, 1),
    scalar("int8", symcr::Kind::Int, 1),
    scalar("int16", symcr::Kind::Int, 2),
    scalar("int32", symcr::Kind::Int, 4),
    scalar("uint8", symcr::Kind::UInt, 1),
    scalar("uint16", symcr::Kind::UInt, 2),
    scalar("uint32", symcr::Kind::UInt, 4),
    scalar("uint64", symcr::Kind::UInt, 8),
    scalar("float32", symcr::Kind::Float, 4),
    scalar("float64", symcr::Kind::Float, 8),
    enumeration("FlightMode", 4, kInt32, flight_modes, 7),
    enumeration("MissionState", 1, kUInt8, mission_states, 4),
    record("Vec3", sizeof(Vec3), alignof(Vec3), vec3_fields, 3),
    array("float32[4]", kFloat32, 4, sizeof(float[4]), alignof(float)),
    array("float32[3]", kFloat32, 3, sizeof(float[3]), alignof(float)),
    array("float32[3][3]", kFloat3, 3, sizeof(float[3][3]), alignof(float)),
    array("uint8[8]", kUInt8, 8, 8, 1),
    record("Waypoint", sizeof(Waypoint), alignof(Waypoint), waypoint_fields, 5),
    array("Waypoint[12]", kWaypoint, 12, sizeof(Waypoint[12]), alignof(Waypoint)),
    record("Ahrs", sizeof(Ahrs), alignof(Ahrs), ahrs_fields, 6),
    record("Mission", sizeof(Mission), alignof(Mission), mission_fields, 4),
    record("Copter", sizeof(Copter), alignof(Copter), copter_fields, 12),
    record("Telemetry", sizeof(Telemetry), alignof(Telemetry), telemetry_fields, 7),
};
static_assert(sizeof(types) / sizeof(types[0]) == kTypeCount, "one entry per index");

inline const symcr::RootInfo roots[] = {
    {"copter", kCopter, &copter, 0, nullptr},
    {"ahrs", kAhrs, &ahrs, 0, nullptr},
    {"mission", kMission, &mission, 0, nullptr},
    {"telemetry", kTelemetry, &telemetry, 0, nullptr},
};
inline const symcr::Schema schema{types, kTypeCount, roots, 4, nullptr};

}  // namespace v1
}  // namespace critical

#endif  // SYMCR_BENCHMARKS_CRITICAL_STATE_HPP
