// The first restore through a plan that opening another build's store prepared
// (prepare_restore): when the device profile's cross-version executor holds the plan, it
// restores that record instead of the general decoder's two passes. Values and report must be
// exactly the general decoder's, and whatever the executor refuses goes the general way.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <deque>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "parsed_schema.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "scratch.hpp"
#include "symcr/device.hpp"

namespace engine_tests {
namespace {

// v0: the build that saved.
enum class Mode0 : std::int32_t { Manual = 0, Auto = 1, Sport = 2 };
struct Vehicle0 {
  std::int32_t id;
  double speed;
  Mode0 mode;
  std::int32_t cells[4];
  std::int32_t* target;  // -> cells[1]
  std::int16_t level;
};
Vehicle0 vehicle0;

// v1: wider id, a float speed, a field added, the modes renumbered, one cell more, a wider level.
// Nothing of v0's is left out: the executor then writes every value the planned path writes.
enum class Mode1 : std::int32_t { Auto = 5, Manual = 6 };
struct Vehicle1 {
  std::int64_t id;
  float speed;
  std::int32_t added;
  Mode1 mode;
  std::int32_t cells[5];
  std::int32_t* target;
  std::int32_t level;
};
Vehicle1 vehicle1;

const symcr::EnumeratorInfo kModes0[] = {{"Manual", 0}, {"Auto", 1}, {"Sport", 2}};
const symcr::EnumeratorInfo kModes1[] = {{"Auto", 5}, {"Manual", 6}};

const symcr::Schema& schema0() {
  static const symcr::FieldInfo fields[] = {
      field("id", 0, offsetof(Vehicle0, id)),         field("speed", 1, offsetof(Vehicle0, speed)),
      field("mode", 3, offsetof(Vehicle0, mode)),     field("cells", 4, offsetof(Vehicle0, cells)),
      field("target", 5, offsetof(Vehicle0, target)), field("level", 6, offsetof(Vehicle0, level))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("double", Kind::Float, 8),
      scalar("int16", Kind::Int, 2),
      enumeration("Mode", 4, 0, kModes0, 3),
      array("int32[4]", 0, 4, 16, 4),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      scalar("int16", Kind::Int, 2),
      record("Vehicle", sizeof(Vehicle0), alignof(Vehicle0), fields, 6),
  };
  static const symcr::RootInfo roots[] = {{"vehicle", 7, &vehicle0, 0, nullptr}};
  static const symcr::Schema schema{types, 8, roots, 1, nullptr};
  return schema;
}

// v1's tables, and a reader schema over them per test: plans are cached per reader, and each
// test needs a plan whose first restore is still to come.
const symcr::TypeInfo* types1() {
  static const symcr::FieldInfo fields[] = {
      field("id", 0, offsetof(Vehicle1, id)),       field("speed", 1, offsetof(Vehicle1, speed)),
      field("added", 2, offsetof(Vehicle1, added)), field("mode", 3, offsetof(Vehicle1, mode)),
      field("cells", 4, offsetof(Vehicle1, cells)), field("target", 5, offsetof(Vehicle1, target)),
      field("level", 2, offsetof(Vehicle1, level))};
  static const symcr::TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      scalar("float", Kind::Float, 4),
      scalar("int32", Kind::Int, 4),
      enumeration("Mode", 4, 2, kModes1, 2),
      array("int32[5]", 2, 5, 20, 4),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 2, nullptr),
      record("Vehicle", sizeof(Vehicle1), alignof(Vehicle1), fields, 7),
  };
  return types;
}
const symcr::RootInfo kRoots1[] = {{"vehicle", 6, &vehicle1, 0, nullptr}};
const symcr::Schema kReaderMatch{types1(), 7, kRoots1, 1, nullptr};
const symcr::Schema kReaderRefused{types1(), 7, kRoots1, 1, nullptr};
const symcr::Schema kReaderUnprepared{types1(), 7, kRoots1, 1, nullptr};
const symcr::Schema kReaderInexact{types1(), 7, kRoots1, 1, nullptr};

// Reader schemas made by the tests, each at an address of its own for the whole run: plans are
// cached by the reader's address, and a plan's first restore is taken once.
std::deque<symcr::Schema>& fresh_readers() {
  static std::deque<symcr::Schema> readers;
  return readers;
}

void set_v0(double speed) {
  vehicle0.id = 4100;
  vehicle0.speed = speed;
  vehicle0.mode = Mode0::Auto;
  for (int i = 0; i < 4; ++i) vehicle0.cells[i] = 10 * (i + 1);
  vehicle0.target = &vehicle0.cells[1];
  vehicle0.level = -3;
}

void scramble_v1() {
  vehicle1.id = -1;
  vehicle1.speed = -1.0f;
  vehicle1.added = 77;
  vehicle1.mode = Mode1::Manual;
  for (int i = 0; i < 5; ++i) vehicle1.cells[i] = -1;
  vehicle1.target = nullptr;
  vehicle1.level = 0;
}

// One restore of `saved` into `reader`, with the writer parsed from its bytes as a store's
// schema area is; `decoded_tables`: whether the general decoder's tables were used.
struct Restored {
  symcr::Report report;
  std::vector<std::uint8_t> bytes;  // vehicle1 afterwards
  bool decoded_tables;
};
// The report of one restore of `saved` into `reader`, with the writer parsed from its bytes as
// a store's schema area is.
symcr::Report restore_report(const Saved& saved, const symcr::Schema& reader, bool prepare) {
  auto writer = std::make_shared<symcr::detail::ParsedSchema>();
  EXPECT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), *writer).ok());
  if (prepare) symcr::detail::prepare_restore(writer->schema(), saved.hash, reader, writer);
  return symcr::detail::restore_payload(writer->schema(), saved.hash, saved.payload.data(),
                                        saved.payload.size(), reader, symcr::RestoreOptions(),
                                        writer);
}

Restored restore(const Saved& saved, const symcr::Schema& reader, bool prepare) {
  Restored restored;
  restored.report = restore_report(saved, reader, prepare);
  restored.decoded_tables = symcr::detail::thread_scratch_bytes().restore != 0;
  const auto* at = reinterpret_cast<const std::uint8_t*>(&vehicle1);
  restored.bytes.assign(at, at + sizeof vehicle1);
  return restored;
}

TEST(FirstRestore, APreparedPlanRestoresThroughTheDeviceExecutorAsTheGeneralDecoderDoes) {
  set_v0(12.5);
  const Saved saved = save(schema0());
  scramble_v1();
  const Restored first = restore(saved, kReaderMatch, true);
  ASSERT_TRUE(first.report.ok()) << first.report.to_text();
  EXPECT_FALSE(first.decoded_tables);  // the executor, not the two passes
  EXPECT_EQ(vehicle1.id, 4100);
  EXPECT_EQ(vehicle1.speed, 12.5f);
  EXPECT_EQ(vehicle1.added, 77);          // not in the checkpoint: kept
  EXPECT_EQ(vehicle1.mode, Mode1::Auto);  // by name: 1 was Auto, Auto is 5 now
  EXPECT_EQ(vehicle1.cells[0], 10);
  EXPECT_EQ(vehicle1.cells[3], 40);
  EXPECT_EQ(vehicle1.cells[4], -1);  // not in the checkpoint: kept
  EXPECT_EQ(vehicle1.target, &vehicle1.cells[1]);
  EXPECT_EQ(vehicle1.level, -3);

  scramble_v1();
  const Restored again = restore(saved, kReaderMatch, true);
  EXPECT_TRUE(again.decoded_tables);  // later restores: the general decoder
  EXPECT_EQ(again.report.to_text(), first.report.to_text());
  EXPECT_EQ(again.bytes, first.bytes);
}

TEST(FirstRestore, AValueTheExecutorRefusesGoesTheGeneralWayAndIsNamed) {
  set_v0(1e300);  // no float holds it
  const Saved saved = save(schema0());
  scramble_v1();
  const Restored first = restore(saved, kReaderRefused, true);
  ASSERT_TRUE(first.report.ok()) << first.report.to_text();
  EXPECT_TRUE(first.decoded_tables);
  expect_entry(first.report, "vehicle.speed", symcr::Decision::Rejected);
  EXPECT_EQ(vehicle1.speed, -1.0f);  // this build's value stays
  EXPECT_EQ(vehicle1.id, 4100);      // the rest is restored
  EXPECT_EQ(vehicle1.mode, Mode1::Auto);
  EXPECT_EQ(vehicle1.target, &vehicle1.cells[1]);

  scramble_v1();
  const Restored again = restore(saved, kReaderRefused, true);
  EXPECT_EQ(again.report.to_text(), first.report.to_text());
  EXPECT_EQ(again.bytes, first.bytes);
}

TEST(FirstRestore, ADoubleNoFloatHoldsExactlyIsDecidedAsTheGeneralDecoderDecides) {
  set_v0(0.1);
  const Saved saved = save(schema0());
  scramble_v1();
  const Restored first = restore(saved, kReaderInexact, true);
  ASSERT_TRUE(first.report.ok()) << first.report.to_text();
  EXPECT_EQ(vehicle1.id, 4100);
  scramble_v1();
  const Restored again = restore(saved, kReaderInexact, true);
  EXPECT_TRUE(again.decoded_tables);
  EXPECT_EQ(again.report.to_text(), first.report.to_text());
  EXPECT_EQ(again.bytes, first.bytes);
}

// Every byte of the payload damaged four ways: the executor's first restore and the general
// decoder's second must agree on the outcome, the report and every byte left in the state.
TEST(FirstRestore, EveryDamagedPayloadIsDecidedAsTheGeneralDecoderDecides) {
  set_v0(12.5);
  const Saved saved = save(schema0());
  std::deque<symcr::Schema>& readers = fresh_readers();  // a plan of its own per damage
  int refused = 0;
  for (std::size_t at = 0; at < saved.payload.size(); ++at) {
    const std::uint8_t original = saved.payload[at];
    for (const std::uint8_t value :
         {std::uint8_t{0}, std::uint8_t{0xFF}, static_cast<std::uint8_t>(original ^ 0x01),
          static_cast<std::uint8_t>(original ^ 0x80)}) {
      if (value == original) continue;
      Saved damaged = saved;
      damaged.payload[at] = value;
      readers.emplace_back(symcr::Schema{types1(), 7, kRoots1, 1, nullptr});
      scramble_v1();
      const Restored first = restore(damaged, readers.back(), true);
      scramble_v1();
      const Restored again = restore(damaged, readers.back(), true);
      ASSERT_EQ(again.report.to_text(), first.report.to_text()) << "byte " << at << " = " << +value;
      ASSERT_EQ(again.bytes, first.bytes) << "byte " << at << " = " << +value;
      if (!first.report.ok()) ++refused;
    }
  }
  EXPECT_GT(refused, 0);  // some damage is found (the rest changes values, as any byte may)
}

// Smaller pairs, each a change whose first restore must still be the planned path's: the
// executor's own rules differ there, or it skips bytes the planned path checks.
struct Small0 {
  std::int32_t mode;
  bool flag;
  std::int32_t* p;
};
struct Small1 {
  Mode1 mode;  // an int becomes an enum: only its enumerators' values are taken
  bool flag;
  std::int32_t* p;
};
struct Small2 {
  Mode1 mode;
  std::int32_t* p;
};  // `flag` removed: the executor would skip its bytes, which the planned path checks
Small0 small0;
Small1 small1;
Small2 small2;
std::int32_t outside_value = 5;  // in no root: a pointer to it is saved as "outside"

const symcr::Schema& small_schema0() {
  static const symcr::FieldInfo fields[] = {field("mode", 0, offsetof(Small0, mode)),
                                            field("flag", 1, offsetof(Small0, flag)),
                                            field("p", 2, offsetof(Small0, p))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4), scalar("bool", Kind::Bool, 1),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      record("Small", sizeof(Small0), alignof(Small0), fields, 3)};
  static const symcr::RootInfo roots[] = {{"small", 3, &small0, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}
// The reader types: Small1's, or with `removed_flag` Small2's (each at index 4).
const symcr::TypeInfo* small_types(bool removed_flag) {
  static const symcr::FieldInfo fields1[] = {field("mode", 1, offsetof(Small1, mode)),
                                             field("flag", 3, offsetof(Small1, flag)),
                                             field("p", 2, offsetof(Small1, p))};
  static const symcr::FieldInfo fields2[] = {field("mode", 1, offsetof(Small2, mode)),
                                             field("p", 2, offsetof(Small2, p))};
  static const symcr::TypeInfo types1[] = {
      scalar("int32", Kind::Int, 4), enumeration("Mode", 4, 0, kModes1, 2),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      scalar("bool", Kind::Bool, 1), record("Small", sizeof(Small1), alignof(Small1), fields1, 3)};
  static const symcr::TypeInfo types2[] = {
      scalar("int32", Kind::Int, 4), enumeration("Mode", 4, 0, kModes1, 2),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      scalar("bool", Kind::Bool, 1), record("Small", sizeof(Small2), alignof(Small2), fields2, 2)};
  return removed_flag ? types2 : types1;
}
const symcr::RootInfo kSmallRoots1[] = {{"small", 4, &small1, 0, nullptr}};
const symcr::RootInfo kSmallRoots2[] = {{"small", 4, &small2, 0, nullptr}};

// Restores `saved` twice into a fresh reader: the first restore through the prepared plan, the
// second the planned path's, both from the same state; they must be alike in report and bytes.
// The first report is returned.
template <typename State>
symcr::Report expect_alike(const Saved& saved, State& state, bool removed_flag) {
  std::deque<symcr::Schema>& readers = fresh_readers();
  readers.emplace_back(symcr::Schema{small_types(removed_flag), 5,
                                     removed_flag ? kSmallRoots2 : kSmallRoots1, 1, nullptr});
  state = State{};
  const symcr::Report first = restore_report(saved, readers.back(), true);
  const State after_first = state;
  state = State{};
  const symcr::Report again = restore_report(saved, readers.back(), true);
  EXPECT_EQ(again.to_text(), first.to_text());
  EXPECT_EQ(std::memcmp(&after_first, &state, sizeof state), 0);
  state = after_first;
  return first;
}

TEST(FirstRestore, AnIntegerThatIsNoEnumeratorIsRejectedAsByThePlannedPath) {
  small0 = Small0{1, true, nullptr};  // 1: no enumerator of Mode1 (5, 6)
  const symcr::Report report = expect_alike(save(small_schema0()), small1, false);
  expect_entry(report, "small.mode", symcr::Decision::Rejected);
  EXPECT_EQ(small1.mode, Mode1{});    // this build's value stays
  small0 = Small0{5, true, nullptr};  // Auto's value
  expect_alike(save(small_schema0()), small1, false);
  EXPECT_EQ(small1.mode, Mode1::Auto);
  EXPECT_TRUE(small1.flag);
}

TEST(FirstRestore, APointerOutsideTheStateIsReportedAsKept) {
  small0 = Small0{5, false, &outside_value};
  const symcr::Report report = expect_alike(save(small_schema0()), small1, false);
  expect_entry(report, "small.p", symcr::Decision::Kept);
}

// The same build's first restore (the device profile's plan-free decoder) reports it too.
TEST(FirstRestore, APointerOutsideTheStateIsReportedByTheSameBuildsFirstRestore) {
  small0 = Small0{5, true, &outside_value};
  const Saved saved = save(small_schema0());
  const symcr::Schema& schema = small_schema0();
  const auto restore_same = [&] {
    small0 = Small0{};
    return symcr::detail::restore_payload(schema, saved.hash, saved.payload.data(),
                                          saved.payload.size(), schema, symcr::RestoreOptions());
  };
  const symcr::Report first = restore_same();
  const symcr::Report again = restore_same();
  EXPECT_EQ(again.to_text(), first.to_text());
  expect_entry(first, "small.p", symcr::Decision::Kept);
  EXPECT_EQ(small0.mode, 5);
}

// An unsigned 2^64 - 1 has the bits of -1 but is not the enumerator -1.
enum class Tiny : std::int8_t { M1 = -1, P1 = 1 };
struct Wide0 {
  std::uint64_t u;
};
struct Wide1 {
  Tiny u;
};
Wide0 wide0;
Wide1 wide1;
const symcr::EnumeratorInfo kTiny[] = {{"M1", -1}, {"P1", 1}};

TEST(FirstRestore, AnUnsignedValueWithTheBitsOfANegativeEnumeratorIsNotIt) {
  static const symcr::FieldInfo fields0[] = {field("u", 0, offsetof(Wide0, u))};
  static const symcr::TypeInfo types0[] = {scalar("uint64", Kind::UInt, 8),
                                           record("W", sizeof(Wide0), alignof(Wide0), fields0, 1)};
  static const symcr::RootInfo roots0[] = {{"w", 1, &wide0, 0, nullptr}};
  static const symcr::Schema schema0{types0, 2, roots0, 1, nullptr};
  static const symcr::FieldInfo fields1[] = {field("u", 1, offsetof(Wide1, u))};
  static const symcr::TypeInfo types1[] = {scalar("int8", Kind::Int, 1),
                                           enumeration("Tiny", 1, 0, kTiny, 2),
                                           record("W", sizeof(Wide1), alignof(Wide1), fields1, 1)};
  static const symcr::RootInfo roots1[] = {{"w", 2, &wide1, 0, nullptr}};
  std::deque<symcr::Schema>& readers = fresh_readers();
  for (const std::uint64_t value : {~std::uint64_t{0}, std::uint64_t{1}}) {
    wide0.u = value;
    const Saved saved = save(schema0);
    readers.emplace_back(symcr::Schema{types1, 3, roots1, 1, nullptr});
    wide1.u = Tiny::P1;
    const symcr::Report first = restore_report(saved, readers.back(), true);
    const Tiny after_first = wide1.u;
    wide1.u = Tiny::P1;
    const symcr::Report again = restore_report(saved, readers.back(), true);
    EXPECT_EQ(again.to_text(), first.to_text());
    EXPECT_EQ(after_first, wide1.u);
    EXPECT_EQ(after_first, Tiny::P1) << value;  // rejected, or 1 restored as P1
  }
}

TEST(FirstRestore, ADamagedValueOfARemovedFieldIsFoundAsByThePlannedPath) {
  small0 = Small0{5, true, nullptr};
  Saved saved = save(small_schema0());
  saved.payload[4] = 2;  // `flag`, after the 4 bytes of `mode`
  EXPECT_FALSE(expect_alike(saved, small2, true).ok());
}

TEST(FirstRestore, WithoutPreparationTheFirstRestoreDecodesAsEveryOther) {
  set_v0(12.5);
  const Saved saved = save(schema0());
  scramble_v1();
  const Restored first = restore(saved, kReaderUnprepared, false);
  ASSERT_TRUE(first.report.ok()) << first.report.to_text();
  EXPECT_TRUE(first.decoded_tables);
  EXPECT_EQ(vehicle1.id, 4100);
  EXPECT_EQ(vehicle1.target, &vehicle1.cells[1]);
}

// Opening a store prepares the scratch of the process's first restore into the build (written
// there, so that restore meets no page the process has not touched yet); that restore, through
// one of the device profile's decoders, takes it. Opening the build's own store also writes the
// steps of that decoder's walk, which its first restore runs.
std::uint8_t* take_prepared(const symcr::Schema& reader) {
  return symcr::detail::schema_cache_entry(reader).take_first_scratch();
}
void free_prepared(std::uint8_t* scratch, const symcr::Schema& reader) {
  std::allocator<std::uint8_t>().deallocate(scratch, symcr::device::scratch_size(reader));
}

TEST(FirstRestore, OpeningTheBuildsOwnStorePreparesTheScratchItsFirstRestoreTakes) {
  set_v0(8.25);
  std::deque<symcr::Schema>& readers = fresh_readers();
  readers.push_back(schema0());
  const symcr::Schema& looked_at = readers.back();
  const Saved saved = save(looked_at);
  const symcr::detail::SchemaCacheEntry& entry = symcr::detail::schema_cache_entry(looked_at);
  ASSERT_TRUE(entry.device_holdable());
  EXPECT_EQ(entry.held_shape().steps, nullptr);
  symcr::detail::prepare_restore(looked_at, saved.hash, looked_at, nullptr);
  // And the steps of its walk (device_test.cpp checks them against the walk).
  EXPECT_NE(entry.held_shape().steps, nullptr);
  EXPECT_GT(entry.held_shape().step_count, 0u);
  std::uint8_t* prepared = take_prepared(looked_at);
  ASSERT_NE(prepared, nullptr);
  const std::size_t size = symcr::device::scratch_size(looked_at);
  EXPECT_EQ(std::count(prepared, prepared + size, 0), static_cast<std::ptrdiff_t>(size));
  free_prepared(prepared, looked_at);
  EXPECT_EQ(take_prepared(looked_at), nullptr);  // taken once

  readers.push_back(schema0());
  const symcr::Schema& restored = readers.back();
  symcr::detail::prepare_restore(restored, saved.hash, restored, nullptr);
  vehicle0 = Vehicle0{};
  const symcr::Report report =
      symcr::detail::restore_payload(restored, saved.hash, saved.payload.data(),
                                     saved.payload.size(), restored, symcr::RestoreOptions());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(symcr::detail::thread_scratch_bytes().restore, 0u);  // the device's decoder
  EXPECT_EQ(take_prepared(restored), nullptr);                   // which took the scratch
  EXPECT_EQ(vehicle0.id, 4100);
  EXPECT_EQ(vehicle0.speed, 8.25);
  EXPECT_EQ(vehicle0.cells[3], 40);
  EXPECT_EQ(vehicle0.target, &vehicle0.cells[1]);
}

TEST(FirstRestore, OpeningAnotherBuildsStorePreparesTheScratchOnlyForTheExecutor) {
  set_v0(2.5);
  const Saved saved = save(schema0());
  auto v0 = std::make_shared<symcr::detail::ParsedSchema>();
  ASSERT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), *v0).ok());
  std::deque<symcr::Schema>& readers = fresh_readers();
  readers.emplace_back(symcr::Schema{types1(), 7, kRoots1, 1, nullptr});
  symcr::detail::prepare_restore(v0->schema(), saved.hash, readers.back(), v0);
  std::uint8_t* prepared = take_prepared(readers.back());
  ASSERT_NE(prepared, nullptr);
  free_prepared(prepared, readers.back());

  readers.emplace_back(symcr::Schema{types1(), 7, kRoots1, 1, nullptr});
  scramble_v1();
  const Restored first = restore(saved, readers.back(), true);
  ASSERT_TRUE(first.report.ok()) << first.report.to_text();
  EXPECT_FALSE(first.decoded_tables);
  EXPECT_EQ(take_prepared(readers.back()), nullptr);  // the executor took it
  EXPECT_EQ(vehicle1.speed, 2.5f);

  // A plan the executor does not hold (a field removed) prepares nothing.
  small0 = Small0{5, true, nullptr};
  const Saved small = save(small_schema0());
  auto writer = std::make_shared<symcr::detail::ParsedSchema>();
  ASSERT_TRUE(symcr::detail::parse_schema(small.schema.data(), small.schema.size(), *writer).ok());
  readers.emplace_back(symcr::Schema{small_types(true), 5, kSmallRoots2, 1, nullptr});
  symcr::detail::prepare_restore(writer->schema(), small.hash, readers.back(), writer);
  EXPECT_EQ(take_prepared(readers.back()), nullptr);
}

// A large state's scratch is not kept waiting for a restore that may never come.
std::int32_t big_cells[20000];
TEST(FirstRestore, ALargeStatesScratchIsNotPreparedAndItsFirstRestoreStillSucceeds) {
  static const symcr::TypeInfo types[] = {scalar("int32", Kind::Int, 4),
                                          array("int32[20000]", 0, 20000, sizeof big_cells, 4)};
  static const symcr::RootInfo roots[] = {{"cells", 1, big_cells, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  ASSERT_GT(symcr::device::scratch_size(schema), 64u * 1024u);
  for (int i = 0; i < 20000; ++i) big_cells[i] = i * 3;
  const Saved saved = save(schema);
  symcr::detail::prepare_restore(schema, saved.hash, schema, nullptr);
  EXPECT_EQ(take_prepared(schema), nullptr);
  std::fill(std::begin(big_cells), std::end(big_cells), -1);
  const symcr::Report report =
      symcr::detail::restore_payload(schema, saved.hash, saved.payload.data(), saved.payload.size(),
                                     schema, symcr::RestoreOptions());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(symcr::detail::thread_scratch_bytes().restore, 0u);
  EXPECT_EQ(big_cells[0], 0);
  EXPECT_EQ(big_cells[19999], 19999 * 3);
}

// A walk of more steps than are kept (each bool is a step of its own) is not written down at
// open: the first restore walks the types itself, to the same values.
bool many_flags[6000];
TEST(FirstRestore, AWalkOfTooManyStepsIsNotKeptAndItsFirstRestoreWalks) {
  static const symcr::TypeInfo types[] = {scalar("bool", Kind::Bool, 1),
                                          array("bool[6000]", 0, 6000, sizeof many_flags, 1)};
  static const symcr::RootInfo roots[] = {{"flags", 1, many_flags, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  const symcr::detail::SchemaCacheEntry& entry = symcr::detail::schema_cache_entry(schema);
  for (int i = 0; i < 6000; ++i) many_flags[i] = i % 3 == 0;
  const Saved saved = save(schema);
  symcr::detail::prepare_restore(schema, saved.hash, schema, nullptr);
  ASSERT_TRUE(entry.device_holdable());
  EXPECT_EQ(entry.held_shape().steps, nullptr);
  std::fill(std::begin(many_flags), std::end(many_flags), true);
  const symcr::Report report =
      symcr::detail::restore_payload(schema, saved.hash, saved.payload.data(), saved.payload.size(),
                                     schema, symcr::RestoreOptions());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(symcr::detail::thread_scratch_bytes().restore, 0u);  // the device's decoder
  for (int i = 0; i < 6000; ++i) ASSERT_EQ(many_flags[i], i % 3 == 0) << i;
}

// A validator reading a member the checkpoint does not hold: the planned path judges a
// value-initialised staged object (max_speed 0 here), so the process's first restore must not
// judge a copy of the running state (max_speed 1000) and accept what every later one rejects.
struct Limits {
  std::int32_t speed;
  std::int32_t max_speed;  // not checkpointed
};
Limits limits;
bool speed_within_limit(const void* object) {
  const auto* l = static_cast<const Limits*>(object);
  return l->speed <= l->max_speed;
}
const symcr::Lifecycle kLimitsLifecycle = {
    []() -> void* { return new Limits(); },
    [](void* object) { delete static_cast<Limits*>(object); }, nullptr};

TEST(FirstRestore, AValidatorJudgesTheSameStagedObjectOnTheSameBuildsFirstRestore) {
  static const symcr::FieldInfo fields[] = {field("speed", 0, offsetof(Limits, speed))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4), record("Limits", sizeof(Limits), alignof(Limits), fields, 1,
                                            &kLimitsLifecycle, speed_within_limit)};
  static const symcr::RootInfo roots[] = {{"limits", 1, &limits, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  limits = Limits{500, 1000};
  const Saved saved = save(schema);
  std::vector<std::string> reports;
  for (int round = 0; round < 2; ++round) {
    symcr::detail::prepare_restore(schema, saved.hash, schema, nullptr);
    limits = Limits{7, 1000};
    const symcr::Report report =
        symcr::detail::restore_payload(schema, saved.hash, saved.payload.data(),
                                       saved.payload.size(), schema, symcr::RestoreOptions());
    expect_entry(report, "limits", symcr::Decision::Rejected);
    EXPECT_EQ(limits.speed, 7) << "round " << round;  // this build's value stays
    reports.push_back(report.to_text());
  }
  EXPECT_EQ(reports[0], reports[1]);
}

}  // namespace
}  // namespace engine_tests
