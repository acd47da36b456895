// In-process state transfer (symcr::transfer): build A's roots moved into build B's, both in
// this binary (file_test_schemas.hpp), must give what a restore of A's checkpoint into B gives,
// and a refused transfer must leave both builds' state as it was.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {
namespace {

using symcr::Error;

void reset_b() {
  copter_b = CopterB{};
  telemetry_b = Telemetry{};
}

std::vector<std::string> decisions(const symcr::Report& report) {
  std::vector<std::string> out;
  for (const symcr::ReportEntry& entry : report.entries()) {
    out.push_back(entry.path + " " + symcr::decision_name(entry.decision) + " " + entry.detail);
  }
  return out;
}

TEST(TransferTest, MovesTheStateAsARestoreOfTheCheckpointWould) {
  fill_a(6);
  const std::vector<std::uint8_t> source = state_a();
  std::vector<std::uint8_t> checkpoint;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, checkpoint).ok());
  reset_b();
  const symcr::Report restored =
      symcr::restore_from_buffer(schema_b, checkpoint.data(), checkpoint.size());
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  const std::vector<std::uint8_t> expected = state_b();

  reset_b();
  const symcr::Report moved = symcr::transfer(schema_a, schema_b);
  ASSERT_TRUE(moved.ok()) << moved.status().message();
  EXPECT_EQ(state_b(), expected);
  EXPECT_EQ(decisions(moved), decisions(restored));
  EXPECT_EQ(state_a(), source) << "the transfer wrote into its source";
  // The values themselves, by name: reordered, widened, dropped and added fields.
  EXPECT_EQ(copter_b.ticks, 1006);
  EXPECT_EQ(copter_b.mission.items[2].speed, 62);
  EXPECT_EQ(copter_b.geofence, 77);  // added in B: B's initial value is kept
  EXPECT_EQ(telemetry_b.frames, 42u);
  EXPECT_EQ(moved.count(symcr::Decision::Kept), 1u);
  EXPECT_EQ(moved.count(symcr::Decision::Dropped), 1u);
}

TEST(TransferTest, APreparedTransferGivesTheSameState) {
  fill_a(3);
  ASSERT_TRUE(symcr::prepare_transfer(schema_a, schema_b).ok());
  reset_b();
  ASSERT_TRUE(symcr::transfer(schema_a, schema_b).ok());
  EXPECT_EQ(copter_b.ticks, 1003);
  EXPECT_EQ(telemetry_b.rssi, -3);
  // Again, from changed values: nothing of the first transfer is kept.
  fill_a(4);
  ASSERT_TRUE(symcr::transfer(schema_a, schema_b).ok());
  EXPECT_EQ(copter_b.ticks, 1004);
  EXPECT_EQ(telemetry_b.rssi, -4);
}

TEST(TransferTest, ARefusedTransferLeavesBothBuildsAsTheyWere) {
  fill_a(5);
  const std::vector<std::uint8_t> source = state_a();
  reset_b();
  copter_b.ticks = 99;
  const std::vector<std::uint8_t> target = state_b();
  symcr::RestoreOptions strict;
  strict.strict = true;  // B drops armed_ms: lossy
  const symcr::Report refused = symcr::transfer(schema_a, schema_b, strict);
  EXPECT_EQ(refused.status().error(), Error::Strict) << refused.status().message();
  EXPECT_EQ(state_b(), target) << "a refused transfer wrote into the new build";
  EXPECT_EQ(state_a(), source);
}

TEST(TransferTest, AnotherProgramIsRefusedUnlessAccepted) {
  static symcr::Schema rover = schema_a;
  static symcr::Schema copter = schema_b;
  rover.program = "rover";
  copter.program = "copter";
  fill_a(2);
  reset_b();
  const std::vector<std::uint8_t> target = state_b();
  const symcr::Report refused = symcr::transfer(rover, copter);
  EXPECT_EQ(refused.status().error(), Error::Incompatible);
  EXPECT_EQ(state_b(), target);
  symcr::RestoreOptions accept;
  accept.accept_other_program = true;
  ASSERT_TRUE(symcr::transfer(rover, copter, accept).ok());
  EXPECT_EQ(copter_b.ticks, 1002);
}

TEST(TransferTest, OneBuildIntoItselfIsRefused) {
  fill_a(1);
  const std::vector<std::uint8_t> source = state_a();
  EXPECT_EQ(symcr::transfer(schema_a, schema_a).status().error(), Error::Incompatible);
  EXPECT_EQ(symcr::prepare_transfer(schema_a, schema_a).error(), Error::Incompatible);
  EXPECT_EQ(state_a(), source);
}

}  // namespace
}  // namespace file_tests
