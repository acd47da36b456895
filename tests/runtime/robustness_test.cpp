// Hostile and damaged payloads: every truncation and every single-bit flip of a small payload
// either fails cleanly with the live state byte-identical, or (a flip that still decodes)
// restores without crashing. Also validators (symcr_validate) checked before writing.
#include <gtest/gtest.h>

#include <cstring>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "visit.hpp"

namespace engine_tests {
namespace {

using symcr::Decision;

void set_writer_world_e() {
  e0::small.a = -5;
  e0::small.flag = 7;
  e0::small.on = true;
  e0::small.d = 3.25;
  e0::small.v = {1, 2, 3};
  e0::small.s = "writer";
  e0::small.arr[0] = 4, e0::small.arr[1] = 5, e0::small.arr[2] = 6;
  e0::small.p = &e0::small.arr[1];
  e0::good = {1, 2};
  e0::bad = {5, 1};
}

struct ReaderSnapshot {
  e1::Small small;
  e1::Checked good, bad;
  static ReaderSnapshot take() { return {e1::small, e1::good, e1::bad}; }
  bool same_as_live() const {
    return small == e1::small && good.lo == e1::good.lo && good.hi == e1::good.hi &&
           bad.lo == e1::bad.lo && bad.hi == e1::bad.hi;
  }
};

void reset_reader() {
  e1::small = e1::Small();
  e1::good = e1::Checked();
  e1::bad = e1::Checked();
}

TEST(WorldE, RestoresSmallStateAndValidatesBeforeWriting) {
  set_writer_world_e();
  reset_reader();
  const symcr::Report report = load(save(e0::schema()), e1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(e1::small.a, -5);
  EXPECT_EQ(e1::small.flag, 7);
  EXPECT_TRUE(e1::small.on);
  EXPECT_EQ(e1::small.d, 3.25);
  EXPECT_EQ(e1::small.v, (std::vector<std::int16_t>{1, 2, 3}));
  EXPECT_EQ(e1::small.s, "writer");
  EXPECT_EQ(e1::small.p, &e1::small.arr[1]);
  EXPECT_EQ(e1::good.lo, 1);
  EXPECT_EQ(e1::good.hi, 2);
  // bad = {5, 1} fails lo <= hi: nothing of it is written.
  EXPECT_EQ(e1::bad.lo, -1);
  EXPECT_EQ(e1::bad.hi, -1);
  bool found = false;
  for (const auto& e : report.entries()) {
    found = found || (e.path == "bad" && e.decision == Decision::Rejected &&
                      e.detail.find("symcr_validate") != std::string::npos);
  }
  EXPECT_TRUE(found) << report.to_text();
  // Strict mode counts the failed validation as lossy.
  reset_reader();
  const symcr::Report strict = load(save(e0::schema()), e1::schema(), /*strict=*/true);
  EXPECT_EQ(strict.status().error(), symcr::Error::Strict);
  EXPECT_EQ(e1::good.lo, -1);
}

TEST(WorldE, EveryTruncationFailsWithStateUntouched) {
  set_writer_world_e();
  const Saved saved = save(e0::schema());
  reset_reader();
  e1::small.v = {4, 4, 4};
  const ReaderSnapshot before = ReaderSnapshot::take();
  for (std::size_t size = 0; size < saved.payload.size(); ++size) {
    const symcr::Report report = load(saved, e1::schema(), false, size);
    ASSERT_FALSE(report.ok()) << size;
    EXPECT_EQ(report.status().error(), symcr::Error::Corrupt) << size;
    ASSERT_TRUE(before.same_as_live()) << "state changed by a payload truncated to " << size;
  }
}

TEST(WorldE, EveryBitFlipFailsCleanlyOrDecodes) {
  set_writer_world_e();
  const Saved pristine = save(e0::schema());
  std::size_t refused = 0, applied = 0;
  for (std::size_t bit = 0; bit < pristine.payload.size() * 8; ++bit) {
    Saved flipped = pristine;
    flipped.payload[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    reset_reader();
    const ReaderSnapshot before = ReaderSnapshot::take();
    const symcr::Report report = load(flipped, e1::schema());
    if (!report.ok()) {
      ++refused;
      ASSERT_TRUE(before.same_as_live()) << "state changed by a refused payload, bit " << bit;
    } else {
      ++applied;
    }
  }
  // Lengths, counts, flags and references are checked: many flips must be refused.
  EXPECT_GT(refused, 40u);
  EXPECT_GT(applied, 100u);
}

TEST(WorldE, BitFlipsInContainerAndPointerWorldsNeverCrash) {
  b0::bag.vec = {1, 2};
  b0::bag.map = {{"k", 1}};
  b0::bag.str = "s";
  b0::bag.list = {b0::Item{1, 2.0}};
  b0::bag.up.reset();
  const Saved pristine = save(b0::schema());
  for (std::size_t bit = 0; bit < pristine.payload.size() * 8; ++bit) {
    Saved flipped = pristine;
    flipped.payload[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    b1::bag = b1::Bag();
    const symcr::Report report = load(flipped, b1::schema());
    (void)report;  // either outcome is fine; the sanitizers watch for the rest
  }
  b1::bag = b1::Bag();
}

TEST(WorldE, TrailingBytesAreCorrupt) {
  set_writer_world_e();
  Saved saved = save(e0::schema());
  saved.payload.push_back(0);
  reset_reader();
  const symcr::Report report = load(saved, e1::schema());
  EXPECT_EQ(report.status().error(), symcr::Error::Corrupt);
  EXPECT_EQ(e1::small.a, -1);
}

}  // namespace
}  // namespace engine_tests

namespace engine_tests {
namespace {

struct CountingVisitor : symcr::detail::ValueVisitor {
  std::size_t leaves = 0;
  void leaf(const char*, const symcr::TypeInfo&, const std::uint8_t*, std::size_t,
            const char*) override {
    ++leaves;
  }
};

TEST(WorldE, VisitingDamagedPointerPayloadsNeverCrashes) {
  // A small pointer world: a root with a pointer into itself and a heap node.
  c0::world = c0::World();
  auto* node = new c0::Node{7, nullptr, nullptr};
  node->next = node;
  c0::world.head = node;
  c0::world.target_ptr = &c0::world.nav.target[1];
  c0::world.navs.resize(2);
  c0::world.pick = &c0::world.navs[1];
  const Saved pristine = save(c0::schema());
  c0::world = c0::World();
  delete node;
  CountingVisitor baseline;
  ASSERT_TRUE(symcr::detail::visit_payload(c0::schema(), pristine.payload.data(),
                                           pristine.payload.size(), baseline).ok());
  std::size_t refused = 0;
  for (std::size_t bit = 0; bit < pristine.payload.size() * 8; ++bit) {
    std::vector<std::uint8_t> flipped = pristine.payload;
    flipped[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    CountingVisitor visitor;
    if (!symcr::detail::visit_payload(c0::schema(), flipped.data(), flipped.size(), visitor).ok()) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 0u);
  for (std::size_t size = 0; size < pristine.payload.size(); ++size) {
    CountingVisitor visitor;
    EXPECT_FALSE(symcr::detail::visit_payload(c0::schema(), pristine.payload.data(), size, visitor).ok());
  }
}

}  // namespace
}  // namespace engine_tests
