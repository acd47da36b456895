// Tainted data: a checkpoint whose values were changed on disk by someone
// who also recomputed the CRC-32C passes every integrity check, so only the user's rules stand
// between it and the live state: SYMCR_RANGE bounds on scalar fields (FieldInfo
// kFieldHasRange/range_min/range_max) and a type's symcr_validate (TypeInfo::validate). A value
// breaking them is rejected (named in the report), the reader keeps its own value, and strict
// mode refuses the whole restore.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "crc32c.hpp"
#include "file_test_util.hpp"
#include "reliability_schemas.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

using symcr::Decision;

struct Sensor {
  float altitude;          // SYMCR_RANGE(-100, 10000)
  std::int32_t throttle;   // SYMCR_RANGE(0, 100)
  std::uint8_t mode;       // no rule
};
struct Limits {  // bool symcr_validate(const Limits& l) { return l.lo <= l.hi; }
  std::int32_t lo;
  std::int32_t hi;
};
struct Vehicle {
  Sensor sensor;
  Limits limits[4];
  std::vector<Limits> more;
  double speed;            // SYMCR_RANGE(0, 50)
  std::int16_t heading;    // SYMCR_RANGE(0, 359)
};
Vehicle vehicle;

bool validate_limits(const void* object) {
  const auto* limits = static_cast<const Limits*>(object);
  return limits->lo <= limits->hi;
}

constexpr symcr::FieldRange kAltitudeRange{-100, 10000};
constexpr symcr::FieldRange kThrottleRange{0, 100};
constexpr symcr::FieldRange kSpeedRange{0, 50};
constexpr symcr::FieldRange kHeadingRange{0, 359};

const symcr::Schema& vehicle_schema() {
  static const FieldInfo sensor_fields[] = {
      ranged("altitude", 0, offsetof(Sensor, altitude), kAltitudeRange),
      ranged("throttle", 1, offsetof(Sensor, throttle), kThrottleRange),
      field("mode", 2, offsetof(Sensor, mode))};
  static const FieldInfo limits_fields[] = {field("lo", 1, offsetof(Limits, lo)),
                                            field("hi", 1, offsetof(Limits, hi))};
  static const FieldInfo vehicle_fields[] = {
      field("sensor", 3, offsetof(Vehicle, sensor)),
      field("limits", 5, offsetof(Vehicle, limits)),
      field("more", 6, offsetof(Vehicle, more)),
      ranged("speed", 7, offsetof(Vehicle, speed), kSpeedRange),
      ranged("heading", 8, offsetof(Vehicle, heading), kHeadingRange)};
  static const TypeInfo types[] = {
      scalar("float32", Kind::Float, 4),
      scalar("int32", Kind::Int, 4),
      scalar("uint8", Kind::UInt, 1),
      record("reliability::Sensor", sizeof(Sensor), alignof(Sensor), sensor_fields, 3),
      record("reliability::Limits", sizeof(Limits), alignof(Limits), limits_fields, 2,
             &symcr::ops::lifecycle<Limits>::table, &validate_limits),
      array("reliability::Limits[4]", 4, 4, sizeof(Limits[4]), alignof(Limits)),
      holder("std::vector<reliability::Limits>", Kind::Container, sizeof(std::vector<Limits>),
             alignof(std::vector<Limits>), 4, &symcr::ops::container<std::vector<Limits>>::table),
      scalar("float64", Kind::Float, 8),
      scalar("int16", Kind::Int, 2),
      record("reliability::Vehicle", sizeof(Vehicle), alignof(Vehicle), vehicle_fields, 5),
  };
  static const symcr::RootInfo roots[] = {{"vehicle", 9, &vehicle, 0, nullptr}};
  static const symcr::Schema schema{types, 10, roots, 1, nullptr};
  return schema;
}

// Payload offsets of the values (docs/format.md §3: schema order, wire widths) with
// vehicle.more holding two elements.
constexpr std::size_t kAltitude = 0, kThrottle = 4, kMode = 8, kLimits = 9, kMoreCount = 41,
                      kMore = 45, kSpeed = 61, kHeading = 69, kPayloadSize = 71 + 8;

void fill_good() {
  vehicle.sensor = Sensor{120.5f, 40, 3};
  for (int i = 0; i < 4; ++i) vehicle.limits[i] = Limits{i, i + 10};
  vehicle.more = {Limits{1, 2}, Limits{-5, 5}};
  vehicle.speed = 12.5;
  vehicle.heading = 270;
}

void reset_reader() {
  vehicle.sensor = Sensor{-1.0f, 1, 1};
  for (int i = 0; i < 4; ++i) vehicle.limits[i] = Limits{-1, -1};
  vehicle.more = {Limits{7, 7}};
  vehicle.speed = 1;
  vehicle.heading = 1;
}

// No live value breaks a rule.
::testing::AssertionResult rules_hold() {
  const Sensor& s = vehicle.sensor;
  if (!(s.altitude >= -100 && s.altitude <= 10000)) return ::testing::AssertionFailure() << "altitude " << s.altitude;
  if (!(s.throttle >= 0 && s.throttle <= 100)) return ::testing::AssertionFailure() << "throttle " << s.throttle;
  if (!(vehicle.speed >= 0 && vehicle.speed <= 50)) return ::testing::AssertionFailure() << "speed " << vehicle.speed;
  if (!(vehicle.heading >= 0 && vehicle.heading <= 359)) return ::testing::AssertionFailure() << "heading " << vehicle.heading;
  for (const Limits& l : vehicle.limits) {
    if (!validate_limits(&l)) return ::testing::AssertionFailure() << "limits " << l.lo << ">" << l.hi;
  }
  for (const Limits& l : vehicle.more) {
    if (!validate_limits(&l)) return ::testing::AssertionFailure() << "more " << l.lo << ">" << l.hi;
  }
  return ::testing::AssertionSuccess();
}

class TaintedData : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = dir_.file("vehicle.ckpt");
    fill_good();
    ASSERT_TRUE(symcr::checkpoint(vehicle_schema(), path_.c_str()).ok());
    record_ = file_tests::read_file(path_);
    payload_at_ =
        symcr::format::load16(record_.data() + 10) + symcr::format::load32(record_.data() + 40);
    ASSERT_EQ(record_.size() - payload_at_, kPayloadSize);
  }

  // Writes the record with `edit` applied to its payload and a correct CRC-32C again: what an
  // attacker with write access to the file produces.
  template <typename Edit>
  void tamper(Edit edit) {
    std::vector<std::uint8_t> bytes = record_;
    edit(bytes.data() + payload_at_);
    symcr::format::store32(bytes.data() + 48, 0);
    symcr::format::store32(bytes.data() + 48, symcr::detail::crc32c(bytes.data(), bytes.size()));
    file_tests::write_file(path_, bytes);
  }

  file_tests::TempDir dir_;
  std::string path_;
  std::vector<std::uint8_t> record_;
  std::size_t payload_at_ = 0;
};

void put_f32(std::uint8_t* p, float v) { std::memcpy(p, &v, 4); }
void put_f64(std::uint8_t* p, double v) { std::memcpy(p, &v, 8); }

bool rejected(const symcr::Report& report, const std::string& path, const char* why) {
  for (const symcr::ReportEntry& entry : report.entries()) {
    if (entry.path == path && entry.decision == Decision::Rejected && entry.lossy &&
        entry.detail.find(why) != std::string::npos) {
      return true;
    }
  }
  return false;
}

TEST_F(TaintedData, OutOfRangeAndInvalidValuesAreRejectedTheRestRestored) {
  tamper([](std::uint8_t* payload) {
    put_f32(payload + kAltitude, 1e9f);
    symcr::format::store32(payload + kThrottle, static_cast<std::uint32_t>(-7));
    payload[kMode] = 250;                                           // no rule: restored
    symcr::format::store32(payload + kLimits + 2 * 8, 100);         // limits[2] = {100, 12}
    symcr::format::store32(payload + kMore + 8 + 4,
                           static_cast<std::uint32_t>(-9));  // more[1] = {-5, -9}
    put_f64(payload + kSpeed, std::numeric_limits<double>::quiet_NaN());
    symcr::format::store16(payload + kHeading, 360);
  });
  reset_reader();
  const symcr::Report report = symcr::restore(vehicle_schema(), path_.c_str());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(rules_hold());
  EXPECT_TRUE(rejected(report, "vehicle.sensor.altitude", "outside")) << report.to_text();
  EXPECT_TRUE(rejected(report, "vehicle.sensor.throttle", "outside")) << report.to_text();
  EXPECT_TRUE(rejected(report, "vehicle.speed", "outside")) << report.to_text();
  EXPECT_TRUE(rejected(report, "vehicle.heading", "outside")) << report.to_text();
  EXPECT_TRUE(rejected(report, "vehicle.limits[2]", "symcr_validate")) << report.to_text();
  EXPECT_TRUE(rejected(report, "vehicle.more[1]", "symcr_validate")) << report.to_text();
  // Rejected values keep the reader's own; everything else is the checkpoint's.
  EXPECT_EQ(vehicle.sensor.altitude, -1.0f);
  EXPECT_EQ(vehicle.sensor.throttle, 1);
  EXPECT_EQ(vehicle.sensor.mode, 250);
  EXPECT_EQ(vehicle.speed, 1);
  EXPECT_EQ(vehicle.heading, 1);
  EXPECT_EQ(vehicle.limits[1].lo, 1);
  EXPECT_EQ(vehicle.limits[2].lo, -1);
  EXPECT_EQ(vehicle.limits[2].hi, -1);
  EXPECT_EQ(vehicle.limits[3].hi, 13);
  // A container element its validator refuses is left out, not inserted value-initialised.
  ASSERT_EQ(vehicle.more.size(), 1u);
  EXPECT_EQ(vehicle.more[0].hi, 2);
  EXPECT_TRUE(validate_limits(&vehicle.more[0]));
  EXPECT_EQ(report.count(Decision::Rejected), 6u) << report.to_text();
}

TEST_F(TaintedData, StrictModeRefusesTaintedCheckpointsAndWritesNothing) {
  tamper([](std::uint8_t* payload) { symcr::format::store16(payload + kHeading, 9999); });
  reset_reader();
  const std::vector<std::uint8_t> before = file_tests::snapshot(vehicle.sensor);
  symcr::RestoreOptions strict;
  strict.strict = true;
  symcr::Report report = symcr::restore(vehicle_schema(), path_.c_str(), strict);
  EXPECT_EQ(report.status().error(), symcr::Error::Strict) << report.to_text();
  EXPECT_EQ(file_tests::snapshot(vehicle.sensor), before);
  EXPECT_EQ(vehicle.heading, 1);

  tamper([](std::uint8_t* payload) {
    symcr::format::store32(payload + kLimits, 50);
  });  // limits[0] = {50, 10}
  report = symcr::restore(vehicle_schema(), path_.c_str(), strict);
  EXPECT_EQ(report.status().error(), symcr::Error::Strict) << report.to_text();
  EXPECT_EQ(vehicle.limits[0].lo, -1);

  // The untampered checkpoint restores in strict mode.
  file_tests::write_file(path_, record_);
  report = symcr::restore(vehicle_schema(), path_.c_str(), strict);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(vehicle.heading, 270);
}

TEST_F(TaintedData, BoundaryValuesAreAccepted) {
  tamper([](std::uint8_t* payload) {
    put_f32(payload + kAltitude, -100.0f);
    symcr::format::store32(payload + kThrottle, 100);
    put_f64(payload + kSpeed, 50.0);
    symcr::format::store16(payload + kHeading, 0);
    symcr::format::store32(payload + kLimits, 10);  // limits[0] = {10, 10}: lo <= hi holds
  });
  reset_reader();
  const symcr::Report report = symcr::restore(vehicle_schema(), path_.c_str());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(report.count(Decision::Rejected), 0u) << report.to_text();
  EXPECT_EQ(vehicle.sensor.altitude, -100.0f);
  EXPECT_EQ(vehicle.sensor.throttle, 100);
  EXPECT_EQ(vehicle.speed, 50.0);
  EXPECT_EQ(vehicle.heading, 0);
  EXPECT_EQ(vehicle.limits[0].lo, 10);
}

// Random tampering of every value byte, with the CRC fixed each time: whatever restore does,
// no live value ever breaks a rule, and a refused restore writes nothing.
TEST_F(TaintedData, RandomTamperingNeverBringsBackAValueThatBreaksARule) {
  std::mt19937 random(99);
  int tried = 0, rejected_values = 0, refused = 0;
  for (int round = 0; round < 3000; ++round) {
    const int edits = 1 + static_cast<int>(random() % 4);
    std::vector<std::pair<std::size_t, std::uint8_t>> changes;
    for (int e = 0; e < edits; ++e) {
      // Mostly inside the values, sometimes the counts and the trailing tables.
      changes.emplace_back(random() % kPayloadSize, static_cast<std::uint8_t>(random()));
    }
    tamper([&](std::uint8_t* payload) {
      for (auto& [at, byte] : changes) payload[at] = byte;
    });
    reset_reader();
    const std::vector<std::uint8_t> sensor_before = file_tests::snapshot(vehicle.sensor);
    const symcr::Report report = symcr::restore(vehicle_schema(), path_.c_str());
    ++tried;
    if (!report.ok()) {
      ++refused;
      ASSERT_EQ(file_tests::snapshot(vehicle.sensor), sensor_before) << report.to_text();
      ASSERT_EQ(vehicle.more.size(), 1u);
      ASSERT_EQ(vehicle.speed, 1);
    }
    rejected_values += static_cast<int>(report.count(Decision::Rejected));
    ASSERT_TRUE(rules_hold()) << "round " << round << "\n" << report.to_text();
  }
  std::printf("[ taint ] %d tampered checkpoints (CRC recomputed): %d refused as corrupt, %d "
              "values rejected by ranges or validators, none restored against a rule\n",
              tried, refused, rejected_values);
  EXPECT_GT(rejected_values, 500);
}

}  // namespace
}  // namespace reliability
