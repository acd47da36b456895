// The device profile's test state, shared by the host tests (device_test.cpp) and the program
// run on a Cortex-M4 under qemu (cortex_m4/): one of every kind the profile holds, with its
// tables written as symcr-gen writes them.
#ifndef SYMCR_TESTS_DEVICE_VEHICLE_HPP
#define SYMCR_TESTS_DEVICE_VEHICLE_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "schema_tables.hpp"

namespace device_tests {

using namespace schema_tables;
using symcr::Kind;

enum class Mode : std::uint8_t { Stabilize = 0, Auto = 3 };
struct Point {
  std::int32_t x;
  double y;
};
union Raw {
  std::uint32_t word;
  float real;
};
struct Flags {  // bit-fields: storage unit at offset 0
  std::uint32_t armed : 1;
  std::int32_t trim : 5;
  std::uint32_t count : 10;
};
struct Vehicle {
  bool flying;
  Mode mode;
  std::int16_t altitude;  // ranged [-100, 5000]
  std::uint64_t ticks;
  float battery;
  Raw raw;
  Flags flags;
  Point route[4];
  Point* target;        // into route: a reference by path
  const int* constant;  // outside the roots: the running build's value stays
  Point* nothing;       // null
};
static_assert(sizeof(Flags) == 4, "one storage unit");

inline Vehicle vehicle;
inline const int kOutside = 7;

inline bool valid_vehicle(const void* object) {
  return static_cast<const Vehicle*>(object)->ticks != 666;
}

enum : std::uint32_t {
  kBool,
  kMode,
  kU8,
  kI16,
  kU64,
  kF32,
  kRaw,
  kU32,
  kI32,
  kFlags,
  kF64,
  kPoint,
  kRoute,
  kPointPtr,
  kInt,
  kIntPtr,
  kVehicle,
  kTypeCount
};

inline const symcr::EnumeratorInfo kModes[] = {{"Stabilize", 0}, {"Auto", 3}};
inline const symcr::FieldInfo kPointFields[] = {field("x", kI32, offsetof(Point, x)),
                                                field("y", kF64, offsetof(Point, y))};
constexpr symcr::FieldRange kTrimRange{-12.0, 12.0};
constexpr symcr::FieldRange kAltitudeRange{-100, 5000};
inline const symcr::FieldInfo kFlagsFields[] = {
    bit_field("armed", kU32, 0, 1),
    {"trim", kI32, 0, 1, 5, symcr::kFieldHasRange, nullptr, &kTrimRange, nullptr},  // ranged bit-field
    bit_field("count", kU32, 6, 10)};
inline const symcr::FieldInfo kVehicleFields[] = {
    field("flying", kBool, offsetof(Vehicle, flying)),
    field("mode", kMode, offsetof(Vehicle, mode)),
    ranged("altitude", kI16, offsetof(Vehicle, altitude), kAltitudeRange),
    field("ticks", kU64, offsetof(Vehicle, ticks)),
    field("battery", kF32, offsetof(Vehicle, battery)),
    field("raw", kRaw, offsetof(Vehicle, raw)),
    field("flags", kFlags, offsetof(Vehicle, flags)),
    field("route", kRoute, offsetof(Vehicle, route)),
    field("target", kPointPtr, offsetof(Vehicle, target)),
    field("constant", kIntPtr, offsetof(Vehicle, constant)),
    field("nothing", kPointPtr, offsetof(Vehicle, nothing))};
inline const symcr::TypeInfo kTypes[kTypeCount] = {
    scalar("bool", Kind::Bool, 1),
    enumeration("Mode", 1, kU8, kModes, 2),
    scalar("uint8", Kind::UInt, 1),
    scalar("int16", Kind::Int, 2),
    scalar("uint64", Kind::UInt, 8),
    scalar("float32", Kind::Float, 4),
    union_of("Raw", sizeof(Raw), alignof(Raw)),
    scalar("uint32", Kind::UInt, 4),
    scalar("int32", Kind::Int, 4),
    record("Flags", sizeof(Flags), alignof(Flags), kFlagsFields, 3),
    scalar("float64", Kind::Float, 8),
    record("Point", sizeof(Point), alignof(Point), kPointFields, 2),
    array("Point[4]", kPoint, 4, sizeof(Point[4]), alignof(Point)),
    holder("Point*", Kind::Pointer, sizeof(Point*), alignof(Point*), kPoint, nullptr),
    scalar("int", Kind::Int, 4),
    holder("const int*", Kind::Pointer, sizeof(int*), alignof(int*), kInt, nullptr),
    record("Vehicle", sizeof(Vehicle), alignof(Vehicle), kVehicleFields, 11, nullptr,
           valid_vehicle)};
inline const symcr::RootInfo kRoots[] = {{"vehicle", kVehicle, &vehicle, 0, nullptr}};
inline const symcr::Schema kSchema{kTypes, kTypeCount, kRoots, 1, "device-test"};

inline void fill(int seed) {
  vehicle.flying = seed % 2 == 1;
  vehicle.mode = Mode::Auto;
  vehicle.altitude = static_cast<std::int16_t>(100 + seed);
  vehicle.ticks = 5000000000ull + static_cast<std::uint64_t>(seed);
  vehicle.battery = 15.5f - seed * 0.25f;
  vehicle.raw.word = 0xA5A50000u + static_cast<std::uint32_t>(seed);
  vehicle.flags.armed = 1;
  vehicle.flags.trim = -3 - seed % 5;
  vehicle.flags.count = 700u + static_cast<std::uint32_t>(seed);
  for (int i = 0; i < 4; ++i) vehicle.route[i] = Point{seed * 10 + i, seed + i * 0.5};
  vehicle.target = &vehicle.route[2];
  vehicle.constant = &kOutside;
  vehicle.nothing = nullptr;
}

inline void scramble() {
  static const int kOther = 99;
  std::memset(static_cast<void*>(&vehicle), 0x5A, sizeof vehicle);
  vehicle.target = &vehicle.route[0];
  vehicle.constant = &kOther;
  vehicle.nothing = &vehicle.route[1];
}

// True when `vehicle` holds what fill(seed) put there (its pointer to route[2] included).
inline bool holds(int seed) {
  bool same = vehicle.flying == (seed % 2 == 1) && vehicle.mode == Mode::Auto &&
              vehicle.altitude == 100 + seed &&
              vehicle.ticks == 5000000000ull + static_cast<std::uint64_t>(seed) &&
              vehicle.battery == 15.5f - seed * 0.25f &&
              vehicle.raw.word == 0xA5A50000u + static_cast<std::uint32_t>(seed) &&
              vehicle.flags.armed == 1 && vehicle.flags.trim == -3 - seed % 5 &&
              vehicle.flags.count == 700u + static_cast<std::uint32_t>(seed) &&
              vehicle.target == &vehicle.route[2] && vehicle.nothing == nullptr;
  for (int i = 0; i < 4; ++i) {
    same = same && vehicle.route[i].x == seed * 10 + i && vehicle.route[i].y == seed + i * 0.5;
  }
  return same;
}

}  // namespace device_tests

#endif  // SYMCR_TESTS_DEVICE_VEHICLE_HPP
