// The engine's fast paths behave exactly like the general ones: contiguous containers of
// fixed-width scalars moved as one block (save and restore, with pointers into their
// elements), copy-only structs (identical layouts: bools still checked, all-or-nothing kept),
// and large arrays appended to the output without zero-fill, and whole copy-only payloads
// (every root copy-only: restored without the general decoder, which still names every fault).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <deque>
#include <vector>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "parsed_schema.hpp"
#include "plan.hpp"
#include "report_access.hpp"
#include "restore_payload.hpp"
#include "scratch.hpp"
#include "symcr/device.hpp"
#include "symcr/ops.hpp"

namespace engine_tests {
namespace {

struct VRoot {
  std::vector<double> doubles;
  std::vector<std::int32_t> ints;
  std::int32_t* into = nullptr;   // points into `ints`
  std::deque<std::int32_t> bits;  // not contiguous: the general path
};
VRoot vroot;

const symcr::Schema& vroot_schema() {
  using symcr::ops::offset_of;
  static const symcr::FieldInfo fields[] = {
      field("doubles", 2, offset_of(&VRoot::doubles)), field("ints", 3, offset_of(&VRoot::ints)),
      field("into", 4, offset_of(&VRoot::into)), field("bits", 6, offset_of(&VRoot::bits))};
  static const symcr::TypeInfo types[] = {
      scalar("double", Kind::Float, 8),
      scalar("int32", Kind::Int, 4),
      holder("std::vector<double>", Kind::Container, sizeof(std::vector<double>),
             alignof(std::vector<double>), 0, &symcr::ops::container<std::vector<double>>::table),
      holder("std::vector<int32>", Kind::Container, sizeof(std::vector<std::int32_t>),
             alignof(std::vector<std::int32_t>), 1,
             &symcr::ops::container<std::vector<std::int32_t>>::table),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      scalar("int64", Kind::Int, 8),
      holder("std::deque<int32>", Kind::Container, sizeof(std::deque<std::int32_t>),
             alignof(std::deque<std::int32_t>), 1,
             &symcr::ops::container<std::deque<std::int32_t>>::table, symcr::ContainerKind::Deque),
      record("VRoot", sizeof(VRoot), alignof(VRoot), fields, 4),
  };
  static const symcr::RootInfo roots[] = {{"vroot", 7, &vroot, 0, nullptr}};
  static const symcr::Schema schema{types, 8, roots, 1, nullptr};
  return schema;
}

TEST(FastPath, ContainerOpsTablesDescribeContiguity) {
  EXPECT_NE(symcr::ops::container<std::vector<double>>::table.contiguous_data, nullptr);
  EXPECT_NE(symcr::ops::container<std::vector<double>>::table.resize_default, nullptr);
  EXPECT_EQ(symcr::ops::container<std::deque<int>>::table.contiguous_data, nullptr);
  EXPECT_EQ(symcr::ops::container<std::deque<int>>::table.resize_default, nullptr);
}

TEST(FastPath, ContiguousScalarContainersRoundTripWithPointersIntoThem) {
  vroot.doubles.clear();
  for (int i = 0; i < 10000; ++i) vroot.doubles.push_back(i * 0.5 - 7);
  vroot.ints = {5, 6, 7, 8, 9};
  vroot.into = &vroot.ints[3];
  vroot.bits = {4, -4, 44};
  const Saved saved = save(vroot_schema());
  const std::vector<double> doubles = vroot.doubles;
  vroot.doubles = {1, 2};
  vroot.ints = {0};
  vroot.into = nullptr;
  vroot.bits.clear();
  const symcr::Report report = load(saved, vroot_schema(), /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(vroot.doubles, doubles);
  EXPECT_EQ(vroot.ints, (std::vector<std::int32_t>{5, 6, 7, 8, 9}));
  EXPECT_EQ(vroot.into, &vroot.ints[3]);
  EXPECT_EQ(vroot.bits, (std::deque<std::int32_t>{4, -4, 44}));
}

TEST(FastPath, EmptyContiguousContainersClearTheReader) {
  vroot.doubles.clear();
  vroot.ints.clear();
  vroot.into = nullptr;
  vroot.bits.clear();
  const Saved saved = save(vroot_schema());
  vroot.doubles = {1};
  vroot.ints = {2};
  const symcr::Report report = load(saved, vroot_schema(), true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(vroot.doubles.empty());
  EXPECT_TRUE(vroot.ints.empty());
}

TEST(FastPath, TruncatedContiguousContainerFailsWithStateUntouched) {
  vroot.doubles.assign(100, 2.5);
  vroot.ints = {1, 2, 3};
  vroot.into = nullptr;
  vroot.bits.clear();
  const Saved saved = save(vroot_schema());
  vroot.doubles = {9};
  vroot.ints = {8};
  for (std::size_t size :
       {std::size_t{3}, std::size_t{4}, std::size_t{4 + 8 * 50}, std::size_t{4 + 8 * 100 + 6}}) {
    const symcr::Report report = load(saved, vroot_schema(), false, size);
    EXPECT_FALSE(report.ok()) << size;
    EXPECT_EQ(vroot.doubles, (std::vector<double>{9})) << size;
    EXPECT_EQ(vroot.ints, (std::vector<std::int32_t>{8})) << size;
  }
}

// A flat struct restored into the same build takes the copy-only path.
struct Flat {
  std::int32_t a;
  bool flag;
  double b;
  std::int16_t c[3];
  bool flags[2];
};
Flat flat;

const symcr::Schema& flat_schema() {
  static const symcr::FieldInfo fields[] = {
      field("a", 0, offsetof(Flat, a)), field("flag", 1, offsetof(Flat, flag)),
      field("b", 2, offsetof(Flat, b)), field("c", 4, offsetof(Flat, c)),
      field("flags", 5, offsetof(Flat, flags))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("bool", Kind::Bool, 1),
      scalar("double", Kind::Float, 8),
      scalar("int16", Kind::Int, 2),
      array("int16[3]", 3, 3, 6, 2),
      array("bool[2]", 1, 2, 2, 1),
      record("Flat", sizeof(Flat), alignof(Flat), fields, 5),
  };
  static const symcr::RootInfo roots[] = {{"flat", 6, &flat, 0, nullptr}};
  static const symcr::Schema schema{types, 7, roots, 1, nullptr};
  return schema;
}

TEST(FastPath, CopyOnlyStructRoundTrips) {
  flat = Flat{-5, true, 2.25, {1, -2, 3}, {false, true}};
  const Saved saved = save(flat_schema());
  ASSERT_EQ(saved.payload.size(), 4 + 1 + 8 + 6 + 2 + 4 + 4u);  // values, heap and reference counts
  std::memset(&flat, 0, sizeof flat);
  const symcr::Report report = load(saved, flat_schema(), true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(flat.a, -5);
  EXPECT_TRUE(flat.flag);
  EXPECT_EQ(flat.b, 2.25);
  EXPECT_EQ(flat.c[1], -2);
  EXPECT_FALSE(flat.flags[0]);
  EXPECT_TRUE(flat.flags[1]);
  expect_entry(report, "flat", symcr::Decision::Restored);
}

TEST(FastPath, CopyOnlyStructStillRefusesInvalidBools) {
  flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  const std::size_t bool_offsets[] = {4, 4 + 1 + 8 + 6, 4 + 1 + 8 + 6 + 1};
  for (std::size_t offset : bool_offsets) {
    Saved saved = save(flat_schema());
    saved.payload[offset] = 2;
    flat = Flat{7, false, 7.0, {7, 7, 7}, {false, false}};
    const symcr::Report report = load(saved, flat_schema());
    EXPECT_FALSE(report.ok()) << offset;
    EXPECT_NE(std::string(report.status().message()).find("bool value 2"), std::string::npos)
        << report.status().message();
    EXPECT_EQ(flat.a, 7) << offset;  // nothing written
    EXPECT_EQ(flat.c[0], 7) << offset;
    flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  }
}

// The same values in another build: fields reordered and one added, a second root.
struct FlatMoved {
  bool flags[2];
  double b;
  std::int64_t added;
  std::int16_t c[3];
  bool flag;
  std::int32_t a;
};
FlatMoved flat_moved;
std::int32_t counter_root;

const symcr::Schema& flat_moved_schema() {
  static const symcr::FieldInfo fields[] = {
      field("flags", 5, offsetof(FlatMoved, flags)), field("b", 2, offsetof(FlatMoved, b)),
      field("added", 7, offsetof(FlatMoved, added)), field("c", 4, offsetof(FlatMoved, c)),
      field("flag", 1, offsetof(FlatMoved, flag)),   field("a", 0, offsetof(FlatMoved, a))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("bool", Kind::Bool, 1),
      scalar("double", Kind::Float, 8),
      scalar("int16", Kind::Int, 2),
      array("int16[3]", 3, 3, 6, 2),
      array("bool[2]", 1, 2, 2, 1),
      record("Flat", sizeof(FlatMoved), alignof(FlatMoved), fields, 6),
      scalar("int64", Kind::Int, 8),
  };
  static const symcr::RootInfo roots[] = {{"counter", 0, &counter_root, 0, nullptr},
                                          {"flat", 6, &flat_moved, 0, nullptr}};
  static const symcr::Schema schema{types, 8, roots, 2, nullptr};
  return schema;
}

std::shared_ptr<const symcr::detail::Plan> plan(const Saved& saved, const symcr::Schema& reader,
                                                symcr::detail::ParsedSchema& writer) {
  EXPECT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), writer).ok());
  symcr::Status status;
  return symcr::detail::plan_for(writer.schema(), saved.hash, reader, status);
}

TEST(FastPath, PlansKnowWhenTheWholePayloadIsCopyOnly) {
  flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  symcr::detail::ParsedSchema writer;
  const Saved saved = save(flat_schema());
  const auto same = plan(saved, flat_schema(), writer);
  ASSERT_TRUE(same);
  EXPECT_TRUE(same->copy_only_payload);
  EXPECT_EQ(same->copy_only_payload_size, saved.payload.size());
  EXPECT_TRUE(plan(saved, flat_moved_schema(), writer)->copy_only_payload);  // moves only

  vroot.doubles = {1};
  symcr::detail::ParsedSchema containers;
  EXPECT_FALSE(plan(save(vroot_schema()), vroot_schema(), containers)->copy_only_payload);
}

TEST(FastPath, CopyOnlyPayloadRestoresIntoMovedFieldsAndKeepsAddedOnes) {
  flat = Flat{-5, true, 2.25, {1, -2, 3}, {false, true}};
  const Saved saved = save(flat_schema());
  flat_moved = FlatMoved{{true, true}, 0, 77, {0, 0, 0}, false, 0};
  counter_root = 41;
  const symcr::Report report = load(saved, flat_moved_schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(flat_moved.a, -5);
  EXPECT_TRUE(flat_moved.flag);
  EXPECT_EQ(flat_moved.b, 2.25);
  EXPECT_EQ(flat_moved.c[0], 1);
  EXPECT_EQ(flat_moved.c[1], -2);
  EXPECT_EQ(flat_moved.c[2], 3);
  EXPECT_FALSE(flat_moved.flags[0]);
  EXPECT_TRUE(flat_moved.flags[1]);
  EXPECT_EQ(flat_moved.added, 77);  // added field: the new build's value
  EXPECT_EQ(counter_root, 41);      // added root: untouched
  expect_entry(report, "flat.added", symcr::Decision::Kept);
  expect_entry(report, "counter", symcr::Decision::Kept);
}

TEST(FastPath, CopyOnlyPayloadFaultsAreNamedAndWriteNothing) {
  flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  const Saved good = save(flat_schema());
  const std::size_t values = good.payload.size() - 8;
  struct Case {
    const char* what;
    std::vector<std::uint8_t> payload;
    const char* message;
  };
  std::vector<Case> cases;
  cases.push_back({"heap count", good.payload, "heap count"});
  cases.back().payload[values] = 1;
  cases.push_back({"reference count", good.payload, "reference count"});
  cases.back().payload[values + 4] = 1;
  cases.push_back({"extra byte", good.payload, "after the payload"});
  cases.back().payload.push_back(0);
  cases.push_back({"short", good.payload, "truncated"});
  cases.back().payload.pop_back();
  for (const Case& c : cases) {
    Saved saved = good;
    saved.payload = c.payload;
    flat = Flat{7, false, 7.0, {7, 7, 7}, {false, false}};
    const symcr::Report report = load(saved, flat_schema());
    EXPECT_FALSE(report.ok()) << c.what;
    EXPECT_NE(std::string(report.status().message()).find(c.message), std::string::npos)
        << c.what << ": " << report.status().message();
    EXPECT_EQ(flat.a, 7) << c.what;  // nothing written
    EXPECT_EQ(flat.b, 7.0) << c.what;
    EXPECT_FALSE(flat.flag) << c.what;
  }
}

TEST(FastPath, CopyOnlyPayloadInStrictModeStillRefusesLossyPlans) {
  // Writer has a root the reader lacks: a dropped root is lossy, and the plan is not copy-only.
  flat_moved = FlatMoved{{true, false}, 3.5, 0, {4, 5, 6}, true, 9};
  counter_root = 12;
  const Saved saved = save(flat_moved_schema());
  flat = Flat{7, false, 7.0, {7, 7, 7}, {false, false}};
  const symcr::Report strict = load(saved, flat_schema(), true);
  EXPECT_FALSE(strict.ok());
  EXPECT_EQ(strict.status().error(), symcr::Error::Strict);
  EXPECT_EQ(flat.a, 7);
  const symcr::Report lenient = load(saved, flat_schema());
  ASSERT_TRUE(lenient.ok()) << lenient.to_text();
  EXPECT_EQ(flat.a, 9);
  EXPECT_EQ(flat.c[2], 6);
  expect_entry(lenient, "counter", symcr::Decision::Dropped);
}

// Integer bit-fields keep a struct copy-only: their values are checked against the widths and
// inserted bit by bit.
struct Bits {
  std::uint8_t flag : 1;
  std::uint8_t mode : 3;
  std::int16_t delta : 5;
  bool on : 1;
  std::int32_t whole;
};
Bits bits;

// The first bit `set` turns on in a zeroed Bits: the bit-field's position from the struct's
// start (the schema's storage unit is then offset 0).
template <class Set>
std::uint16_t bit_position(Set set) {
  Bits probe;
  std::memset(&probe, 0, sizeof probe);
  set(probe);
  unsigned char bytes[sizeof probe];
  std::memcpy(bytes, &probe, sizeof probe);
  for (std::uint16_t bit = 0; bit < 8 * sizeof probe; ++bit) {
    if (bytes[bit / 8] & (1u << (bit % 8))) return bit;
  }
  return 0xFFFF;
}

const symcr::Schema& bits_schema() {
  static const std::uint16_t flag_at = bit_position([](Bits& b) { b.flag = 1; });
  static const std::uint16_t mode_at = bit_position([](Bits& b) { b.mode = 1; });
  static const std::uint16_t delta_at = bit_position([](Bits& b) { b.delta = 1; });
  static const std::uint16_t on_at = bit_position([](Bits& b) { b.on = true; });
  static const symcr::FieldInfo fields[] = {
      bit_field("flag", 0, flag_at, 1), bit_field("mode", 0, mode_at, 3),
      bit_field("delta", 1, delta_at, 5), bit_field("on", 2, on_at, 1),
      field("whole", 3, offsetof(Bits, whole))};
  static const symcr::TypeInfo types[] = {
      scalar("uint8", Kind::UInt, 1),
      scalar("int16", Kind::Int, 2),
      scalar("bool", Kind::Bool, 1),
      scalar("int32", Kind::Int, 4),
      record("Bits", sizeof(Bits), alignof(Bits), fields, 5),
  };
  static const symcr::RootInfo roots[] = {{"bits", 4, &bits, 0, nullptr}};
  static const symcr::Schema schema{types, 5, roots, 1, nullptr};
  return schema;
}

TEST(FastPath, BitFieldsKeepAStructCopyOnlyAndRoundTrip) {
  bits.flag = 1;
  bits.mode = 5;
  bits.delta = -9;
  bits.on = true;
  bits.whole = -123456;
  const Saved saved = save(bits_schema());
  ASSERT_EQ(saved.payload.size(), 1 + 1 + 2 + 1 + 4 + 4 + 4u);  // wire: each value at full width
  symcr::detail::ParsedSchema writer;
  EXPECT_TRUE(plan(saved, bits_schema(), writer)->copy_only_payload);
  std::memset(&bits, 0xFF, sizeof bits);  // every bit set: restore must clear the zero bits
  const symcr::Report report = load(saved, bits_schema(), true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(bits.flag, 1);
  EXPECT_EQ(bits.mode, 5);
  EXPECT_EQ(bits.delta, -9);
  EXPECT_TRUE(bits.on);
  EXPECT_EQ(bits.whole, -123456);

  bits.flag = 0;
  bits.mode = 0;
  bits.delta = 15;
  bits.on = false;
  const Saved other = save(bits_schema());
  std::memset(&bits, 0xFF, sizeof bits);
  ASSERT_TRUE(load(other, bits_schema()).ok());
  EXPECT_EQ(bits.flag, 0);
  EXPECT_EQ(bits.mode, 0);
  EXPECT_EQ(bits.delta, 15);
  EXPECT_FALSE(bits.on);
}

TEST(FastPath, BitFieldValuesBeyondTheirWidthsAreRejectedLikeTheGeneralPath) {
  bits.flag = 1;
  bits.mode = 2;
  bits.delta = 3;
  bits.on = false;
  bits.whole = 4;
  const Saved good = save(bits_schema());
  struct Case {
    const char* path;
    std::size_t offset;  // wire byte to overwrite
    std::uint8_t value;
  };
  const Case cases[] = {{"bits.flag", 0, 2}, {"bits.mode", 1, 8}, {"bits.delta", 2, 16}};
  for (const Case& c : cases) {
    Saved saved = good;
    saved.payload[c.offset] = c.value;
    bits.flag = 0;
    bits.mode = 7;
    bits.delta = -1;
    bits.whole = 0;
    const symcr::Report report = load(saved, bits_schema());
    ASSERT_TRUE(report.ok()) << c.path << ": " << report.to_text();
    expect_entry(report, c.path, symcr::Decision::Rejected, "does not fit in");
    EXPECT_EQ(bits.whole, 4) << c.path;  // the rest is restored
    // The rejected field kept the reader's value, the others were restored.
    EXPECT_EQ(bits.flag, c.offset == 0 ? 0 : 1) << c.path;
    EXPECT_EQ(bits.mode, c.offset == 1 ? 7 : 2) << c.path;
    EXPECT_EQ(bits.delta, c.offset == 2 ? -1 : 3) << c.path;
  }
  Saved bad_bool = good;
  bad_bool.payload[4] = 3;  // the bool bit-field's wire byte
  bits.whole = 0;
  const symcr::Report refused = load(bad_bool, bits_schema());
  EXPECT_FALSE(refused.ok());
  EXPECT_EQ(bits.whole, 0);  // nothing written
}

TEST(FastPath, ScratchStatisticsSeeTheTablesOfTheGeneralPathOnly) {
  vroot.doubles = {1, 2, 3};
  vroot.ints = {4, 5, 6, 7};
  vroot.into = &vroot.ints[2];
  vroot.bits = {8};
  const Saved with_pointer = save(vroot_schema());
  const std::size_t checkpoint_scratch = symcr::detail::thread_scratch_bytes().checkpoint;
  EXPECT_GT(checkpoint_scratch, 0u);  // the memo table for `into` and the region index
  ASSERT_TRUE(load(with_pointer, vroot_schema()).ok());
  const std::size_t general = symcr::detail::thread_scratch_bytes().restore;
  EXPECT_GT(general, 0u);
  EXPECT_EQ(vroot.into, &vroot.ints[2]);

  flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  ASSERT_TRUE(load(save(flat_schema()), flat_schema()).ok());
  EXPECT_EQ(symcr::detail::thread_scratch_bytes().restore, 0u);  // copy-only: no tables
  // Kept between checkpoints for reuse: a smaller checkpoint does not shrink it.
  EXPECT_GE(symcr::detail::thread_scratch_bytes().checkpoint, checkpoint_scratch);
}

// The schema-level report is the slow part of a plan: a restore that is not strict writes it
// only when the report's entries are first read; a strict one needs it to decide.
TEST(FastPath, TheSchemaLevelReportIsWrittenWhenFirstAsked) {
  static const symcr::Schema reader = flat_moved_schema();  // a plan of its own
  flat = Flat{3, false, 0.5, {4, 5, 6}, {true, true}};
  const Saved saved = save(flat_schema());
  const symcr::Report report = load(saved, reader);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(flat_moved.a, 3);
  const auto plan = symcr::detail::cached_plan(saved.hash, reader);
  ASSERT_TRUE(plan);
  EXPECT_TRUE(plan->report_entries.empty());
  ASSERT_FALSE(report.entries().empty());
  EXPECT_EQ(plan->report_entries.size(), report.entries().size());
  EXPECT_EQ(report.count(symcr::Decision::Kept), 2u);  // the added field and root
}

TEST(FastPath, AStrictRestoreWritesTheReportToDecide) {
  static const symcr::Schema reader = flat_moved_schema();
  flat = Flat{3, false, 0.5, {4, 5, 6}, {true, true}};
  const Saved saved = save(flat_schema());
  ASSERT_TRUE(load(saved, reader, /*strict=*/true).ok());
  const auto plan = symcr::detail::cached_plan(saved.hash, reader);
  ASSERT_TRUE(plan);
  EXPECT_FALSE(plan->report_entries.empty());
  EXPECT_FALSE(plan->any_lossy());
}

// The same build's checkpoint is restored by the device profile's decoder, which is strict: a
// value beyond its range (saving does not check them) makes it refuse, having changed nothing,
// and the general way applies the rules per value: that value keeps the running build's, the
// rest is restored, and the report says so.
TEST(FastPath, TheSameBuildsValueBeyondItsRangeIsRejectedAloneAsBefore) {
  const symcr::Schema& schema = a1::schema();
  ASSERT_EQ(symcr::device::check_schema(schema), symcr::device::Result::Ok);
  a1::basic = a1::Basic{};
  a1::basic.yaw = 123;
  a1::basic.speed = 500;  // outside [0, 100]
  const Saved saved = save(schema);
  a1::basic = a1::Basic{};
  a1::basic.speed = 42;
  const symcr::Report report = symcr::detail::restore_payload(
      schema, saved.hash, saved.payload.data(), saved.payload.size(), schema, {});
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(a1::basic.yaw, 123);
  EXPECT_EQ(a1::basic.speed, 42);
  EXPECT_EQ(report.count(symcr::Decision::Rejected), 1u);
}

TEST(FastPath, ReportsAreIndependentCopies) {
  flat = Flat{1, true, 1.0, {1, 2, 3}, {true, false}};
  const Saved saved = save(flat_schema());
  symcr::Report first = load(saved, flat_schema());
  const symcr::Report second = load(saved, flat_schema());
  ASSERT_TRUE(first.ok());
  const std::size_t count = second.entries().size();
  symcr::detail::ReportAccess::add(first, "extra", symcr::Decision::Rejected, "added later", true);
  EXPECT_EQ(first.entries().size(), count + 1);
  EXPECT_EQ(second.entries().size(), count);
  EXPECT_EQ(first.entries().back().path, "extra");
  first.clear();
  EXPECT_TRUE(first.entries().empty());
  EXPECT_EQ(second.entries().size(), count);
}

}  // namespace
}  // namespace engine_tests
