// The device profile's compact tables (what symcr-gen emits for PROFILE device) against the
// TypeInfo tables of the same schema: the same sizes, the same record bytes, every value
// restored, and the same refusals with the roots untouched.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "compact_schema.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"
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

}  // namespace
}  // namespace device_tests
