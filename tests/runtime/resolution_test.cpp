// docs/resolution.md, rule by rule: world A (scalars, structs, arrays, unions, enums, bit-fields,
// roots) and world D (bases), saved by the old build (a0/d0) and restored into the patched
// build (a1/d1).
#include <gtest/gtest.h>

#include <cstring>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "parsed_schema.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"

namespace engine_tests {
namespace {

using symcr::Decision;

void set_writer_world_a() {
  a0::Basic& b = a0::basic;
  std::memset(&b, 0, sizeof b);
  b.heading = -123;
  b.narrow_fit = 1234;
  b.narrow_nofit = 70000;
  b.ratio = 0.5f;
  b.precise = 0.1;
  b.to_float_ok = 16777216;
  b.to_float_bad = 16777217;
  b.to_int_ok = 2.0;
  b.to_int_bad = 2.5;
  b.mode = a0::Mode::AUTO;
  b.mode_unknown = a0::Mode::GUIDED;
  b.removed = 5;
  b.same = 200;
  b.grow[0] = 1, b.grow[1] = 2, b.grow[2] = 3;
  b.shrink[0] = 1, b.shrink[1] = 2, b.shrink[2] = 3, b.shrink[3] = 4;
  b.inner = {10, 20, 1.5f};
  b.blob.word = 0x3f800000u;
  b.blob2.word = 7;
  b.kind_change = {1, 2, 3.0f};
  b.bits.a = 5;
  b.bits.b = 17;
  b.bits.c = -3;
  b.speed = 150;
  a0::old_counter = 4242;
  a0::gone_root = 1;
}

class WorldA : public ::testing::Test {
 protected:
  void SetUp() override {
    set_writer_world_a();
    a1::basic = a1::Basic();
    a1::counter = -1;
    a1::new_root = 99;
    saved_ = save(a0::schema());
    report_ = load(saved_, a1::schema());
    ASSERT_TRUE(report_.ok()) << report_.to_text();
  }
  Saved saved_;
  symcr::Report report_;
};

TEST_F(WorldA, RuleNoneRestoresEverythingIntoTheSameBuild) {
  a0::Basic before = a0::basic;
  const Saved saved = save(a0::schema());
  std::memset(&a0::basic, 0x55, sizeof a0::basic);
  a0::old_counter = 0;
  const symcr::Report report = load(saved, a0::schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(std::memcmp(&before.inner, &a0::basic.inner, sizeof before.inner), 0);
  EXPECT_EQ(a0::basic.heading, -123);
  EXPECT_EQ(a0::basic.narrow_nofit, 70000);
  EXPECT_EQ(a0::basic.to_int_bad, 2.5);
  EXPECT_EQ(a0::basic.mode_unknown, a0::Mode::GUIDED);
  EXPECT_EQ(a0::basic.bits.c, -3);
  EXPECT_EQ(a0::basic.bits.b, 17u);
  EXPECT_EQ(a0::basic.shrink[3], 4);
  EXPECT_EQ(a0::old_counter, 4242);
  EXPECT_EQ(report.count(Decision::Restored), report.entries().size()) << report.to_text();
}

TEST_F(WorldA, RuleFieldAddedKeepsTheNewBuildsValue) {
  EXPECT_EQ(a1::basic.added, 77);
  expect_entry(report_, "basic.added", Decision::Kept, "added", 0);
  EXPECT_EQ(a1::basic.inner.added_inner, 5);
  expect_entry(report_, "basic.inner.added_inner", Decision::Kept, "added", 0);
}

TEST_F(WorldA, RuleFieldRemovedIsDroppedAndLossy) {
  expect_entry(report_, "basic.removed", Decision::Dropped, "removed", 1);
}

TEST_F(WorldA, ARemovedAndAnAddedFieldOfOneTypeGetARenameHint) {
  // basic.removed and basic.added are both int32: perhaps a rename without its annotation.
  const char* hint =
      "; did you mean SYMCR_RENAMED_FROM(\"removed\") on added / renamed(Basic::added, removed)?";
  const symcr::ReportEntry* removed = entry(report_, "basic.removed");
  ASSERT_NE(removed, nullptr);
  EXPECT_EQ(removed->detail, std::string("field removed in this build") + hint);
  const symcr::ReportEntry* added = entry(report_, "basic.added");
  ASSERT_NE(added, nullptr);
  EXPECT_EQ(added->detail, std::string("field added in this build") + hint);
  // Inner gained an int32 but lost nothing: no hint there.
  const symcr::ReportEntry* inner = entry(report_, "basic.inner.added_inner");
  ASSERT_NE(inner, nullptr);
  EXPECT_EQ(inner->detail, "field added in this build");
}

TEST_F(WorldA, RuleReorderedFieldsMatchByName) {
  EXPECT_EQ(a1::basic.inner.first, 10);
  EXPECT_EQ(a1::basic.inner.second, 20);
  EXPECT_EQ(a1::basic.inner.third, 1.5f);
  EXPECT_EQ(a1::basic.same, 200);
  expect_entry(report_, "basic.inner.first", Decision::Restored);
  expect_entry(report_, "basic.same", Decision::Restored, "", 0);
}

TEST_F(WorldA, RuleRenamedFieldAndRootRestoreFromTheOldName) {
  EXPECT_EQ(a1::basic.yaw, -123);
  expect_entry(report_, "basic.yaw", Decision::Converted, "renamed from heading");
  EXPECT_EQ(a1::counter, 4242);
  expect_entry(report_, "counter", Decision::Converted, "renamed from old_counter");
}

TEST_F(WorldA, RuleIntegerWidened) {
  expect_entry(report_, "basic.yaw", Decision::Converted, "int16 -> int32", 0);
}

TEST_F(WorldA, RuleIntegerNarrowedValueFits) {
  EXPECT_EQ(a1::basic.narrow_fit, 1234);
  expect_entry(report_, "basic.narrow_fit", Decision::Converted, "int32 -> int16");
}

TEST_F(WorldA, RuleIntegerNarrowedValueDoesNotFitIsRejected) {
  EXPECT_EQ(a1::basic.narrow_nofit, -1);  // the new build's value stays
  // The schema-level entry plus the value-level rejection with its concrete path.
  int rejected = 0;
  for (const auto& e : report_.entries()) {
    if (e.path == "basic.narrow_nofit" && e.decision == Decision::Rejected) {
      ++rejected;
      EXPECT_NE(e.detail.find("70000 out of range of int16"), std::string::npos) << e.detail;
      EXPECT_TRUE(e.lossy);
    }
  }
  EXPECT_EQ(rejected, 1) << report_.to_text();
}

TEST_F(WorldA, RuleIntToFloatMustRoundTrip) {
  EXPECT_EQ(a1::basic.to_float_ok, 16777216.0f);
  EXPECT_EQ(a1::basic.to_float_bad, -1.0f);
  bool found = false;
  for (const auto& e : report_.entries()) {
    found = found || (e.path == "basic.to_float_bad" && e.decision == Decision::Rejected &&
                      e.detail.find("16777217 not exactly representable") != std::string::npos);
  }
  EXPECT_TRUE(found) << report_.to_text();
}

TEST_F(WorldA, RuleFloatToIntMustBeIntegral) {
  EXPECT_EQ(a1::basic.to_int_ok, 2);
  EXPECT_EQ(a1::basic.to_int_bad, -1);
  bool found = false;
  for (const auto& e : report_.entries()) {
    found = found || (e.path == "basic.to_int_bad" && e.decision == Decision::Rejected &&
                      e.detail.find("2.5") != std::string::npos);
  }
  EXPECT_TRUE(found) << report_.to_text();
}

TEST_F(WorldA, RuleFloatDoubleConverted) {
  EXPECT_EQ(a1::basic.ratio, 0.5);
  EXPECT_EQ(a1::basic.precise, 0.1f);
  expect_entry(report_, "basic.ratio", Decision::Converted, "float32 -> float64", 0);
  expect_entry(report_, "basic.precise", Decision::Converted, "float64 -> float32", 1);
}

TEST_F(WorldA, RuleEnumByNameAndUnknownNameRejected) {
  EXPECT_EQ(a1::basic.mode, a1::Mode::AUTO);
  EXPECT_EQ(static_cast<int>(a1::basic.mode), 5);
  EXPECT_EQ(a1::basic.mode_unknown, a1::Mode::RTL);
  expect_entry(report_, "basic.mode", Decision::Converted, "GUIDED not in this build");
  bool found = false;
  for (const auto& e : report_.entries()) {
    found = found || (e.path == "basic.mode_unknown" && e.decision == Decision::Rejected &&
                      e.detail == "enum GUIDED not in this build");
  }
  EXPECT_TRUE(found) << report_.to_text();
}

TEST_F(WorldA, RuleArrayGrowsKeepsTheRest) {
  EXPECT_EQ(a1::basic.grow[0], 1);
  EXPECT_EQ(a1::basic.grow[1], 2);
  EXPECT_EQ(a1::basic.grow[2], 3);
  EXPECT_EQ(a1::basic.grow[3], -1);
  EXPECT_EQ(a1::basic.grow[4], -1);
  expect_entry(report_, "basic.grow", Decision::Converted, "array grows 3 -> 5", 0);
}

TEST_F(WorldA, RuleArrayShrinksIsLossy) {
  EXPECT_EQ(a1::basic.shrink[0], 1);
  EXPECT_EQ(a1::basic.shrink[1], 2);
  expect_entry(report_, "basic.shrink", Decision::Converted, "array shrinks 4 -> 2", 1);
}

TEST_F(WorldA, RuleUnionSameSizeIsRawBytes) {
  EXPECT_EQ(a1::basic.blob.word, 0x3f800000u);
  EXPECT_EQ(a1::basic.blob.real, 1.0f);
  expect_entry(report_, "basic.blob", Decision::Restored);
}

TEST_F(WorldA, RuleUnionSizeChangedIsRejected) {
  EXPECT_EQ(a1::basic.blob2.wide, 0u);
  expect_entry(report_, "basic.blob2", Decision::Rejected, "union size changed: 4 -> 8", 1);
}

TEST_F(WorldA, RuleIncompatibleKindsRejected) {
  EXPECT_EQ(a1::basic.kind_change, -1);
  expect_entry(report_, "basic.kind_change", Decision::Rejected, "incompatible kinds: struct Inner -> int int32", 1);
}

TEST_F(WorldA, BitFieldsAreRestoredByName) {
  EXPECT_EQ(a1::basic.bits.a, 5u);
  EXPECT_EQ(a1::basic.bits.b, 17u);
  EXPECT_EQ(a1::basic.bits.c, -3);
}

TEST_F(WorldA, RangeValidationRejectsOutOfRangeValues) {
  EXPECT_EQ(a1::basic.speed, -1);
  bool found = false;
  for (const auto& e : report_.entries()) {
    found = found || (e.path == "basic.speed" && e.decision == Decision::Rejected &&
                      e.detail.find("150 outside [0, 100]") != std::string::npos);
  }
  EXPECT_TRUE(found) << report_.to_text();
  a0::basic.speed = 50;
  const symcr::Report again = load(save(a0::schema()), a1::schema());
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(a1::basic.speed, 50);
}

TEST_F(WorldA, RootsRemovedAndAdded) {
  expect_entry(report_, "gone_root", Decision::Dropped, "root not in this build", 1);
  expect_entry(report_, "new_root", Decision::Kept, "root added", 0);
  EXPECT_EQ(a1::new_root, 99);
}

TEST_F(WorldA, StrictModeRefusesLossyAndLeavesStateUntouched) {
  a1::basic = a1::Basic();
  a1::counter = -1;
  unsigned char before[sizeof(a1::Basic)];
  std::memcpy(before, &a1::basic, sizeof before);
  const symcr::Report strict = load(saved_, a1::schema(), /*strict=*/true);
  EXPECT_FALSE(strict.ok());
  EXPECT_EQ(strict.status().error(), symcr::Error::Strict);
  EXPECT_EQ(std::memcmp(before, &a1::basic, sizeof before), 0);
  EXPECT_EQ(a1::counter, -1);
  // Default mode applies the same checkpoint and reports.
  const symcr::Report lenient = load(saved_, a1::schema());
  EXPECT_TRUE(lenient.ok());
  EXPECT_EQ(a1::counter, 4242);
}

TEST_F(WorldA, ReportRendersAsTextAndJson) {
  const std::string text = report_.to_text();
  EXPECT_NE(text.find("basic.yaw"), std::string::npos);
  const std::string json = report_.to_json();
  EXPECT_EQ(json.rfind("{\"ok\":true", 0), 0u) << json;
  EXPECT_NE(json.find("\"path\":\"basic.removed\",\"decision\":\"dropped\""), std::string::npos);
}

TEST(WorldD, BasesMatchByClassName) {
  d0::derived.id = 1;
  d0::derived.g = 2;
  d0::derived.x = 3;
  d1::derived = d1::Derived();
  const symcr::Report report = load(save(d0::schema()), d1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(d1::derived.id, 1);
  EXPECT_EQ(d1::derived.x, 3);
  EXPECT_EQ(d1::derived.base_added, 11);
  EXPECT_EQ(d1::derived.e, 21);
  expect_entry(report, "derived.Gone", Decision::Dropped, "removed", 1);  // base removed
  expect_entry(report, "derived.Extra", Decision::Kept, "added", 0);      // base added
  expect_entry(report, "derived.Base.base_added", Decision::Kept, "added", 0);  // base gains a field
  expect_entry(report, "derived.Base.id", Decision::Restored);
}

TEST(WorldA2, IncompatibleWhenNothingCanBeRestored) {
  // Restoring world D's checkpoint into world A's build: no root matches.
  const symcr::Report report = load(save(d0::schema()), a1::schema());
  EXPECT_FALSE(report.ok());
  EXPECT_EQ(report.status().error(), symcr::Error::Incompatible);
  expect_entry(report, "derived", Decision::Dropped);
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

TEST(WorldA3, PlanPayloadReportsWithoutWritingEvenWithoutAddresses) {
  set_writer_world_a();
  const Saved saved = save(a0::schema());
  // The reader as another build's schema file: parsed, roots without addresses.
  const auto& reader_blob = symcr::detail::schema_blob(a1::schema());
  symcr::detail::ParsedSchema reader;
  ASSERT_TRUE(symcr::detail::parse_schema(reader_blob.data, reader_blob.size,
                                          reader).ok());
  symcr::detail::ParsedSchema writer;
  ASSERT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), writer).ok());
  a1::basic = a1::Basic();
  const symcr::Report plan = symcr::detail::plan_payload(
      writer.schema(), saved.hash, saved.payload.data(), saved.payload.size(), reader.schema(), {});
  ASSERT_TRUE(plan.ok()) << plan.to_text();
  expect_entry(plan, "basic.yaw", symcr::Decision::Converted, "renamed from heading");
  expect_entry(plan, "basic.narrow_nofit", symcr::Decision::Rejected, "70000 out of range");
  EXPECT_EQ(a1::basic.yaw, -1);  // nothing written
  const symcr::Report schema_only = symcr::detail::plan_payload(
      writer.schema(), saved.hash, nullptr, 0, reader.schema(), {});
  ASSERT_TRUE(schema_only.ok());
  expect_entry(schema_only, "basic.removed", symcr::Decision::Dropped);
  EXPECT_EQ(symcr::detail::plan_payload(writer.schema(), saved.hash, saved.payload.data(),
                                        saved.payload.size(), reader.schema(), {true})
                .status()
                .error(),
            symcr::Error::Strict);
}

}  // namespace
}  // namespace engine_tests
