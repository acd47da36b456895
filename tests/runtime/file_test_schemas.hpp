// Hand-written schemas for the file-layer tests, in the shape symcr-gen emits: constant
// FieldInfo/TypeInfo tables built from offsetof/sizeof over real variables.
//
// Build A and build B model a patch: B reorders Copter's fields, widens `ticks`, drops
// `armed_ms` and adds `geofence`. Telemetry is unchanged. Both name their roots "copter" and
// "telemetry", over different C++ variables, so one test binary can play both builds.
#ifndef SYMCR_TESTS_RUNTIME_FILE_TEST_SCHEMAS_HPP
#define SYMCR_TESTS_RUNTIME_FILE_TEST_SCHEMAS_HPP

#include <cstddef>
#include <cstdint>

#include "file_test_util.hpp"
#include "schema_tables.hpp"
#include "symcr/generated.hpp"

namespace file_tests {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

// ---- shared types ----------------------------------------------------------------------------
enum class FlightMode : std::int32_t { Stabilize = 0, Auto = 3, Land = 9 };

struct Waypoint {
  double lat;
  double lon;
  float alt;
  std::int16_t speed;
};

struct Mission {
  Waypoint items[4];
  std::uint8_t current;
  bool active;
};

struct Telemetry {
  std::uint32_t frames;
  std::int16_t rssi;
};

// ---- build A ---------------------------------------------------------------------------------
struct CopterA {
  std::int32_t ticks;
  FlightMode mode;
  Mission mission;
  std::uint64_t armed_ms;
  float battery;
};

inline CopterA copter_a;
inline Telemetry telemetry_a;

// ---- build B ---------------------------------------------------------------------------------
struct CopterB {
  FlightMode mode;
  std::int64_t ticks;  // widened from int32
  Mission mission;
  float battery;
  std::int32_t geofence = 77;  // added; armed_ms removed
};

inline CopterB copter_b;
inline Telemetry telemetry_b;

// ---- a state too large for a small store slot -------------------------------------------------
struct Blob {
  std::uint8_t bytes[8192];
};
inline Blob big_blob;

namespace tables {

enum : std::uint32_t {
  kBool, kInt16, kInt32, kInt64, kUInt8, kUInt32, kUInt64, kFloat32, kFloat64,
  kFlightMode, kWaypoint, kWaypoints4, kMission, kTelemetry, kCopter, kTypeCount
};

inline const symcr::EnumeratorInfo flight_modes[] = {
    {"Stabilize", 0}, {"Auto", 3}, {"Land", 9}};

inline const symcr::FieldInfo waypoint_fields[] = {
    field("lat", kFloat64, offsetof(Waypoint, lat)),
    field("lon", kFloat64, offsetof(Waypoint, lon)),
    field("alt", kFloat32, offsetof(Waypoint, alt)),
    field("speed", kInt16, offsetof(Waypoint, speed)),
};
inline const symcr::FieldInfo mission_fields[] = {
    field("items", kWaypoints4, offsetof(Mission, items)),
    field("current", kUInt8, offsetof(Mission, current)),
    field("active", kBool, offsetof(Mission, active)),
};
inline const symcr::FieldInfo telemetry_fields[] = {
    field("frames", kUInt32, offsetof(Telemetry, frames)),
    field("rssi", kInt16, offsetof(Telemetry, rssi)),
};
inline const symcr::FieldInfo copter_a_fields[] = {
    field("ticks", kInt32, offsetof(CopterA, ticks)),
    field("mode", kFlightMode, offsetof(CopterA, mode)),
    field("mission", kMission, offsetof(CopterA, mission)),
    field("armed_ms", kUInt64, offsetof(CopterA, armed_ms)),
    field("battery", kFloat32, offsetof(CopterA, battery)),
};
inline const symcr::FieldInfo copter_b_fields[] = {
    field("mode", kFlightMode, offsetof(CopterB, mode)),
    field("ticks", kInt64, offsetof(CopterB, ticks)),
    field("mission", kMission, offsetof(CopterB, mission)),
    field("battery", kFloat32, offsetof(CopterB, battery)),
    field("geofence", kInt32, offsetof(CopterB, geofence)),
};

#define FILE_TESTS_COMMON_TYPES                                                             \
  scalar("bool", symcr::Kind::Bool, 1), scalar("int16", symcr::Kind::Int, 2),     \
      scalar("int32", symcr::Kind::Int, 4), scalar("int64", symcr::Kind::Int, 8), \
      scalar("uint8", symcr::Kind::UInt, 1), scalar("uint32", symcr::Kind::UInt, 4), \
      scalar("uint64", symcr::Kind::UInt, 8),                                          \
      scalar("float32", symcr::Kind::Float, 4),                                        \
      scalar("float64", symcr::Kind::Float, 8),                                        \
      enumeration("file_tests::FlightMode", sizeof(FlightMode), kInt32, flight_modes, 3),     \
      record("file_tests::Waypoint", sizeof(Waypoint), alignof(Waypoint),              \
                  waypoint_fields, 4),                                                      \
      array("file_tests::Waypoint[4]", kWaypoint, 4, sizeof(Waypoint[4]),              \
                 alignof(Waypoint)),                                                        \
      record("file_tests::Mission", sizeof(Mission), alignof(Mission), mission_fields, 3), \
      record("file_tests::Telemetry", sizeof(Telemetry), alignof(Telemetry),           \
                  telemetry_fields, 2)

inline const symcr::TypeInfo types_a[] = {
    FILE_TESTS_COMMON_TYPES,
    record("file_tests::Copter", sizeof(CopterA), alignof(CopterA), copter_a_fields, 5),
};
inline const symcr::TypeInfo types_b[] = {
    FILE_TESTS_COMMON_TYPES,
    record("file_tests::Copter", sizeof(CopterB), alignof(CopterB), copter_b_fields, 5),
};
#undef FILE_TESTS_COMMON_TYPES
static_assert(sizeof(types_a) / sizeof(types_a[0]) == kTypeCount, "one entry per index");

inline const symcr::RootInfo roots_a[] = {
    {"copter", kCopter, &copter_a, 0, nullptr},
    {"telemetry", kTelemetry, &telemetry_a, 0, nullptr},
};
inline const symcr::RootInfo roots_b[] = {
    {"copter", kCopter, &copter_b, 0, nullptr},
    {"telemetry", kTelemetry, &telemetry_b, 0, nullptr},
};

inline const symcr::TypeInfo blob_types[] = {
    scalar("uint8", symcr::Kind::UInt, 1),
    array("uint8[8192]", 0, sizeof(Blob::bytes), sizeof(Blob::bytes), 1),
};
inline const symcr::RootInfo blob_roots[] = {{"blob", 1, &big_blob, 0, nullptr}};

}  // namespace tables

inline const symcr::Schema schema_a{tables::types_a, tables::kTypeCount, tables::roots_a, 2, nullptr};
inline const symcr::Schema schema_b{tables::types_b, tables::kTypeCount, tables::roots_b, 2, nullptr};
inline const symcr::Schema blob_schema{tables::blob_types, 2, tables::blob_roots, 1, nullptr};

// Byte offset of copter.mission.active in build A's payload (docs/format.md §3: values in
// schema order at their wire widths): ticks 4 + mode 4 + items 4 × (8 + 8 + 4 + 2) + current 1.
inline constexpr std::size_t kPayloadOffsetOfActiveA = 4 + 4 + 4 * 22 + 1;

// Distinct, checkable contents per `seed`.
inline void fill_a(int seed) {
  copter_a = CopterA{};
  copter_a.ticks = 1000 + seed;
  copter_a.mode = seed % 2 ? FlightMode::Auto : FlightMode::Land;
  for (int i = 0; i < 4; ++i) {
    copter_a.mission.items[i] = Waypoint{42.0 + seed + i * 0.25, -83.5 - i, 100.0f + i,
                                         static_cast<std::int16_t>(seed * 10 + i)};
  }
  copter_a.mission.current = static_cast<std::uint8_t>(seed % 4);
  copter_a.mission.active = true;
  copter_a.armed_ms = 5000000000ull + static_cast<std::uint64_t>(seed);
  copter_a.battery = 15.5f - static_cast<float>(seed) * 0.125f;
  telemetry_a = Telemetry{static_cast<std::uint32_t>(7 * seed), static_cast<std::int16_t>(-seed)};
}

inline void scramble_a() {
  copter_a = CopterA{};
  copter_a.ticks = -1;
  copter_a.mode = FlightMode::Stabilize;
  telemetry_a = Telemetry{0xFFFFFFFFu, 1};
}

// Build A's state holds what fill_a(seed) put there, every value.
inline void expect_a(int seed) {
  EXPECT_EQ(copter_a.ticks, 1000 + seed);
  EXPECT_EQ(copter_a.mode, seed % 2 ? FlightMode::Auto : FlightMode::Land);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(copter_a.mission.items[i].lat, 42.0 + seed + i * 0.25);
    EXPECT_EQ(copter_a.mission.items[i].lon, -83.5 - i);
    EXPECT_EQ(copter_a.mission.items[i].alt, 100.0f + i);
    EXPECT_EQ(copter_a.mission.items[i].speed, seed * 10 + i);
  }
  EXPECT_EQ(copter_a.mission.current, seed % 4);
  EXPECT_TRUE(copter_a.mission.active);
  EXPECT_EQ(copter_a.armed_ms, 5000000000ull + static_cast<std::uint64_t>(seed));
  EXPECT_EQ(copter_a.battery, 15.5f - static_cast<float>(seed) * 0.125f);
  EXPECT_EQ(telemetry_a.frames, static_cast<std::uint32_t>(7 * seed));
  EXPECT_EQ(telemetry_a.rssi, -seed);
}

// A build's roots, byte for byte: what a refused restore or transfer must leave as it was.
inline std::vector<std::uint8_t> state_a() {
  std::vector<std::uint8_t> bytes = snapshot(copter_a);
  const std::vector<std::uint8_t> telemetry = snapshot(telemetry_a);
  bytes.insert(bytes.end(), telemetry.begin(), telemetry.end());
  return bytes;
}
inline std::vector<std::uint8_t> state_b() {
  std::vector<std::uint8_t> bytes = snapshot(copter_b);
  const std::vector<std::uint8_t> telemetry = snapshot(telemetry_b);
  bytes.insert(bytes.end(), telemetry.begin(), telemetry.end());
  return bytes;
}

}  // namespace file_tests

#endif  // SYMCR_TESTS_RUNTIME_FILE_TEST_SCHEMAS_HPP
