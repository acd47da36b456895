// docs/resolution.md, "container: its contents": world B, every standard container, string, optional,
// variant and unique_ptr, restored into a build that changed element types and kinds.
#include <gtest/gtest.h>

#include "encode.hpp"
#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"

namespace engine_tests {
namespace {

using symcr::Decision;

class WorldB : public ::testing::Test {
 protected:
  void SetUp() override {
    b0::Bag& bag = b0::bag;
    bag.vec = {1, -2, 300};
    bag.map = {{"a", 1}, {"b", 2}};
    bag.set = {5, 3, 9};
    bag.list = {b0::Item{1, 1.5}, b0::Item{2, 2.5}};
    bag.deque = {7, 8};
    bag.str = "hello";
    bag.wide = u"hi";
    bag.opt = b0::Item{3, 3.5};
    bag.opt_empty.reset();
    bag.var_item = b0::Item{4, 4.5};
    bag.var_gone = std::int32_t{5};
    bag.up.reset(new b0::Item{6, 6.5});
    bag.up_null.reset();

    b1::bag = b1::Bag();
    b1::bag.vec = {99};
    b1::bag.map = {{"stale", 1}};
    b1::bag.var_gone = std::string("keep");
    saved_ = save(b0::schema());
    report_ = load(saved_, b1::schema());
    ASSERT_TRUE(report_.ok()) << report_.to_text();
  }
  Saved saved_;
  symcr::Report report_;
};

TEST_F(WorldB, VectorElementsConverted) {
  EXPECT_EQ(b1::bag.vec, (std::vector<std::int32_t>{1, -2, 300}));
  expect_entry(report_, "bag.vec", Decision::Converted, "std::vector<int16> -> std::vector<int32>");
}

TEST_F(WorldB, MapRebuiltFromPairs) {
  ASSERT_EQ(b1::bag.map.size(), 2u);
  EXPECT_EQ(b1::bag.map.at("a"), 1);
  EXPECT_EQ(b1::bag.map.at("b"), 2);
  EXPECT_EQ(b1::bag.map.count("stale"), 0u);
  expect_entry(report_, "bag.map[].second", Decision::Converted, "int32 -> int64");
  expect_entry(report_, "bag.map[].first", Decision::Restored);
}

TEST_F(WorldB, SetBecomesVectorInIterationOrder) {
  EXPECT_EQ(b1::bag.set, (std::vector<std::int32_t>{3, 5, 9}));
  expect_entry(report_, "bag.set", Decision::Converted, "std::set<int32> -> std::vector<int32>");
}

TEST_F(WorldB, ListOfStructsWhoseElementGainedAField) {
  ASSERT_EQ(b1::bag.list.size(), 2u);
  EXPECT_EQ(b1::bag.list.front().id, 1);
  EXPECT_EQ(b1::bag.list.front().weight, 1.5);
  EXPECT_EQ(b1::bag.list.front().extra, 42);
  EXPECT_EQ(b1::bag.list.back().id, 2);
  EXPECT_EQ(b1::bag.list.back().weight, 2.5);
  expect_entry(report_, "bag.list[].extra", Decision::Kept, "added");
  expect_entry(report_, "bag.list[].id", Decision::Converted, "int32 -> int64");
}

TEST_F(WorldB, DequeRestored) {
  EXPECT_EQ(b1::bag.deque, (std::deque<std::int32_t>{7, 8}));
}

TEST_F(WorldB, StringsIncludingCharacterWidthChange) {
  EXPECT_EQ(b1::bag.str, "hello");
  EXPECT_EQ(b1::bag.wide, "hi");
  expect_entry(report_, "bag.wide", Decision::Converted, "re-encoded UTF-16 -> UTF-8");
  // Characters past ASCII are re-encoded by code point, not cut to 8 bits.
  b0::bag.wide = u"\u00e9\u4e2d\U0001F681";
  b1::bag.wide = "before";
  symcr::Report report = load(save(b0::schema()), b1::schema());
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(b1::bag.wide, "\xC3\xA9\xE4\xB8\xAD\xF0\x9F\x9A\x81");
  // A string that is not valid UTF-16 (an unpaired surrogate) is rejected, keeping the
  // reader's string.
  b0::bag.wide = std::u16string(u"ok") + char16_t{0xD800};
  b1::bag.wide = "before";
  report = load(save(b0::schema()), b1::schema());
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(b1::bag.wide, "before");
  bool found = false;
  for (const auto& e : report.entries()) {
    found = found || (e.path == "bag.wide" && e.decision == Decision::Rejected && e.lossy &&
                      e.detail.find("not valid UTF-16 at character 2") != std::string::npos);
  }
  EXPECT_TRUE(found) << report.to_text();
}

TEST_F(WorldB, OptionalEngagedAndEmpty) {
  ASSERT_TRUE(b1::bag.opt.has_value());
  EXPECT_EQ(b1::bag.opt->id, 3);
  EXPECT_EQ(b1::bag.opt->weight, 3.5);
  EXPECT_EQ(b1::bag.opt->extra, 42);
  EXPECT_FALSE(b1::bag.opt_empty.has_value());
}

TEST_F(WorldB, VariantAlternativeMatchedByTypeName) {
  ASSERT_EQ(b1::bag.var_item.index(), 2u);
  EXPECT_EQ(std::get<b1::Item>(b1::bag.var_item).id, 4);
  EXPECT_EQ(std::get<b1::Item>(b1::bag.var_item).weight, 4.5);
}

TEST_F(WorldB, VariantAlternativeRemovedIsRejected) {
  ASSERT_EQ(b1::bag.var_gone.index(), 0u);
  EXPECT_EQ(std::get<std::string>(b1::bag.var_gone), "keep");
  bool found = false;
  for (const auto& e : report_.entries()) {
    found = found || (e.path == "bag.var_gone" && e.decision == Decision::Rejected &&
                      e.detail == "alternative int32 not in this build");
  }
  EXPECT_TRUE(found) << report_.to_text();
}

TEST_F(WorldB, UniquePtrFilledAndReset) {
  ASSERT_NE(b1::bag.up, nullptr);
  EXPECT_EQ(b1::bag.up->id, 6);
  EXPECT_EQ(b1::bag.up->weight, 6.5);
  EXPECT_EQ(b1::bag.up_null, nullptr);
  // An object the new build already owns is filled in place.
  b1::Item* owned = new b1::Item();
  b1::bag.up.reset(owned);
  ASSERT_TRUE(load(saved_, b1::schema()).ok());
  EXPECT_EQ(b1::bag.up.get(), owned);
  EXPECT_EQ(owned->id, 6);
}

TEST_F(WorldB, EmptyContainersClearTheReader) {
  b0::bag.vec.clear();
  b0::bag.list.clear();
  b1::bag.vec = {1, 2};
  ASSERT_TRUE(load(save(b0::schema()), b1::schema()).ok());
  EXPECT_TRUE(b1::bag.vec.empty());
  EXPECT_TRUE(b1::bag.list.empty());
}

TEST_F(WorldB, IdentityRestoreOfEveryContainer) {
  const Saved saved = save(b0::schema());
  b0::bag = b0::Bag();
  const symcr::Report report = load(saved, b0::schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(b0::bag.vec, (std::vector<std::int16_t>{1, -2, 300}));
  EXPECT_EQ(b0::bag.set, (std::set<std::int32_t>{3, 5, 9}));
  EXPECT_EQ(b0::bag.map.at("b"), 2);
  EXPECT_EQ(b0::bag.wide, u"hi");
  EXPECT_EQ(std::get<std::int32_t>(b0::bag.var_gone), 5);
  EXPECT_EQ(std::get<b0::Item>(b0::bag.var_item).id, 4);
  ASSERT_NE(b0::bag.up, nullptr);
  EXPECT_EQ(b0::bag.up->id, 6);
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

TEST(WorldT, RecursiveTypeThroughAContainerPlansOnceAndRestores) {
  t0::tree = t0::Tree{1, {t0::Tree{2, {t0::Tree{3, {}}}}, t0::Tree{4, {}}}};
  t0::many.clear();
  t1::tree = t1::Tree();
  const symcr::Report report = load(save(t0::schema()), t1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(t1::tree.value, 1);
  ASSERT_EQ(t1::tree.children.size(), 2u);
  EXPECT_EQ(t1::tree.children[0].value, 2);
  ASSERT_EQ(t1::tree.children[0].children.size(), 1u);
  EXPECT_EQ(t1::tree.children[0].children[0].value, 3);
  EXPECT_EQ(t1::tree.children[1].value, 4);
  // Listed once, not expanded through the recursion.
  expect_entry(report, "tree.value", symcr::Decision::Converted, "int32 -> int64");
  EXPECT_NE(entry(report, "tree.children"), nullptr);
  EXPECT_EQ(entry(report, "tree.children[].value"), nullptr);

}

TEST(WorldT, ValueRejectionsAreCappedPerFieldWithASummary) {
  t0::tree = t0::Tree{0, {}};
  t0::many.assign(250, 1000);  // none fits int8
  t0::many[7] = 5;             // this one does
  t1::many.clear();
  const symcr::Report report = load(save(t0::schema()), t1::schema());
  ASSERT_TRUE(report.ok()) << report.status().message();
  // A rejected element is left out: no value-initialised 0 stands in for it.
  EXPECT_EQ(t1::many, (std::vector<std::int8_t>{5}));
  std::size_t concrete = 0;
  bool summary = false;
  for (const auto& e : report.entries()) {
    if (e.decision != symcr::Decision::Rejected) continue;
    if (e.path.rfind("many[", 0) == 0) ++concrete;
    if (e.detail == "and 149 more values rejected") summary = true;
  }
  EXPECT_EQ(concrete, 100u);
  EXPECT_TRUE(summary) << report.to_text();
  EXPECT_NE(entry(report, "many[0]"), nullptr);
  EXPECT_EQ(entry(report, "many[0]")->detail, "1000 out of range of int8");
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

t0::Tree chain(int depth) {
  t0::Tree root{0, {}};
  t0::Tree* at = &root;
  for (int i = 1; i < depth; ++i) {
    at->children.push_back(t0::Tree{i, {}});
    at = &at->children.back();
  }
  return root;
}

TEST(WorldT, DeepNestingWithinTheLimitRoundTripsBeyondItIsRefused) {
  t0::many.clear();
  t0::tree = chain(900);
  const Saved saved = save(t0::schema());
  const symcr::Report report = load(saved, t1::schema());
  ASSERT_TRUE(report.ok()) << report.status().message();
  const t1::Tree* at = &t1::tree;
  int depth = 1;
  while (!at->children.empty()) {
    at = &at->children[0];
    ++depth;
  }
  EXPECT_EQ(depth, 900);
  EXPECT_EQ(at->value, 899);

  t0::tree = chain(1100);
  std::vector<std::uint8_t> payload;
  const symcr::Status status = symcr::detail::encode_payload(t0::schema(), payload);
  EXPECT_EQ(status.error(), symcr::Error::Unsupported);
  EXPECT_NE(std::string(status.message()).find("nesting limit"), std::string::npos)
      << status.message();
  t0::tree = t0::Tree{};
  t1::tree = t1::Tree{};
}

}  // namespace
}  // namespace engine_tests
