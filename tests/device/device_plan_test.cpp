// The device profile's cross-version restore: a checkpoint of a previous build (V0) restored
// into this one (V1) through the device plan image symcr-gen embeds for V0's schema, value by
// value, equal to the host runtime's restore of the same checkpoint; refusals all-or-nothing;
// what the device cannot resolve refused when the image is made.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "compact_schema.hpp"
#include "device_plan_encode.hpp"
#include "schema_blob.hpp"
#include "schema_tables.hpp"
#include "symcr/device.hpp"
#include "symcr/symcr.hpp"

namespace device_plan_tests {
namespace {

using namespace schema_tables;
using symcr::Kind;
using symcr::device::Result;

std::int64_t clock_now = 0;
std::int64_t read_clock() { return clock_now; }
const symcr::ClockInfo kClock{"boot_ms", read_clock, 0};
const symcr::FieldTime kFixTime{&kClock, 0};

// ---- V0: the build that saved ----------------------------------------------------------------
enum class ModeV0 : std::uint8_t { Stabilize = 0, Auto = 3, Land = 4, Flip = 5 };
struct PointV0 {
  std::int32_t x;
  double y;
};
struct FlagsV0 {
  std::uint32_t armed : 1;
  std::int32_t trim : 5;
};
struct VehicleV0 {
  bool flying;
  ModeV0 mode;
  std::int16_t altitude;
  std::uint32_t battery_mv;  // renamed to battery in V1, narrowed to 16 bits
  std::uint16_t retired;     // removed in V1
  FlagsV0 flags;
  PointV0 route[3];  // grown to 5 in V1
  PointV0* target;
  float speed;                // a double in V1
  std::uint32_t last_fix_ms;  // a time of the boot clock
};
VehicleV0 v0;
std::int32_t v0_retired_root;  // a root V1 no longer has

enum : std::uint32_t {
  kBool0,
  kMode0,
  kU8_0,
  kI16_0,
  kU32_0,
  kU16_0,
  kI32_0,
  kFlags0,
  kF64_0,
  kPoint0,
  kRoute0,
  kPointPtr0,
  kF32_0,
  kVehicle0,
  kTypes0
};
const symcr::EnumeratorInfo kModesV0[] = {{"Stabilize", 0}, {"Auto", 3}, {"Land", 4}, {"Flip", 5}};
const FieldInfo kPointV0[] = {field("x", kI32_0, offsetof(PointV0, x)),
                              field("y", kF64_0, offsetof(PointV0, y))};
const FieldInfo kFlagsV0[] = {bit_field("armed", kU32_0, 0, 1), bit_field("trim", kI32_0, 1, 5)};
const FieldInfo kVehicleV0[] = {
    field("flying", kBool0, offsetof(VehicleV0, flying)),
    field("mode", kMode0, offsetof(VehicleV0, mode)),
    field("altitude", kI16_0, offsetof(VehicleV0, altitude)),
    field("battery_mv", kU32_0, offsetof(VehicleV0, battery_mv)),
    field("retired", kU16_0, offsetof(VehicleV0, retired)),
    field("flags", kFlags0, offsetof(VehicleV0, flags)),
    field("route", kRoute0, offsetof(VehicleV0, route)),
    field("target", kPointPtr0, offsetof(VehicleV0, target)),
    field("speed", kF32_0, offsetof(VehicleV0, speed)),
    timed("last_fix_ms", kU32_0, offsetof(VehicleV0, last_fix_ms), kFixTime)};
const TypeInfo kTypesV0[kTypes0] = {
    scalar("bool", Kind::Bool, 1),
    enumeration("Mode", 1, kU8_0, kModesV0, 4),
    scalar("uint8", Kind::UInt, 1),
    scalar("int16", Kind::Int, 2),
    scalar("uint32", Kind::UInt, 4),
    scalar("uint16", Kind::UInt, 2),
    scalar("int32", Kind::Int, 4),
    record("Flags", sizeof(FlagsV0), alignof(FlagsV0), kFlagsV0, 2),
    scalar("float64", Kind::Float, 8),
    record("Point", sizeof(PointV0), alignof(PointV0), kPointV0, 2),
    array("Point[3]", kPoint0, 3, sizeof(PointV0[3]), alignof(PointV0)),
    holder("Point*", Kind::Pointer, sizeof(PointV0*), alignof(PointV0*), kPoint0, nullptr),
    scalar("float32", Kind::Float, 4),
    record("Vehicle", sizeof(VehicleV0), alignof(VehicleV0), kVehicleV0, 10)};
const symcr::RootInfo kRootsV0[] = {{"vehicle", kVehicle0, &v0, 0, nullptr},
                                    {"retired_root", kI32_0, &v0_retired_root, 0, nullptr}};
const symcr::Schema kSchemaV0{kTypesV0, kTypes0, kRootsV0, 2, "plan-test"};

// ---- V1: the patched build that restores -----------------------------------------------------
enum class ModeV1 : std::int16_t { Land = 1, Stabilize = 2, Auto = 7, Guided = 9 };
struct PointV1 {
  double y;  // reordered
  std::int32_t x;
  std::int32_t z;  // added
};
struct FlagsV1 {
  std::uint32_t armed : 1;
  std::int32_t trim : 7;  // wider, ranged
};
struct VehicleV1 {
  std::int64_t altitude;  // widened, ranged
  ModeV1 mode;            // renumbered, widened
  PointV1 route[5];       // grown
  bool flying;
  std::uint16_t battery;  // renamed from battery_mv, narrowed
  std::int32_t added;     // added: keeps the running build's value
  FlagsV1 flags;
  PointV1* target;
  double speed;
  std::uint32_t last_fix_ms;
};
VehicleV1 v1;
std::uint8_t v1_extra;  // a root V0 did not have

bool valid_v1(const void* object) {
  return static_cast<const VehicleV1*>(object)->altitude != 4321;
}

enum : std::uint32_t {
  kBool1,
  kMode1,
  kI16_1,
  kI64_1,
  kU16_1,
  kI32_1,
  kU32_1,
  kFlags1,
  kF64_1,
  kPoint1,
  kRoute1,
  kPointPtr1,
  kU8_1,
  kVehicle1,
  kTypes1
};
const symcr::EnumeratorInfo kModesV1[] = {
    {"Land", 1}, {"Stabilize", 2}, {"Auto", 7}, {"Guided", 9}};
const char* const kBatteryWas[] = {"battery_mv", nullptr};
constexpr symcr::FieldRange kAltitudeRange{-100, 5000};
constexpr symcr::FieldRange kTrimRange{-12, 12};
const FieldInfo kPointV1[] = {field("y", kF64_1, offsetof(PointV1, y)),
                              field("x", kI32_1, offsetof(PointV1, x)),
                              field("z", kI32_1, offsetof(PointV1, z))};
const FieldInfo kFlagsV1[] = {
    bit_field("armed", kU32_1, 0, 1),
    {"trim", kI32_1, 0, 1, 7, symcr::kFieldHasRange, nullptr, &kTrimRange, nullptr}};
const FieldInfo kVehicleV1[] = {
    ranged("altitude", kI64_1, offsetof(VehicleV1, altitude), kAltitudeRange),
    field("mode", kMode1, offsetof(VehicleV1, mode)),
    field("route", kRoute1, offsetof(VehicleV1, route)),
    field("flying", kBool1, offsetof(VehicleV1, flying)),
    field("battery", kU16_1, offsetof(VehicleV1, battery), kBatteryWas),
    field("added", kI32_1, offsetof(VehicleV1, added)),
    field("flags", kFlags1, offsetof(VehicleV1, flags)),
    field("target", kPointPtr1, offsetof(VehicleV1, target)),
    field("speed", kF64_1, offsetof(VehicleV1, speed)),
    timed("last_fix_ms", kU32_1, offsetof(VehicleV1, last_fix_ms), kFixTime)};
const TypeInfo kTypesV1[kTypes1] = {
    scalar("bool", Kind::Bool, 1),
    enumeration("Mode", 2, kI16_1, kModesV1, 4),
    scalar("int16", Kind::Int, 2),
    scalar("int64", Kind::Int, 8),
    scalar("uint16", Kind::UInt, 2),
    scalar("int32", Kind::Int, 4),
    scalar("uint32", Kind::UInt, 4),
    record("Flags", sizeof(FlagsV1), alignof(FlagsV1), kFlagsV1, 2),
    scalar("float64", Kind::Float, 8),
    record("Point", sizeof(PointV1), alignof(PointV1), kPointV1, 3),
    array("Point[5]", kPoint1, 5, sizeof(PointV1[5]), alignof(PointV1)),
    holder("Point*", Kind::Pointer, sizeof(PointV1*), alignof(PointV1*), kPoint1, nullptr),
    scalar("uint8", Kind::UInt, 1),
    record("Vehicle", sizeof(VehicleV1), alignof(VehicleV1), kVehicleV1, 10, nullptr, valid_v1)};
const symcr::RootInfo kRootsV1[] = {{"vehicle", kVehicle1, &v1, 0, nullptr},
                                    {"extra", kU8_1, &v1_extra, 0, nullptr}};
const symcr::Schema kSchemaV1{kTypesV1, kTypes1, kRootsV1, 2, "plan-test"};

std::uint64_t hash_of(const symcr::Schema& schema) {
  return symcr::detail::schema_blob(schema).hash;
}

void fill_v0(int seed) {
  std::memset(static_cast<void*>(&v0), 0, sizeof v0);
  v0.flying = seed % 2 == 0;
  v0.mode = seed % 3 == 0 ? ModeV0::Land : ModeV0::Auto;
  v0.altitude = static_cast<std::int16_t>(-50 + 37 * seed);
  v0.battery_mv = 11000u + static_cast<std::uint32_t>(seed);
  v0.retired = 0xBEEF;
  v0.flags.armed = 1;
  v0.flags.trim = -3 - seed % 5;
  for (int i = 0; i < 3; ++i) v0.route[i] = PointV0{seed * 10 + i, seed + i * 0.25};
  v0.target = &v0.route[seed % 3];
  v0.speed = 2.5f + static_cast<float>(seed);
  v0.last_fix_ms = 1000u + static_cast<std::uint32_t>(seed);
  v0_retired_root = 77;
}

// V1's state as a reset leaves it: its initial values.
void initial_v1() {
  std::memset(static_cast<void*>(&v1), 0, sizeof v1);
  v1.mode = ModeV1::Stabilize;
  for (int i = 0; i < 5; ++i) v1.route[i] = PointV1{-1.0, -1, 40 + i};
  v1.added = 1234;
  v1.altitude = 7;
  v1_extra = 9;
}

struct Devices {
  std::vector<std::uint8_t> image;
  symcr::PlannedSchema planned{};
  symcr::device::Build v1_build;
  symcr::device::Build v0_build;
  Devices() {
    std::string error;
    EXPECT_TRUE(symcr::detail::device_plan_image_for(kSchemaV0, hash_of(kSchemaV0), kSchemaV1,
                                                     hash_of(kSchemaV1), image, error))
        << error;
    planned = symcr::PlannedSchema{hash_of(kSchemaV0), image.data(),
                                   static_cast<std::uint32_t>(image.size())};
    v1_build = symcr::device::Build(&kSchemaV1, hash_of(kSchemaV1), &planned, 1);
    v0_build = symcr::device::Build(&kSchemaV0, hash_of(kSchemaV0));
  }
  std::vector<std::uint8_t> save_v0() const {
    std::vector<std::uint8_t> record(symcr::device::record_size(kSchemaV0));
    std::size_t size = 0;
    EXPECT_EQ(symcr::device::save(v0_build, 5, record.data(), record.size(), &size), Result::Ok);
    record.resize(size);
    return record;
  }
  Result restore_v1(const std::vector<std::uint8_t>& record) const {
    std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchemaV1));
    return symcr::device::restore(v1_build, record.data(), record.size(), scratch.data(),
                                  scratch.size());
  }
};

std::vector<std::uint8_t> v1_bytes() {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&v1);
  std::vector<std::uint8_t> bytes(p, p + sizeof v1);
  bytes.push_back(v1_extra);
  return bytes;
}

// Every value of V1 equal (padding aside) to another restore's.
void expect_same_v1(const VehicleV1& a, std::uint8_t a_extra) {
  EXPECT_EQ(v1.altitude, a.altitude);
  EXPECT_EQ(v1.mode, a.mode);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(v1.route[i].x, a.route[i].x) << i;
    EXPECT_EQ(v1.route[i].y, a.route[i].y) << i;
    EXPECT_EQ(v1.route[i].z, a.route[i].z) << i;
  }
  EXPECT_EQ(v1.flying, a.flying);
  EXPECT_EQ(v1.battery, a.battery);
  EXPECT_EQ(v1.added, a.added);
  EXPECT_EQ(v1.flags.armed, a.flags.armed);
  EXPECT_EQ(v1.flags.trim, a.flags.trim);
  EXPECT_EQ(v1.target, a.target);
  EXPECT_EQ(v1.speed, a.speed);
  EXPECT_EQ(v1.last_fix_ms, a.last_fix_ms);
  EXPECT_EQ(v1_extra, a_extra);
}

TEST(DevicePlan, RestoresAPreviousBuildsCheckpointValueByValue) {
  const Devices devices;
  clock_now = 500;
  fill_v0(4);
  const std::vector<std::uint8_t> record = devices.save_v0();
  initial_v1();
  clock_now = 20;  // after the reset the clock starts again: times move by 20 - 500
  ASSERT_EQ(devices.restore_v1(record), Result::Ok);
  EXPECT_EQ(v1.altitude, -50 + 37 * 4);
  EXPECT_EQ(v1.mode, ModeV1::Auto);  // by name: 3 was Auto, Auto is 7 now
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(v1.route[i].x, 40 + i);
    EXPECT_EQ(v1.route[i].y, 4 + i * 0.25);
    EXPECT_EQ(v1.route[i].z, 40 + i);  // added member: the running build's value
  }
  for (int i = 3; i < 5; ++i) {  // elements the checkpoint did not have
    EXPECT_EQ(v1.route[i].x, -1);
    EXPECT_EQ(v1.route[i].y, -1.0);
  }
  EXPECT_TRUE(v1.flying);
  EXPECT_EQ(v1.battery, 11004u);
  EXPECT_EQ(v1.added, 1234);
  EXPECT_EQ(v1.flags.armed, 1u);
  EXPECT_EQ(v1.flags.trim, -7);
  EXPECT_EQ(v1.target, &v1.route[1]);  // by path: the same element
  EXPECT_EQ(v1.speed, 6.5);
  EXPECT_EQ(v1.last_fix_ms, 1004u + 20u - 500u);
  EXPECT_EQ(v1_extra, 9);

  fill_v0(3);  // Land: 4 then, 1 now
  const std::vector<std::uint8_t> landing = devices.save_v0();
  ASSERT_EQ(devices.restore_v1(landing), Result::Ok);
  EXPECT_EQ(v1.mode, ModeV1::Land);
  EXPECT_EQ(v1.target, &v1.route[0]);
}

// V1's tables in the compact form symcr-gen emits for a firmware (its clock's time, ranges and
// enum included): V0's checkpoint through the plan, and V1's own, restore the same values and
// save the same bytes as through V1's TypeInfo tables.
TEST(DevicePlan, CompactTablesRestoreAsTheTypeInfoTables) {
  const Devices devices;
  const device_tests::CompactSchema compact(kSchemaV1);
  const symcr::device::Build compact_build(&compact.schema(), hash_of(kSchemaV1), &devices.planned,
                                           1);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(compact.schema()));
  ASSERT_EQ(scratch.size(), symcr::device::scratch_size(kSchemaV1));
  for (int seed = 0; seed < 6; ++seed) {
    clock_now = 500;
    fill_v0(seed);
    const std::vector<std::uint8_t> record = devices.save_v0();
    clock_now = 20;
    initial_v1();
    ASSERT_EQ(devices.restore_v1(record), Result::Ok) << seed;
    const std::vector<std::uint8_t> by_typeinfo = v1_bytes();
    initial_v1();
    ASSERT_EQ(symcr::device::restore(compact_build, record.data(), record.size(), scratch.data(),
                                     scratch.size()),
              Result::Ok)
        << seed;
    EXPECT_EQ(v1_bytes(), by_typeinfo) << seed;
    std::vector<std::uint8_t> own(symcr::device::record_size(compact.schema()));
    std::vector<std::uint8_t> own_typeinfo(symcr::device::record_size(kSchemaV1));
    std::size_t size = 0, size_typeinfo = 0;
    ASSERT_EQ(symcr::device::save(compact_build, 7, own.data(), own.size(), &size), Result::Ok);
    ASSERT_EQ(symcr::device::save(devices.v1_build, 7, own_typeinfo.data(), own_typeinfo.size(),
                                  &size_typeinfo),
              Result::Ok);
    own.resize(size);
    own_typeinfo.resize(size_typeinfo);
    EXPECT_EQ(own, own_typeinfo) << seed;
    clock_now = 50 + seed;  // another reset: the time moves on the same-build path too
    initial_v1();
    ASSERT_EQ(devices.restore_v1(own_typeinfo), Result::Ok) << seed;
    const std::vector<std::uint8_t> own_by_typeinfo = v1_bytes();
    EXPECT_EQ(v1.last_fix_ms, 1000u + static_cast<std::uint32_t>(seed) + 20u - 500u + 30u +
                                  static_cast<std::uint32_t>(seed));
    initial_v1();
    ASSERT_EQ(symcr::device::restore(compact_build, own.data(), own.size(), scratch.data(),
                                     scratch.size()),
              Result::Ok)
        << seed;
    EXPECT_EQ(v1_bytes(), own_by_typeinfo) << seed;
  }
}

// After restoring V0's checkpoint, V1 checkpoints in its own format: the same-build path.
TEST(DevicePlan, TheNewBuildThenRestoresItsOwnCheckpoints) {
  const Devices devices;
  clock_now = 0;
  fill_v0(5);
  initial_v1();
  ASSERT_EQ(devices.restore_v1(devices.save_v0()), Result::Ok);
  const VehicleV1 restored = v1;
  std::vector<std::uint8_t> own(symcr::device::record_size(kSchemaV1));
  std::size_t size = 0;
  ASSERT_EQ(symcr::device::save(devices.v1_build, 6, own.data(), own.size(), &size), Result::Ok);
  own.resize(size);
  initial_v1();
  ASSERT_EQ(devices.restore_v1(own), Result::Ok);
  expect_same_v1(restored, 9);
}

TEST(DevicePlan, EqualsTheHostRuntimesCrossVersionRestore) {
  const Devices devices;
  for (int seed = 0; seed < 12; ++seed) {
    // The clock stands still: the host, restoring in the process that saved, keeps times as
    // they are, while a device (restoring after a reset) moves them by its clock.
    clock_now = 100 + seed;
    fill_v0(seed);
    std::vector<std::uint8_t> checkpoint;  // the host's, with V0's schema inline
    ASSERT_TRUE(symcr::checkpoint_to_buffer(kSchemaV0, checkpoint, 3).ok());
    initial_v1();
    const symcr::Report host =
        symcr::restore_from_buffer(kSchemaV1, checkpoint.data(), checkpoint.size());
    ASSERT_TRUE(host.ok()) << host.to_text();
    const VehicleV1 by_host = v1;
    const std::uint8_t host_extra = v1_extra;
    initial_v1();
    ASSERT_EQ(devices.restore_v1(checkpoint), Result::Ok) << seed;
    expect_same_v1(by_host, host_extra);
    initial_v1();  // the device's own record of the same state restores the same
    ASSERT_EQ(devices.restore_v1(devices.save_v0()), Result::Ok) << seed;
    expect_same_v1(by_host, host_extra);
  }
}

// Each case refuses the whole checkpoint and changes nothing; the host's strict restore
// refuses it too.
TEST(DevicePlan, AValueTheNewBuildRefusesRefusesTheWholeCheckpoint) {
  const Devices devices;
  const auto cases = {
      +[] { v0.altitude = 6000; },      // outside V1's range
      +[] { v0.altitude = 4321; },      // refused by V1's validator
      +[] { v0.battery_mv = 70000; },   // does not fit 16 bits
      +[] { v0.mode = ModeV0::Flip; },  // no enumerator of that name in V1
      +[] { v0.flags.trim = -13; },     // the range of V1's wider bit-field
  };
  for (void (*change)() : cases) {
    fill_v0(2);
    change();
    std::vector<std::uint8_t> checkpoint;
    ASSERT_TRUE(symcr::checkpoint_to_buffer(kSchemaV0, checkpoint, 3).ok());
    initial_v1();
    const std::vector<std::uint8_t> before = v1_bytes();
    EXPECT_EQ(devices.restore_v1(checkpoint), Result::Rejected);
    EXPECT_EQ(devices.restore_v1(devices.save_v0()), Result::Rejected);
    EXPECT_EQ(v1_bytes(), before);
    symcr::RestoreOptions strict;
    strict.strict = true;
    EXPECT_FALSE(
        symcr::restore_from_buffer(kSchemaV1, checkpoint.data(), checkpoint.size(), strict).ok());
  }
}

TEST(DevicePlan, ACheckpointOfAnUnknownBuildLeavesTheStateInitial) {
  const Devices devices;
  fill_v0(1);
  const std::vector<std::uint8_t> record = devices.save_v0();
  initial_v1();
  const std::vector<std::uint8_t> before = v1_bytes();
  // Without the plan, and with a plan for another writer or another reader: OtherSchema.
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchemaV1));
  const symcr::device::Build bare(&kSchemaV1, hash_of(kSchemaV1));
  EXPECT_EQ(
      symcr::device::restore(bare, record.data(), record.size(), scratch.data(), scratch.size()),
      Result::OtherSchema);
  const symcr::PlannedSchema elsewhere{devices.planned.writer_hash ^ 1, devices.planned.image,
                                       devices.planned.size};
  const symcr::device::Build other_writer(&kSchemaV1, hash_of(kSchemaV1), &elsewhere, 1);
  EXPECT_EQ(symcr::device::restore(other_writer, record.data(), record.size(), scratch.data(),
                                   scratch.size()),
            Result::OtherSchema);
  const symcr::device::Build other_reader(&kSchemaV1, hash_of(kSchemaV1) ^ 1, &devices.planned, 1);
  EXPECT_EQ(symcr::device::restore(other_reader, record.data(), record.size(), scratch.data(),
                                   scratch.size()),
            Result::OtherSchema);
  EXPECT_EQ(v1_bytes(), before);
}

// Several previous releases: each record restores through the plan for its own build.
TEST(DevicePlan, SeveralPreviousReleasesEachThroughItsOwnPlan) {
  const Devices devices;
  // The second previous release: V0 without its retired root.
  const symcr::Schema v0_one_root{kTypesV0, kTypes0, kRootsV0, 1, "plan-test"};
  std::vector<std::uint8_t> image;
  std::string error;
  ASSERT_TRUE(symcr::detail::device_plan_image_for(v0_one_root, hash_of(v0_one_root), kSchemaV1,
                                                   hash_of(kSchemaV1), image, error))
      << error;
  const symcr::PlannedSchema plans[] = {
      {hash_of(v0_one_root), image.data(), static_cast<std::uint32_t>(image.size())},
      devices.planned};
  const symcr::device::Build build(&kSchemaV1, hash_of(kSchemaV1), plans, 2);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchemaV1));
  clock_now = 0;
  for (int release = 0; release < 2; ++release) {
    fill_v0(6 + release);
    const symcr::device::Build writer(release == 0 ? &v0_one_root : &kSchemaV0,
                                      release == 0 ? hash_of(v0_one_root) : hash_of(kSchemaV0));
    std::vector<std::uint8_t> record(symcr::device::record_size(kSchemaV0));
    std::size_t size = 0;
    ASSERT_EQ(symcr::device::save(writer, 1, record.data(), record.size(), &size), Result::Ok);
    initial_v1();
    ASSERT_EQ(symcr::device::restore(build, record.data(), size, scratch.data(), scratch.size()),
              Result::Ok)
        << release;
    EXPECT_EQ(v1.altitude, -50 + 37 * (6 + release));
    EXPECT_EQ(v1.battery, 11006u + static_cast<unsigned>(release));
    EXPECT_EQ(v1.target, &v1.route[(6 + release) % 3]);
  }
}

TEST(DevicePlan, ADamagedImageOrRecordIsRefusedAndChangesNothing) {
  const Devices devices;
  fill_v0(2);
  std::vector<std::uint8_t> record = devices.save_v0();
  initial_v1();
  const std::vector<std::uint8_t> before = v1_bytes();
  std::vector<std::uint8_t> image = devices.image;
  image.pop_back();  // the tables no longer end the image
  const symcr::PlannedSchema truncated{devices.planned.writer_hash, image.data(),
                                       static_cast<std::uint32_t>(image.size())};
  const symcr::device::Build build(&kSchemaV1, hash_of(kSchemaV1), &truncated, 1);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchemaV1));
  EXPECT_EQ(
      symcr::device::restore(build, record.data(), record.size(), scratch.data(), scratch.size()),
      Result::Corrupt);
  record[100] ^= 0x40;  // the record's CRC no longer holds
  EXPECT_EQ(devices.restore_v1(record), Result::Corrupt);
  EXPECT_EQ(v1_bytes(), before);
}

// What the device cannot carry out is refused when the image is made (symcr-gen's build-time
// error), naming the member path and the fixes.
TEST(DevicePlan, WhatTheDeviceCannotResolveIsRefusedWithThePathAndTheFix) {
  // V1 whose Mode has none of V0's enumerators: no value of it could be restored, which the
  // host decides per value and the device, all or nothing, cannot.
  TypeInfo types[kTypes1];
  std::memcpy(static_cast<void*>(types), kTypesV1, sizeof types);
  const symcr::EnumeratorInfo renamed[] = {{"Hover", 1}, {"Mission", 2}};
  types[kMode1].enumerators = renamed;
  types[kMode1].enumerator_count = 2;
  const symcr::Schema reader{types, kTypes1, kRootsV1, 2, "plan-test"};
  std::vector<std::uint8_t> image;
  std::string error;
  EXPECT_FALSE(symcr::detail::device_plan_image_for(kSchemaV0, hash_of(kSchemaV0), reader,
                                                    hash_of(reader), image, error));
  EXPECT_NE(error.find("'vehicle.mode'"), std::string::npos) << error;
  EXPECT_NE(error.find("SYMCR_SKIP"), std::string::npos) << error;
  EXPECT_NE(error.find("symcr convert"), std::string::npos) << error;
}

}  // namespace
}  // namespace device_plan_tests
