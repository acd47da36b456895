// Build v1 of the CLI fixture program, a patch of v0: ticks widened, the enum renumbered and
// extended, armed_ms removed, geofence added, battery made double, the mission shortened to
// three waypoints, `current` renamed, rssi narrowed. Built with FIXTURE_KIND_CHANGE, `home`
// also changes from a struct to an int (a change no rule can restore).
#include <string>
#include <vector>

#include "fixture_tables.hpp"

namespace cli_fixture {
namespace {

enum class FlightMode : std::int32_t { STABILIZE = 0, AUTO = 5, RTL = 6, LAND = 9 };
struct Waypoint {
  double lat;
  double lon;
  float alt;
};
struct Mission {
  Waypoint items[3];
  std::uint8_t active_index;  // SYMCR_RENAMED_FROM("current")
  std::string name;
  std::vector<std::int32_t> log;
};
struct Copter {
  FlightMode mode;
  std::int64_t ticks;
  Mission mission;
  double battery;
  std::int32_t geofence = 150;
#ifdef FIXTURE_KIND_CHANGE
  std::int32_t home;
#else
  Waypoint home;
#endif
  Waypoint* target;
};
struct Telemetry {
  std::uint32_t frames;
  std::int8_t rssi;
};

Copter copter;
Telemetry telemetry;

enum : std::uint32_t {
  kBool, kInt8, kInt32, kInt64, kUInt8, kUInt32, kFloat32, kFloat64, kFlightMode,
  kWaypoint, kWaypoints, kString, kLog, kWaypointPtr, kMission, kCopter, kTelemetry, kTypeCount
};

const symcr::EnumeratorInfo flight_modes[] = {
    {"STABILIZE", 0}, {"AUTO", 5}, {"RTL", 6}, {"LAND", 9}};
const char* const current_old_names[] = {"current", nullptr};
const symcr::FieldInfo waypoint_fields[] = {
    field("lat", kFloat64, offsetof(Waypoint, lat)),
    field("lon", kFloat64, offsetof(Waypoint, lon)),
    field("alt", kFloat32, offsetof(Waypoint, alt)),
};
const symcr::FieldInfo mission_fields[] = {
    field("items", kWaypoints, offsetof(Mission, items)),
    field("active_index", kUInt8, offsetof(Mission, active_index), current_old_names),
    field("name", kString, offsetof(Mission, name)),
    field("log", kLog, offsetof(Mission, log)),
};
const symcr::FieldInfo copter_fields[] = {
    field("mode", kFlightMode, offsetof(Copter, mode)),
    field("ticks", kInt64, offsetof(Copter, ticks)),
    field("mission", kMission, offsetof(Copter, mission)),
    field("battery", kFloat64, offsetof(Copter, battery)),
    field("geofence", kInt32, offsetof(Copter, geofence)),
#ifdef FIXTURE_KIND_CHANGE
    field("home", kInt32, offsetof(Copter, home)),
#else
    field("home", kWaypoint, offsetof(Copter, home)),
#endif
    field("target", kWaypointPtr, offsetof(Copter, target)),
};
const symcr::FieldInfo telemetry_fields[] = {
    field("frames", kUInt32, offsetof(Telemetry, frames)),
    field("rssi", kInt8, offsetof(Telemetry, rssi)),
};

const symcr::TypeInfo types[] = {
    scalar("bool", Kind::Bool, 1),
    scalar("int8", Kind::Int, 1),
    scalar("int32", Kind::Int, 4),
    scalar("int64", Kind::Int, 8),
    scalar("uint8", Kind::UInt, 1),
    scalar("uint32", Kind::UInt, 4),
    scalar("float32", Kind::Float, 4),
    scalar("float64", Kind::Float, 8),
    enumeration("FlightMode", sizeof(FlightMode), kInt32, flight_modes, 4),
    record("Waypoint", sizeof(Waypoint), alignof(Waypoint), waypoint_fields, 3),
    array("Waypoint[3]", kWaypoint, 3, sizeof(Waypoint[3]), alignof(Waypoint)),
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
const symcr::Schema v1_schema{types, kTypeCount, roots, 2, nullptr};

}  // namespace

const symcr::Schema& schema() { return v1_schema; }

void fill_state(int seed) {
  copter.mode = seed % 2 ? FlightMode::AUTO : FlightMode::RTL;
  copter.ticks = 2000 + seed;
  for (int i = 0; i < 3; ++i) {
    copter.mission.items[i] = Waypoint{42.25 + i * 0.01, -83.75 + seed, 100.0f + 0.5f * i};
  }
  copter.mission.active_index = static_cast<std::uint8_t>(seed % 3);
  copter.mission.name = "ISTAR";
  copter.mission.log = {7, 8, seed};
  copter.battery = 15.5;
#ifdef FIXTURE_KIND_CHANGE
  copter.home = 0;
#else
  copter.home = Waypoint{42.28, -83.74, 0.0f};
#endif
  copter.target = &copter.mission.items[1];
  telemetry = Telemetry{static_cast<std::uint32_t>(7 * seed), -70};
}

}  // namespace cli_fixture
