// Build v0 of the CLI fixture program: a copter with a mission, a string, a vector and an
// interior pointer, plus telemetry.
#include <string>
#include <vector>

#include "fixture_tables.hpp"

namespace cli_fixture {
namespace {

enum class FlightMode : std::uint8_t { STABILIZE = 0, AUTO = 3, LAND = 9 };
struct Waypoint {
  double lat;
  double lon;
  float alt;
};
struct Mission {
  Waypoint items[4];
  std::uint8_t current;
  std::string name;
  std::vector<std::int32_t> log;
};
struct Copter {
  std::int32_t ticks;
  FlightMode mode;
  Mission mission;
  std::uint64_t armed_ms;
  float battery;
  Waypoint home;
  Waypoint* target;
};
struct Telemetry {
  std::uint32_t frames;
  std::int16_t rssi;
};

Copter copter;
Telemetry telemetry;

enum : std::uint32_t {
  kBool, kInt8, kInt16, kInt32, kUInt8, kUInt32, kUInt64, kFloat32, kFloat64, kFlightMode,
  kWaypoint, kWaypoints, kString, kLog, kWaypointPtr, kMission, kCopter, kTelemetry, kTypeCount
};

const symcr::EnumeratorInfo flight_modes[] = {{"STABILIZE", 0}, {"AUTO", 3}, {"LAND", 9}};
const symcr::FieldInfo waypoint_fields[] = {
    field("lat", kFloat64, offsetof(Waypoint, lat)),
    field("lon", kFloat64, offsetof(Waypoint, lon)),
    field("alt", kFloat32, offsetof(Waypoint, alt)),
};
const symcr::FieldInfo mission_fields[] = {
    field("items", kWaypoints, offsetof(Mission, items)),
    field("current", kUInt8, offsetof(Mission, current)),
    field("name", kString, offsetof(Mission, name)),
    field("log", kLog, offsetof(Mission, log)),
};
const symcr::FieldInfo copter_fields[] = {
    field("ticks", kInt32, offsetof(Copter, ticks)),
    field("mode", kFlightMode, offsetof(Copter, mode)),
    field("mission", kMission, offsetof(Copter, mission)),
    field("armed_ms", kUInt64, offsetof(Copter, armed_ms)),
    field("battery", kFloat32, offsetof(Copter, battery)),
    field("home", kWaypoint, offsetof(Copter, home)),
    field("target", kWaypointPtr, offsetof(Copter, target)),
};
const symcr::FieldInfo telemetry_fields[] = {
    field("frames", kUInt32, offsetof(Telemetry, frames)),
    field("rssi", kInt16, offsetof(Telemetry, rssi)),
};

const symcr::TypeInfo types[] = {
    scalar("bool", Kind::Bool, 1),
    scalar("int8", Kind::Int, 1),
    scalar("int16", Kind::Int, 2),
    scalar("int32", Kind::Int, 4),
    scalar("uint8", Kind::UInt, 1),
    scalar("uint32", Kind::UInt, 4),
    scalar("uint64", Kind::UInt, 8),
    scalar("float32", Kind::Float, 4),
    scalar("float64", Kind::Float, 8),
    enumeration("FlightMode", sizeof(FlightMode), kUInt8, flight_modes, 3),
    record("Waypoint", sizeof(Waypoint), alignof(Waypoint), waypoint_fields, 3),
    array("Waypoint[4]", kWaypoint, 4, sizeof(Waypoint[4]), alignof(Waypoint)),
    holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), kInt8,
           &symcr::ops::string<std::string>::table),
    holder("std::vector<int32>", Kind::Container, sizeof(std::vector<std::int32_t>),
           alignof(std::vector<std::int32_t>), kInt32,
           &symcr::ops::container<std::vector<std::int32_t>>::table, symcr::ContainerKind::Vector),
    holder("Waypoint*", Kind::Pointer, sizeof(Waypoint*), alignof(Waypoint*), kWaypoint, nullptr),
    record("Mission", sizeof(Mission), alignof(Mission), mission_fields, 4),
    record("Copter", sizeof(Copter), alignof(Copter), copter_fields, 7),
    record("Telemetry", sizeof(Telemetry), alignof(Telemetry), telemetry_fields, 2),
};
static_assert(sizeof(types) / sizeof(types[0]) == kTypeCount, "one entry per index");

const symcr::RootInfo roots[] = {
    {"copter", kCopter, &copter, 0, nullptr},
    {"telemetry", kTelemetry, &telemetry, 0, nullptr},
};
const symcr::Schema v0_schema{types, kTypeCount, roots, 2, nullptr};

}  // namespace

const symcr::Schema& schema() { return v0_schema; }

void fill_state(int seed) {
  copter.ticks = 1000 + seed;
  copter.mode = seed % 2 ? FlightMode::AUTO : FlightMode::LAND;
  for (int i = 0; i < 4; ++i) {
    copter.mission.items[i] = Waypoint{42.25 + i * 0.01, -83.75 + seed, 100.0f + 0.5f * i};
  }
  copter.mission.current = static_cast<std::uint8_t>(seed % 4);
  copter.mission.name = "ISTAR";
  copter.mission.log = {7, 8, seed};
  copter.armed_ms = 5000000000ull + static_cast<std::uint64_t>(seed);
  copter.battery = 15.5f;
  copter.home = Waypoint{42.28, -83.74, 0.0f};
  copter.target = &copter.mission.items[2];
  // From seed 10 on, a signal too weak for v1's int8 rssi: rejected value by value.
  telemetry = Telemetry{static_cast<std::uint32_t>(7 * seed),
                        static_cast<std::int16_t>(-70 - 20 * (seed / 10) * 10)};
}

}  // namespace cli_fixture
