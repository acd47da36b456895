// The generated tables hold what g++ computes for the same types: sizes, alignments, offsets
// (also of private, protected, bit-field, base and anonymous members), canonical names, kinds,
// enumerators, element types, ops, lifecycles and root addresses.
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <symcr/ops.hpp>

#include "roots.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "symcr/format/hashes.hpp"

// offsetof on these non-standard-layout types is conditionally supported; g++ supports it.
#pragma GCC diagnostic ignored "-Winvalid-offsetof"

namespace {

const symcr::Schema& schema() { return *symcr_program_schema(); }

const symcr::TypeInfo* type_named(const std::string& name) {
  for (std::uint32_t i = 0; i < schema().type_count; ++i)
    if (name == schema().types[i].name) return &schema().types[i];
  return nullptr;
}

const symcr::TypeInfo& type_at(std::uint32_t index) {
  EXPECT_LT(index, schema().type_count);
  return schema().types[index];
}

const symcr::FieldInfo* field_named(const symcr::TypeInfo& type, const std::string& name) {
  for (std::uint32_t i = 0; i < type.field_count; ++i)
    if (name == type.fields[i].name) return &type.fields[i];
  return nullptr;
}

const symcr::RootInfo* root_named(const std::string& name) {
  for (std::uint32_t i = 0; i < schema().root_count; ++i)
    if (name == schema().roots[i].name) return &schema().roots[i];
  return nullptr;
}

std::ptrdiff_t distance(const void* from, const void* to) {
  return static_cast<const char*>(to) - static_cast<const char*>(from);
}

const symcr::TypeInfo& everything_type() {
  const symcr::TypeInfo* t = type_named("fleet::Everything");
  EXPECT_NE(t, nullptr);
  return *t;
}

// The type of Everything's field `name`, checking its offset against offsetof.
#define EXPECT_FIELD(member, type_name, expected_kind)                                            \
  do {                                                                                   \
    const symcr::FieldInfo* f = field_named(everything_type(), #member);                 \
    ASSERT_NE(f, nullptr) << #member;                                                    \
    EXPECT_EQ(f->offset, offsetof(fleet::Everything, member)) << #member;                \
    const symcr::TypeInfo& t = type_at(f->type);                                         \
    EXPECT_STREQ(t.name, type_name) << #member;                                          \
    EXPECT_EQ(t.kind, symcr::Kind::expected_kind) << #member;                                     \
    EXPECT_EQ(t.size, sizeof(everything.member)) << #member;                             \
    EXPECT_EQ(t.align, alignof(decltype(everything.member))) << #member;                 \
  } while (0)

TEST(Tables, ProgramSchemaExists) {
  ASSERT_NE(symcr_program_schema(), nullptr);
  EXPECT_EQ(symcr_program_schema(), symcr_program_schema());
}

TEST(Tables, Scalars) {
  EXPECT_FIELD(b, "bool", Bool);
  EXPECT_FIELD(c, "int8", Int);  // char is signed on x86-64
  EXPECT_FIELD(sc, "int8", Int);
  EXPECT_FIELD(uc, "uint8", UInt);
  EXPECT_FIELD(s, "int16", Int);
  EXPECT_FIELD(us, "uint16", UInt);
  EXPECT_FIELD(i, "int32", Int);
  EXPECT_FIELD(u, "uint32", UInt);
  EXPECT_FIELD(l, "int64", Int);
  EXPECT_FIELD(ul, "uint64", UInt);
  EXPECT_FIELD(ll, "int64", Int);
  EXPECT_FIELD(ull, "uint64", UInt);
  EXPECT_FIELD(wc, "int32", Int);
  EXPECT_FIELD(c16, "uint16", UInt);
  EXPECT_FIELD(c32, "uint32", UInt);
  EXPECT_FIELD(f, "float32", Float);
  EXPECT_FIELD(d, "float64", Float);
  EXPECT_FIELD(ld, "float80", Float);
}

TEST(Tables, Enums) {
  EXPECT_FIELD(mode, "fleet::Mode", Enum);
  EXPECT_FIELD(legacy, "fleet::Legacy", Enum);
  const symcr::TypeInfo& mode = *type_named("fleet::Mode");
  EXPECT_TRUE(mode.flags & symcr::kTypeScopedEnum);
  EXPECT_STREQ(type_at(mode.element).name, "uint8");
  ASSERT_EQ(mode.enumerator_count, 3u);
  EXPECT_STREQ(mode.enumerators[1].name, "Auto");
  EXPECT_EQ(mode.enumerators[1].value, 5);
  const symcr::TypeInfo& legacy = *type_named("fleet::Legacy");
  EXPECT_FALSE(legacy.flags & symcr::kTypeScopedEnum);
  EXPECT_STREQ(type_at(legacy.element).name, "int64");
  EXPECT_EQ(legacy.enumerators[0].value, -3);
  EXPECT_EQ(legacy.enumerators[1].value, 1000000000000);
}

TEST(Tables, MultiDimensionalArrays) {
  EXPECT_FIELD(grid, "int32[2][3]", Array);
  const symcr::TypeInfo& grid = *type_named("int32[2][3]");
  EXPECT_EQ(grid.count, 2u);
  const symcr::TypeInfo& row = type_at(grid.element);
  EXPECT_STREQ(row.name, "int32[3]");
  EXPECT_EQ(row.count, 3u);
  EXPECT_EQ(row.size, sizeof(int[3]));
}

TEST(Tables, TemplateWrapperWithPrivateMember) {
  EXPECT_FIELD(param, "fleet::Param<int8>", Struct);
  const symcr::TypeInfo& param = *type_named("fleet::Param<int8>");
  const symcr::FieldInfo* value = field_named(param, "value_");
  ASSERT_NE(value, nullptr);
  EXPECT_EQ(value->offset, distance(&everything.param, everything.param.value_address()));
}

TEST(Tables, BitFields) {
  EXPECT_FIELD(bits, "fleet::Bits", Struct);
  const symcr::TypeInfo& bits = *type_named("fleet::Bits");
  EXPECT_EQ(bits.field_count, 5u);  // the unnamed `: 0` is not a field
  // Setting each bit-field to all ones must set exactly the bits the table names.
  auto check = [&](const char* name, auto set) {
    const symcr::FieldInfo* f = field_named(bits, name);
    ASSERT_NE(f, nullptr) << name;
    ASSERT_GT(f->bit_width, 0u) << name;
    fleet::Bits value;
    std::memset(static_cast<void*>(&value), 0, sizeof value);
    set(value);
    const symcr::TypeInfo& unit_type = type_at(f->type);
    std::uint64_t unit = 0;
    std::memcpy(&unit, reinterpret_cast<const char*>(&value) + f->offset, unit_type.size);
    std::uint64_t mask = ((std::uint64_t{1} << f->bit_width) - 1) << f->bit_offset;
    EXPECT_EQ(unit, mask) << name;
  };
  check("armed", [](fleet::Bits& v) { v.armed = 1; });
  check("motors", [](fleet::Bits& v) { v.motors = 15; });
  check("trim", [](fleet::Bits& v) { v.trim = -1; });
  check("flag", [](fleet::Bits& v) { v.flag = true; });
  EXPECT_EQ(field_named(bits, "tag")->bit_width, 0u);
}

TEST(Tables, BasesAndNonPublicMembers) {
  EXPECT_FIELD(vehicle, "fleet::Vehicle", Struct);
  const symcr::TypeInfo& vehicle = *type_named("fleet::Vehicle");
  ASSERT_GE(vehicle.field_count, 5u);
  EXPECT_STREQ(vehicle.fields[0].name, "fleet::Base");
  EXPECT_TRUE(vehicle.fields[0].flags & symcr::kFieldBase);
  EXPECT_EQ(vehicle.fields[0].offset,
            distance(&everything.vehicle,
                     &static_cast<const fleet::Base&>(everything.vehicle)));
  EXPECT_STREQ(vehicle.fields[1].name, "fleet::Other");
  EXPECT_TRUE(vehicle.fields[1].flags & symcr::kFieldBase);
  EXPECT_EQ(vehicle.fields[1].offset,
            distance(&everything.vehicle, everything.vehicle.other_address()));
  EXPECT_EQ(field_named(vehicle, "id")->offset, offsetof(fleet::Vehicle, id));
  EXPECT_EQ(field_named(vehicle, "hidden_")->offset,
            distance(&everything.vehicle, everything.vehicle.hidden_address()));
  EXPECT_EQ(field_named(vehicle, "secret_")->offset,
            distance(&everything.vehicle, everything.vehicle.secret_address()));
}

TEST(Tables, PrivateNestedTypes) {
  const symcr::TypeInfo* slot = type_named("fleet::Vehicle::Slot");
  ASSERT_NE(slot, nullptr);
  EXPECT_EQ(slot->size, fleet::Vehicle::slot_size());
  const symcr::TypeInfo* slots = type_named("std::vector<fleet::Vehicle::Slot>");
  ASSERT_NE(slots, nullptr);
  ASSERT_NE(slots->ops, nullptr);  // instantiated although Slot is private
  everything.vehicle.add_slot(4);
  everything.vehicle.add_slot(5);
  const symcr::FieldInfo* field = field_named(*type_named("fleet::Vehicle"), "slots_");
  ASSERT_NE(field, nullptr);
  const void* vector = reinterpret_cast<const char*>(&everything.vehicle) + field->offset;
  EXPECT_EQ(static_cast<const symcr::ContainerOps*>(slots->ops)->size(vector),
            everything.vehicle.slot_count());
}

TEST(Tables, UnionsAreRawBytes) {
  EXPECT_FIELD(raw, "fleet::Raw", Union);
  EXPECT_EQ(type_named("fleet::Raw")->size, sizeof(fleet::Raw));
}

TEST(Tables, AnonymousStructAndUnion) {
  EXPECT_FIELD(unnamed, "fleet::Everything::(anonymous struct at field 25)", Struct);
  const symcr::TypeInfo& inner = *type_named("fleet::Everything::(anonymous struct at field 25)");
  EXPECT_EQ(field_named(inner, "inner_b")->offset, sizeof(int));
  const symcr::FieldInfo* anon = field_named(everything_type(), "(anonymous union at field 26)");
  ASSERT_NE(anon, nullptr);
  EXPECT_EQ(anon->offset, offsetof(fleet::Everything, anon_i));
  EXPECT_EQ(type_at(anon->type).kind, symcr::Kind::Union);
  EXPECT_EQ(type_at(anon->type).size, sizeof(int));
}

TEST(Tables, Pointers) {
  EXPECT_FIELD(head, "fleet::Node*", Pointer);
  const symcr::TypeInfo& pointer = *type_named("fleet::Node*");
  const symcr::TypeInfo& node = type_at(pointer.element);
  EXPECT_STREQ(node.name, "fleet::Node");
  ASSERT_NE(node.lifecycle, nullptr);  // heap pointees can be rebuilt
  void* created = node.lifecycle->create();
  EXPECT_EQ(static_cast<fleet::Node*>(created)->next, nullptr);
  node.lifecycle->destroy(created);
  EXPECT_EQ(field_named(node, "next")->type, static_cast<std::uint32_t>(&pointer - schema().types));
}

TEST(Tables, StandardLibrary) {
  EXPECT_FIELD(name, "std::basic_string<int8>", String);
  EXPECT_FIELD(route, "std::vector<fleet::Waypoint>", Container);
  EXPECT_FIELD(trims, "std::array<int16,4>", Array);
  EXPECT_FIELD(recent, "std::deque<int32>", Container);
  EXPECT_FIELD(samples, "std::list<float64>", Container);
  EXPECT_FIELD(named, "std::map<std::basic_string<int8>,fleet::Waypoint>", Container);
  EXPECT_FIELD(labels, "std::unordered_map<int32,std::basic_string<int8>>", Container);
  EXPECT_FIELD(visited, "std::set<int32>", Container);
  EXPECT_FIELD(home_alt, "std::optional<float64>", Optional);
  EXPECT_FIELD(range, "std::pair<int32,float64>", Struct);
  EXPECT_FIELD(triple, "std::tuple<int32,float64,int8>", Struct);
  EXPECT_FIELD(rally, "std::unique_ptr<fleet::Waypoint>", UniquePtr);
  EXPECT_FIELD(shared, "std::shared_ptr<fleet::Node>", SharedPtr);
  EXPECT_FIELD(status, "std::variant<int32,std::basic_string<int8>,fleet::Waypoint>", Variant);

  const symcr::TypeInfo& route = *type_named("std::vector<fleet::Waypoint>");
  EXPECT_EQ(route.container_kind, static_cast<std::uint8_t>(symcr::ContainerKind::Vector));
  EXPECT_STREQ(type_at(route.element).name, "fleet::Waypoint");
  ASSERT_NE(route.ops, nullptr);
  everything.route.assign(3, fleet::Waypoint{1, 2, 3});
  EXPECT_EQ(static_cast<const symcr::ContainerOps*>(route.ops)->size(&everything.route), 3u);

  const symcr::TypeInfo& named = *type_named("std::map<std::basic_string<int8>,fleet::Waypoint>");
  const symcr::TypeInfo& element = type_at(named.element);
  using Element = symcr::ops::element_t<std::map<std::string, fleet::Waypoint>>;
  EXPECT_STREQ(element.name, "std::pair<std::basic_string<int8>,fleet::Waypoint>");
  EXPECT_EQ(element.size, sizeof(Element));
  EXPECT_EQ(field_named(element, "second")->offset, offsetof(Element, second));
  EXPECT_NE(element.lifecycle, nullptr);  // staged before insertion
  EXPECT_NE(type_named("std::set<int32>")->ops, nullptr);
  EXPECT_NE(type_at(type_named("std::set<int32>")->element).lifecycle, nullptr);

  const symcr::TypeInfo& triple = *type_named("std::tuple<int32,float64,int8>");
  ASSERT_EQ(triple.field_count, 3u);
  EXPECT_EQ(triple.fields[0].offset, distance(&everything.triple, &std::get<0>(everything.triple)));
  EXPECT_EQ(triple.fields[1].offset, distance(&everything.triple, &std::get<1>(everything.triple)));
  EXPECT_EQ(triple.fields[2].offset, distance(&everything.triple, &std::get<2>(everything.triple)));

  const symcr::TypeInfo& range = *type_named("std::pair<int32,float64>");
  EXPECT_EQ(field_named(range, "second")->offset, offsetof(decltype(everything.range), second));

  const symcr::TypeInfo& status =
      *type_named("std::variant<int32,std::basic_string<int8>,fleet::Waypoint>");
  ASSERT_EQ(status.alternative_count, 3u);
  EXPECT_STREQ(type_at(status.alternatives[2]).name, "fleet::Waypoint");
  EXPECT_NE(status.ops, nullptr);
  EXPECT_EQ(type_named("std::array<int16,4>")->count, 4u);
  EXPECT_NE(type_named("std::unique_ptr<fleet::Waypoint>")->ops, nullptr);
  EXPECT_NE(type_named("std::shared_ptr<fleet::Node>")->ops, nullptr);
}

TEST(Tables, RangesAndRenames) {
  const symcr::TypeInfo& limits = *type_named("fleet::Limits");
  const symcr::FieldInfo* throttle = field_named(limits, "throttle");
  ASSERT_NE(throttle, nullptr);
  EXPECT_TRUE(throttle->flags & symcr::kFieldHasRange);
  ASSERT_NE(throttle->range, nullptr);
  EXPECT_EQ(throttle->range->min, 0.0);
  EXPECT_EQ(throttle->range->max, 1.0);
  const symcr::FieldInfo* altitude = field_named(limits, "altitude");
  ASSERT_NE(altitude->range, nullptr);
  EXPECT_EQ(altitude->range->min, -100.5);
  EXPECT_EQ(altitude->range->max, 1e4);
  const symcr::FieldInfo* yaw = field_named(limits, "yaw");
  EXPECT_FALSE(yaw->flags & symcr::kFieldHasRange);
  ASSERT_NE(yaw->renamed_from, nullptr);
  EXPECT_STREQ(yaw->renamed_from[0], "heading");
  EXPECT_STREQ(yaw->renamed_from[1], "bearing");
  EXPECT_EQ(yaw->renamed_from[2], nullptr);
  EXPECT_EQ(throttle->renamed_from, nullptr);
}

TEST(Tables, RootsOfEveryLinkage) {
  struct Expected {
    const char* name;
    const void* address;
    const char* type;
  } expected[] = {
      {"everything", &everything, "fleet::Everything"},
      {"hidden_root", hidden_root_address(), "(anonymous namespace)::Hidden"},
      {"fleet::fleet_counter", &fleet::fleet_counter, "int32"},
      {"Registry::count", Registry::count_address(), "int32"},
      {"local_static_address::calls", local_static_address(), "int32"},
  };
  EXPECT_EQ(schema().root_count, std::size(expected));
  for (const Expected& e : expected) {
    const symcr::RootInfo* root = root_named(e.name);
    ASSERT_NE(root, nullptr) << e.name;
    EXPECT_EQ(root->address, e.address) << e.name;
    EXPECT_STREQ(type_at(root->type).name, e.type) << e.name;
  }
}

// The serialised form symcr-gen embeds is the program's tables serialised by the runtime, byte
// for byte, with their hash; and it is what the program writes into its checkpoints.
TEST(Tables, EmbeddedSerialisedFormIsTheTablesSerialised) {
  const symcr::SerialisedSchema* embedded = symcr_program_serialised_schema();
  ASSERT_NE(embedded, nullptr);
  std::vector<std::uint8_t> serialised;
  symcr::detail::serialise_schema(schema(), serialised);
  ASSERT_EQ(embedded->size, serialised.size());
  EXPECT_EQ(std::memcmp(embedded->bytes, serialised.data(), serialised.size()), 0);
  EXPECT_EQ(embedded->hash, symcr::format::fnv1a64(serialised.data(), serialised.size()));
  const symcr::detail::SchemaBlob& used = symcr::detail::schema_blob(schema());
  EXPECT_EQ(used.data, embedded->bytes);  // the constant itself: nothing serialised at run time
  EXPECT_EQ(used.hash, embedded->hash);
}

}  // namespace
