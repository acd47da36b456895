// docs/resolution.md, "Validators": a value its type's symcr_validate refuses is never replaced by
// a value-initialised stand-in. A container element holding one (the element itself, a map's key
// or mapped value, a field of a struct element, an element of a std::array element) is left out
// of its container; a fixed array element, an optional's, unique_ptr's or variant's value keeps
// this build's value; an inner container holding the refused value takes it in (the outer element
// stays). Every kind of container, one test each; the writer build has no validator, the reader
// build the same types with one.
#include <array>
#include <deque>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"

namespace engine_tests {
namespace {

using symcr::Decision;
using symcr::RootInfo;
using symcr::Schema;
using symcr::ops::offset_of;

struct Zone {
  float radius_m = 0;
  std::int32_t id = 0;
  bool operator<(const Zone& other) const { return id < other.id; }
};
// The reader's rule: a zone needs a positive radius (a value-initialised Zone fails it).
bool zone_valid(const void* object) { return static_cast<const Zone*>(object)->radius_m > 0; }

struct Fence {
  std::int32_t id = 0;
  Zone zone;
};
using ZoneById = std::pair<std::int32_t, Zone>;
using CountByZone = std::pair<Zone, std::int32_t>;
using ZoneGroup = std::pair<std::int32_t, std::vector<Zone>>;
using ZoneOrId = std::variant<std::int32_t, Zone>;

struct Zones {
  std::map<std::int32_t, Zone> by_id;
  std::unordered_map<std::int32_t, Zone> hashed;
  std::map<Zone, std::int32_t> by_zone;
  std::set<Zone> set;
  std::vector<Zone> list;
  std::deque<Fence> fence_deque;
  std::list<Fence> fence_list;
  std::vector<std::array<Zone, 2>> zone_pairs;
  std::map<std::int32_t, std::vector<Zone>> groups;
  Zone fixed[3];
  std::optional<Zone> maybe;
  std::unique_ptr<Zone> owned;
  ZoneOrId either = std::int32_t{0};
  Zone* pinned = nullptr;  // a heap object
  Zone* spare = nullptr;   // another
};
Zones zones;

// One table for both builds: `validate` is the reader's symcr_validate, null for the writer.
// The type indexes are the comments' numbers.
#define ZONE_TYPES(validate)                                                                     \
  {                                                                                              \
    scalar("float32", Kind::Float, 4), /* 0 */                                                   \
        scalar("int32", Kind::Int, 4), /* 1 */                                                   \
        record("Zone", sizeof(Zone), alignof(Zone), zone_fields, 2,                              \
               &symcr::ops::lifecycle<Zone>::table, validate), /* 2 */                           \
        record("std::pair<int32,Zone>", sizeof(ZoneById), alignof(ZoneById), by_id_fields, 2,   \
               &symcr::ops::lifecycle<ZoneById>::table), /* 3 */                                 \
        holder("std::map<int32,Zone>", Kind::Container, sizeof(zones.by_id),                     \
               alignof(decltype(zones.by_id)), 3,                                                \
               &symcr::ops::container<decltype(zones.by_id)>::table,                             \
               symcr::ContainerKind::Map), /* 4 */                                               \
        holder("std::unordered_map<int32,Zone>", Kind::Container, sizeof(zones.hashed),          \
               alignof(decltype(zones.hashed)), 3,                                               \
               &symcr::ops::container<decltype(zones.hashed)>::table,                            \
               symcr::ContainerKind::UnorderedMap), /* 5 */                                      \
        record("std::pair<Zone,int32>", sizeof(CountByZone), alignof(CountByZone),              \
               by_zone_fields, 2, &symcr::ops::lifecycle<CountByZone>::table), /* 6 */           \
        holder("std::map<Zone,int32>", Kind::Container, sizeof(zones.by_zone),                   \
               alignof(decltype(zones.by_zone)), 6,                                              \
               &symcr::ops::container<decltype(zones.by_zone)>::table,                           \
               symcr::ContainerKind::Map), /* 7 */                                               \
        holder("std::set<Zone>", Kind::Container, sizeof(zones.set), alignof(decltype(zones.set)), \
               2, &symcr::ops::container<decltype(zones.set)>::table,                            \
               symcr::ContainerKind::Set), /* 8 */                                               \
        holder("std::vector<Zone>", Kind::Container, sizeof(zones.list),                         \
               alignof(decltype(zones.list)), 2,                                                 \
               &symcr::ops::container<decltype(zones.list)>::table), /* 9 */                     \
        record("Fence", sizeof(Fence), alignof(Fence), fence_fields, 2,                          \
               &symcr::ops::lifecycle<Fence>::table), /* 10 */                                   \
        holder("std::deque<Fence>", Kind::Container, sizeof(zones.fence_deque),                  \
               alignof(decltype(zones.fence_deque)), 10,                                         \
               &symcr::ops::container<decltype(zones.fence_deque)>::table,                       \
               symcr::ContainerKind::Deque), /* 11 */                                            \
        holder("std::list<Fence>", Kind::Container, sizeof(zones.fence_list),                    \
               alignof(decltype(zones.fence_list)), 10,                                          \
               &symcr::ops::container<decltype(zones.fence_list)>::table,                        \
               symcr::ContainerKind::List), /* 12 */                                             \
        array("std::array<Zone,2>", 2, 2, sizeof(std::array<Zone, 2>), alignof(Zone)), /* 13 */ \
        holder("std::vector<std::array<Zone,2>>", Kind::Container, sizeof(zones.zone_pairs),     \
               alignof(decltype(zones.zone_pairs)), 13,                                          \
               &symcr::ops::container<decltype(zones.zone_pairs)>::table), /* 14 */              \
        record("std::pair<int32,std::vector<Zone>>", sizeof(ZoneGroup), alignof(ZoneGroup),     \
               group_fields, 2, &symcr::ops::lifecycle<ZoneGroup>::table), /* 15 */              \
        holder("std::map<int32,std::vector<Zone>>", Kind::Container, sizeof(zones.groups),       \
               alignof(decltype(zones.groups)), 15,                                              \
               &symcr::ops::container<decltype(zones.groups)>::table,                            \
               symcr::ContainerKind::Map), /* 16 */                                              \
        array("Zone[3]", 2, 3, sizeof(zones.fixed), alignof(Zone)), /* 17 */                     \
        holder("std::optional<Zone>", Kind::Optional, sizeof(zones.maybe),                       \
               alignof(decltype(zones.maybe)), 2,                                                \
               &symcr::ops::optional<decltype(zones.maybe)>::table), /* 18 */                    \
        holder("std::unique_ptr<Zone>", Kind::UniquePtr, sizeof(zones.owned),                    \
               alignof(decltype(zones.owned)), 2,                                                \
               &symcr::ops::unique_ptr<decltype(zones.owned)>::table), /* 19 */                  \
        variant_of("std::variant<int32,Zone>", sizeof(ZoneOrId), alignof(ZoneOrId),             \
                   alternatives, 2, &symcr::ops::variant<ZoneOrId>::table), /* 20 */             \
        record("Zones", sizeof(Zones), alignof(Zones), zones_fields, 15), /* 21 */               \
        holder("Zone*", Kind::Pointer, sizeof(Zone*), alignof(Zone*), 2, nullptr), /* 22 */     \
  }

const FieldInfo zone_fields[] = {field("radius_m", 0, offsetof(Zone, radius_m)),
                                 field("id", 1, offsetof(Zone, id))};
const FieldInfo by_id_fields[] = {field("first", 1, offset_of(&ZoneById::first)),
                                  field("second", 2, offset_of(&ZoneById::second))};
const FieldInfo by_zone_fields[] = {field("first", 2, offset_of(&CountByZone::first)),
                                    field("second", 1, offset_of(&CountByZone::second))};
const FieldInfo fence_fields[] = {field("id", 1, offsetof(Fence, id)),
                                  field("zone", 2, offsetof(Fence, zone))};
const FieldInfo group_fields[] = {field("first", 1, offset_of(&ZoneGroup::first)),
                                  field("second", 9, offset_of(&ZoneGroup::second))};
const std::uint32_t alternatives[] = {1, 2};
const FieldInfo zones_fields[] = {
    field("by_id", 4, offset_of(&Zones::by_id)),
    field("hashed", 5, offset_of(&Zones::hashed)),
    field("by_zone", 7, offset_of(&Zones::by_zone)),
    field("set", 8, offset_of(&Zones::set)),
    field("list", 9, offset_of(&Zones::list)),
    field("fence_deque", 11, offset_of(&Zones::fence_deque)),
    field("fence_list", 12, offset_of(&Zones::fence_list)),
    field("zone_pairs", 14, offset_of(&Zones::zone_pairs)),
    field("groups", 16, offset_of(&Zones::groups)),
    field("fixed", 17, offset_of(&Zones::fixed)),
    field("maybe", 18, offset_of(&Zones::maybe)),
    field("owned", 19, offset_of(&Zones::owned)),
    field("either", 20, offset_of(&Zones::either)),
    field("pinned", 22, offset_of(&Zones::pinned)),
    field("spare", 22, offset_of(&Zones::spare))};
const RootInfo roots[] = {{"zones", 21, &zones, 0, nullptr}};
constexpr std::uint32_t kTypeCount = 23;

const Schema& writer_schema() {
  static const TypeInfo types[] = ZONE_TYPES(nullptr);
  static_assert(sizeof types / sizeof types[0] == kTypeCount, "the table's type count");
  static const Schema schema{types, kTypeCount, roots, 1, nullptr};
  return schema;
}

const Schema& reader_schema() {
  static const TypeInfo types[] = ZONE_TYPES(&zone_valid);
  static_assert(sizeof types / sizeof types[0] == kTypeCount, "the table's type count");
  static const Schema schema{types, kTypeCount, roots, 1, nullptr};
  return schema;
}
#undef ZONE_TYPES

const Zone kGood{150.0f, 1};
const Zone kBad{-5.0f, 2};  // refused by zone_valid
const Zone kOther{80.0f, 3};

// The writer's state: every container holds a good and a bad zone (the bad one second).
void fill_writer() {
  zones.by_id = {{1, kGood}, {2, kBad}, {3, kOther}};
  zones.hashed = {{1, kGood}, {2, kBad}};
  zones.by_zone = {{kGood, 10}, {kBad, 20}, {kOther, 30}};
  zones.set = {kGood, kBad, kOther};
  zones.list = {kGood, kBad, kOther};
  zones.fence_deque = {Fence{7, kGood}, Fence{8, kBad}, Fence{9, kOther}};
  zones.fence_list = {Fence{7, kGood}, Fence{8, kBad}};
  zones.zone_pairs = {{kGood, kOther}, {kOther, kBad}};
  zones.groups = {{1, {kGood, kBad, kOther}}, {2, {kBad}}};
  zones.fixed[0] = kGood;
  zones.fixed[1] = kBad;
  zones.fixed[2] = kOther;
  zones.maybe = kBad;
  zones.owned.reset(new Zone(kBad));
  zones.either = kBad;
  delete zones.pinned;
  delete zones.spare;
  zones.pinned = new Zone(kBad);
  zones.spare = new Zone(kOther);
}

// The reader's own state before the restore: what a refused value leaves in place.
const Zone kReaders{1.0f, 99};
void fill_reader() {
  delete zones.pinned;
  delete zones.spare;
  zones = Zones();
  zones.by_id = {{99, kReaders}};
  zones.fixed[1] = kReaders;
  zones.either = std::int32_t{42};
}

bool has_entry(const symcr::Report& report, const std::string& path, const char* detail) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.decision == Decision::Rejected && e.lossy &&
        e.detail.find(detail) != std::string::npos) {
      return true;
    }
  }
  return false;
}

class ValidatedParts : public ::testing::Test {
 protected:
  void SetUp() override {
    fill_writer();
    const Saved saved = save(writer_schema());
    fill_reader();
    report_ = load(saved, reader_schema());
    ASSERT_TRUE(report_.ok()) << report_.to_text();
  }
  symcr::Report report_;
};

TEST_F(ValidatedParts, MapWhoseMappedValueIsRefusedLeavesTheKeyOut) {
  ASSERT_EQ(zones.by_id.size(), 2u) << report_.to_text();
  EXPECT_EQ(zones.by_id.count(2), 0u);
  EXPECT_EQ(zones.by_id.at(1).radius_m, 150.0f);
  EXPECT_EQ(zones.by_id.at(3).id, 3);
  for (const auto& entry : zones.by_id) EXPECT_TRUE(zone_valid(&entry.second));
  EXPECT_TRUE(has_entry(report_, "zones.by_id[1].second", "Zone failed its symcr_validate"))
      << report_.to_text();
  EXPECT_TRUE(has_entry(report_, "zones.by_id[1]", "left out of its container"))
      << report_.to_text();
}

TEST_F(ValidatedParts, UnorderedMapWhoseMappedValueIsRefusedLeavesTheKeyOut) {
  ASSERT_EQ(zones.hashed.size(), 1u) << report_.to_text();
  EXPECT_EQ(zones.hashed.count(2), 0u);
  EXPECT_EQ(zones.hashed.at(1).id, 1);
}

TEST_F(ValidatedParts, MapWhoseKeyIsRefusedLeavesTheEntryOut) {
  ASSERT_EQ(zones.by_zone.size(), 2u) << report_.to_text();
  for (const auto& entry : zones.by_zone) EXPECT_TRUE(zone_valid(&entry.first));
  EXPECT_EQ(zones.by_zone.at(kGood), 10);
  EXPECT_EQ(zones.by_zone.at(kOther), 30);
  EXPECT_TRUE(has_entry(report_, "zones.by_zone[1].first", "symcr_validate"))
      << report_.to_text();
}

TEST_F(ValidatedParts, SetElementRefusedIsLeftOut) {
  ASSERT_EQ(zones.set.size(), 2u);
  for (const Zone& zone : zones.set) EXPECT_TRUE(zone_valid(&zone));
  // The element is the refused value: one entry says so, no second one.
  EXPECT_TRUE(has_entry(report_, "zones.set[1]", "Zone failed its symcr_validate"));
  EXPECT_FALSE(has_entry(report_, "zones.set[1]", "left out"));
}

TEST_F(ValidatedParts, VectorElementRefusedIsLeftOutTheOthersKeepTheirOrder) {
  ASSERT_EQ(zones.list.size(), 2u);
  EXPECT_EQ(zones.list[0].id, 1);
  EXPECT_EQ(zones.list[1].id, 3);
}

TEST_F(ValidatedParts, DequeAndListElementWithARefusedFieldAreLeftOutWhole) {
  ASSERT_EQ(zones.fence_deque.size(), 2u) << report_.to_text();
  EXPECT_EQ(zones.fence_deque[0].id, 7);
  EXPECT_EQ(zones.fence_deque[1].id, 9);
  for (const Fence& fence : zones.fence_deque) EXPECT_TRUE(zone_valid(&fence.zone));
  ASSERT_EQ(zones.fence_list.size(), 1u);
  EXPECT_EQ(zones.fence_list.front().id, 7);
  EXPECT_TRUE(has_entry(report_, "zones.fence_deque[1].zone", "symcr_validate"));
  EXPECT_TRUE(has_entry(report_, "zones.fence_deque[1]", "left out of its container"))
      << report_.to_text();
}

TEST_F(ValidatedParts, StdArrayElementOfAVectorWithARefusedZoneIsLeftOutWhole) {
  ASSERT_EQ(zones.zone_pairs.size(), 1u) << report_.to_text();
  EXPECT_EQ(zones.zone_pairs[0][0].id, 1);
  EXPECT_EQ(zones.zone_pairs[0][1].id, 3);
}

TEST_F(ValidatedParts, InnerContainerTakesInItsRefusedElement) {
  // The refused zones are left out of the inner vectors; the map's entries stay.
  ASSERT_EQ(zones.groups.size(), 2u) << report_.to_text();
  ASSERT_EQ(zones.groups.at(1).size(), 2u);
  EXPECT_EQ(zones.groups.at(1)[0].id, 1);
  EXPECT_EQ(zones.groups.at(1)[1].id, 3);
  EXPECT_TRUE(zones.groups.at(2).empty());
  EXPECT_FALSE(has_entry(report_, "zones.groups[0]", "left out"));
}

TEST_F(ValidatedParts, FixedArrayElementRefusedKeepsThisBuildsValue) {
  EXPECT_EQ(zones.fixed[0].id, 1);
  EXPECT_EQ(zones.fixed[1].id, kReaders.id);
  EXPECT_EQ(zones.fixed[1].radius_m, kReaders.radius_m);
  EXPECT_EQ(zones.fixed[2].id, 3);
  EXPECT_TRUE(has_entry(report_, "zones.fixed[1]", "symcr_validate"));
}

TEST_F(ValidatedParts, OptionalUniquePtrAndVariantHoldingARefusedValueKeepThisBuildsValue) {
  EXPECT_FALSE(zones.maybe.has_value()) << report_.to_text();
  EXPECT_EQ(zones.owned, nullptr);
  ASSERT_EQ(zones.either.index(), 0u);
  EXPECT_EQ(std::get<std::int32_t>(zones.either), 42);
  EXPECT_TRUE(has_entry(report_, "zones.maybe", "symcr_validate")) << report_.to_text();
  EXPECT_TRUE(has_entry(report_, "zones.owned", "symcr_validate")) << report_.to_text();
}

TEST_F(ValidatedParts, HeapObjectRefusedIsNotCreatedItsPointerKeepsThisBuildsValue) {
  EXPECT_EQ(zones.pinned, nullptr) << report_.to_text();
  ASSERT_NE(zones.spare, nullptr);
  EXPECT_EQ(zones.spare->id, kOther.id);
  EXPECT_TRUE(has_entry(report_, "zones.pinned", "holds a value its symcr_validate refused"))
      << report_.to_text();
}

TEST_F(ValidatedParts, StrictModeRefusesAndWritesNothing) {
  fill_writer();
  const Saved saved = save(writer_schema());
  fill_reader();
  const symcr::Report strict = load(saved, reader_schema(), /*strict=*/true);
  EXPECT_EQ(strict.status().error(), symcr::Error::Strict) << strict.to_text();
  ASSERT_EQ(zones.by_id.size(), 1u);
  EXPECT_EQ(zones.by_id.count(99), 1u);
}

}  // namespace
}  // namespace engine_tests
