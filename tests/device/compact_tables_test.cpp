// The device profile's compact tables (what symcr-gen emits for PROFILE device) against the
// TypeInfo tables of the same schema: the same sizes, the same record bytes, every value
// restored, and the same refusals with the roots untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <vector>

#include "compact_schema.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/format/record.hpp"
#include "vehicle.hpp"

namespace device_tests {
namespace {

using symcr::device::Result;

struct Both {
  CompactSchema compact{kSchema};
  std::uint64_t hash = symcr::detail::schema_blob(kSchema).hash;
  symcr::device::Build typeinfo{&kSchema, hash};
  symcr::device::Build device{&compact.schema(), hash};

  static std::vector<std::uint8_t> save(const symcr::device::Build& build) {
    std::vector<std::uint8_t> record(symcr::device::record_size(*build.schema));
    std::size_t size = 0;
    EXPECT_EQ(symcr::device::save(build, 9, record.data(), record.size(), &size), Result::Ok);
    record.resize(size);
    return record;
  }
  static Result restore(const symcr::device::Build& build, const std::vector<std::uint8_t>& r) {
    std::vector<std::uint8_t> scratch(symcr::device::scratch_size(*build.schema));
    return symcr::device::restore(build, r.data(), r.size(), scratch.data(), scratch.size());
  }
};

// The record's CRC-32C recomputed after a change (docs/format.md §1).
void reseal(std::vector<std::uint8_t>& record) {
  std::memset(record.data() + symcr::format::kRecordChecksumOffset, 0, 4);
  symcr::format::store32(record.data() + symcr::format::kRecordChecksumOffset,
                         symcr::format::crc32c_extend_small(0, record.data(), record.size()));
}

std::vector<std::uint8_t> vehicle_bytes() {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&vehicle);
  return std::vector<std::uint8_t>(p, p + sizeof vehicle);
}

TEST(DeviceCompactTables, SizeSaveAndRestoreAsTheTypeInfoTables) {
  const Both both;
  EXPECT_EQ(symcr::device::check_schema(both.compact.schema()), Result::Ok);
  EXPECT_EQ(symcr::device::record_size(both.compact.schema()), symcr::device::record_size(kSchema));
  EXPECT_EQ(symcr::device::scratch_size(both.compact.schema()),
            symcr::device::scratch_size(kSchema));
  fill(4);
  const std::vector<std::uint8_t> record = Both::save(both.device);
  EXPECT_EQ(record, Both::save(both.typeinfo));
  scramble();
  const int* const running = vehicle.constant;
  ASSERT_EQ(Both::restore(both.device, record), Result::Ok);
  EXPECT_TRUE(holds(4));
  EXPECT_EQ(vehicle.target, &vehicle.route[2]);  // a reference by path, through the fields
  EXPECT_EQ(vehicle.constant, running);          // elsewhere: the running build's value
}

// A value out of its SYMCR_RANGE (a plain field, a bit-field) and one the validator refuses.
TEST(DeviceCompactTables, RangesAndTheValidatorRefuseTheWholeCheckpoint) {
  const Both both;
  void (*const breaks[])() = {[] { vehicle.altitude = 5001; }, [] { vehicle.flags.trim = -13; },
                              [] { vehicle.ticks = 666; }};
  for (auto breaking : breaks) {
    fill(2);
    breaking();
    const std::vector<std::uint8_t> record = Both::save(both.device);
    fill(6);
    const std::vector<std::uint8_t> before = vehicle_bytes();
    EXPECT_EQ(Both::restore(both.device, record), Result::Rejected);
    EXPECT_EQ(vehicle_bytes(), before);
    EXPECT_EQ(Both::restore(both.typeinfo, record), Result::Rejected);
    EXPECT_EQ(vehicle_bytes(), before);
  }
}

// Reference members: a struct's members that are not saved but at which a pointer may point (a
// shallow root's unselected members). A path steps into them after the struct's fields, and the
// compact tables keep them after the fields (their count in DeviceTypeInfo::count's high half).
struct Sensor {
  std::int32_t reading;
  std::int32_t offset;
};
struct Board {
  std::int32_t saved;
  Sensor sensors[3];  // not saved: a reference member
  Sensor* active;     // a field: points into sensors
};
Board board;

enum : std::uint32_t { kBoardI32, kSensor, kSensors, kSensorPtr, kBoard, kBoardTypeCount };
const symcr::FieldInfo kSensorFields[] = {field("reading", kBoardI32, offsetof(Sensor, reading)),
                                          field("offset", kBoardI32, offsetof(Sensor, offset))};
const symcr::FieldInfo kBoardFields[] = {field("saved", kBoardI32, offsetof(Board, saved)),
                                         field("active", kSensorPtr, offsetof(Board, active))};
const symcr::FieldInfo kBoardReferenceMembers[] = {
    field("sensors", kSensors, offsetof(Board, sensors))};
symcr::TypeInfo board_type() {
  symcr::TypeInfo type = record("Board", sizeof(Board), alignof(Board), kBoardFields, 2);
  type.flags = symcr::kTypeReferenceMembers;
  type.reference_members = kBoardReferenceMembers;
  type.reference_member_count = 1;
  return type;
}
const symcr::TypeInfo kBoardTypes[kBoardTypeCount] = {
    scalar("int32", Kind::Int, 4),
    record("Sensor", sizeof(Sensor), alignof(Sensor), kSensorFields, 2),
    array("Sensor[3]", kSensor, 3, sizeof(Sensor[3]), alignof(Sensor)),
    holder("Sensor*", Kind::Pointer, sizeof(Sensor*), alignof(Sensor*), kSensor, nullptr),
    board_type()};
const symcr::RootInfo kBoardRoots[] = {{"board", kBoard, &board, 0, nullptr}};
const symcr::Schema kBoardSchema{kBoardTypes, kBoardTypeCount, kBoardRoots, 1, "board"};

TEST(DeviceCompactTables, APointerAtAReferenceMemberRestoresThroughEitherForm) {
  const CompactSchema compact(kBoardSchema);
  const std::uint64_t hash = symcr::detail::schema_blob(kBoardSchema).hash;
  const symcr::device::Build typeinfo{&kBoardSchema, hash}, device{&compact.schema(), hash};
  board = Board{7, {{1, 2}, {3, 4}, {5, 6}}, &board.sensors[2]};
  const std::vector<std::uint8_t> record = Both::save(device);
  ASSERT_EQ(record, Both::save(typeinfo));
  // The reference (docs/format.md §3): an object, root 0, two steps: 2 (the first member after
  // Board's two fields) and 2 (the third element), ending at a Sensor.
  const std::uint8_t reference[] = {0, 0, 0, 0, 0, 2, 0, 2, 0, 0, 0, 2, 0, 0, 0, kSensor, 0, 0, 0};
  ASSERT_TRUE(std::search(record.begin(), record.end(), std::begin(reference),
                          std::end(reference)) != record.end());

  for (const symcr::device::Build* build : {&device, &typeinfo}) {
    board = Board{0, {{9, 9}, {8, 8}, {7, 7}}, nullptr};
    ASSERT_EQ(Both::restore(*build, record), Result::Ok);
    EXPECT_EQ(board.saved, 7);
    EXPECT_EQ(board.active, &board.sensors[2]);
    EXPECT_EQ(board.sensors[2].reading, 7);  // not saved: the running value stays
  }

  // A step past the reference members leaves the struct: refused, with the board untouched.
  std::vector<std::uint8_t> beyond = record;
  std::search(beyond.begin(), beyond.end(), std::begin(reference), std::end(reference))[7] = 3;
  reseal(beyond);  // the first step: Board has 2 fields and 1 reference member
  for (const symcr::device::Build* build : {&device, &typeinfo}) {
    board = Board{1, {{9, 9}, {8, 8}, {7, 7}}, nullptr};
    EXPECT_EQ(Both::restore(*build, beyond), Result::Corrupt);
    EXPECT_EQ(board.saved, 1);
    EXPECT_EQ(board.active, nullptr);
  }
}

}  // namespace
}  // namespace device_tests
