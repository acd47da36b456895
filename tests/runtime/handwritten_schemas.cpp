// The tables for handwritten_schemas.hpp (what symcr-gen will emit for these structs).
#include "handwritten_schemas.hpp"

namespace engine_tests {

using symcr::ContainerKind;
using symcr::EnumeratorInfo;
using symcr::RootInfo;
using symcr::Schema;
using symcr::ops::offset_of;
#define SYMCR_COUNT(array) static_cast<std::uint32_t>(sizeof(array) / sizeof((array)[0]))

// ---- World A ---------------------------------------------------------------------------------
namespace a0 {
Basic basic;
std::int32_t old_counter;
std::int32_t gone_root;
const Schema& schema() {
  static const EnumeratorInfo mode_enumerators[] = {
      {"STABILIZE", 0}, {"AUTO", 1}, {"GUIDED", 2}, {"LAND", 3}};
  static const FieldInfo inner_fields[] = {
      field("first", 1, offsetof(Inner, first)),
      field("second", 1, offsetof(Inner, second)),
      field("third", 2, offsetof(Inner, third))};
  static const FieldInfo bits_fields[] = {
      bit_field("a", 11, 0, 3), bit_field("b", 11, 3, 5), bit_field("c", 1, 8, 4)};
  static const FieldInfo basic_fields[] = {
      field("heading", 0, offsetof(Basic, heading)),
      field("narrow_fit", 1, offsetof(Basic, narrow_fit)),
      field("narrow_nofit", 1, offsetof(Basic, narrow_nofit)),
      field("ratio", 2, offsetof(Basic, ratio)),
      field("precise", 3, offsetof(Basic, precise)),
      field("to_float_ok", 1, offsetof(Basic, to_float_ok)),
      field("to_float_bad", 1, offsetof(Basic, to_float_bad)),
      field("to_int_ok", 3, offsetof(Basic, to_int_ok)),
      field("to_int_bad", 3, offsetof(Basic, to_int_bad)),
      field("mode", 5, offsetof(Basic, mode)),
      field("mode_unknown", 5, offsetof(Basic, mode_unknown)),
      field("removed", 1, offsetof(Basic, removed)),
      field("same", 4, offsetof(Basic, same)),
      field("grow", 6, offsetof(Basic, grow)),
      field("shrink", 7, offsetof(Basic, shrink)),
      field("inner", 8, offsetof(Basic, inner)),
      field("blob", 9, offsetof(Basic, blob)),
      field("blob2", 10, offsetof(Basic, blob2)),
      field("kind_change", 8, offsetof(Basic, kind_change)),
      field("bits", 12, offsetof(Basic, bits)),
      field("speed", 1, offsetof(Basic, speed))};
  static const TypeInfo types[] = {
      scalar("int16", Kind::Int, 2),
      scalar("int32", Kind::Int, 4),
      scalar("float32", Kind::Float, 4),
      scalar("float64", Kind::Float, 8),
      scalar("uint8", Kind::UInt, 1),
      enumeration("Mode", 1, 4, mode_enumerators, SYMCR_COUNT(mode_enumerators)),
      array("int32[3]", 1, 3, 12, 4),
      array("int32[4]", 1, 4, 16, 4),
      record("Inner", sizeof(Inner), alignof(Inner), inner_fields, SYMCR_COUNT(inner_fields)),
      union_of("Blob", sizeof(Blob), alignof(Blob)),
      union_of("Blob2", sizeof(Blob2), alignof(Blob2)),
      scalar("uint32", Kind::UInt, 4),
      record("Bits", sizeof(Bits), alignof(Bits), bits_fields, SYMCR_COUNT(bits_fields)),
      record("Basic", sizeof(Basic), alignof(Basic), basic_fields, SYMCR_COUNT(basic_fields)),
  };
  static const RootInfo roots[] = {{"basic", 13, &basic, 0, nullptr},
                                   {"old_counter", 1, &old_counter, 0, nullptr},
                                   {"gone_root", 1, &gone_root, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace a0

namespace a1 {
Basic basic;
std::int32_t counter = -1;
std::int32_t new_root = 99;
const Schema& schema() {
  static const EnumeratorInfo mode_enumerators[] = {
      {"LAND", 0}, {"AUTO", 5}, {"STABILIZE", 7}, {"RTL", 9}};
  static const FieldInfo inner_fields[] = {
      field("third", 2, offsetof(Inner, third)),
      field("first", 1, offsetof(Inner, first)),
      field("added_inner", 1, offsetof(Inner, added_inner)),
      field("second", 1, offsetof(Inner, second))};
  static const FieldInfo bits_fields[] = {
      bit_field("a", 11, 0, 5), bit_field("c", 1, 5, 3), bit_field("b", 11, 8, 6)};
  static const char* const yaw_aliases[] = {"heading", nullptr};
  static constexpr symcr::FieldRange kSpeedRange{0, 100};
  static const FieldInfo basic_fields[] = {
      field("added", 1, offsetof(Basic, added)),
      field("ratio", 3, offsetof(Basic, ratio)),
      field("precise", 2, offsetof(Basic, precise)),
      field("yaw", 1, offsetof(Basic, yaw), yaw_aliases),
      field("narrow_fit", 0, offsetof(Basic, narrow_fit)),
      field("narrow_nofit", 0, offsetof(Basic, narrow_nofit)),
      field("to_float_ok", 2, offsetof(Basic, to_float_ok)),
      field("to_float_bad", 2, offsetof(Basic, to_float_bad)),
      field("to_int_ok", 1, offsetof(Basic, to_int_ok)),
      field("to_int_bad", 1, offsetof(Basic, to_int_bad)),
      field("mode", 5, offsetof(Basic, mode)),
      field("mode_unknown", 5, offsetof(Basic, mode_unknown)),
      field("same", 4, offsetof(Basic, same)),
      field("grow", 6, offsetof(Basic, grow)),
      field("shrink", 7, offsetof(Basic, shrink)),
      field("inner", 8, offsetof(Basic, inner)),
      field("blob", 9, offsetof(Basic, blob)),
      field("blob2", 10, offsetof(Basic, blob2)),
      field("kind_change", 1, offsetof(Basic, kind_change)),
      field("bits", 12, offsetof(Basic, bits)),
      ranged("speed", 1, offsetof(Basic, speed), kSpeedRange)};
  static const TypeInfo types[] = {
      scalar("int16", Kind::Int, 2),
      scalar("int32", Kind::Int, 4),
      scalar("float32", Kind::Float, 4),
      scalar("float64", Kind::Float, 8),
      scalar("uint8", Kind::UInt, 1),
      enumeration("Mode", 4, 1, mode_enumerators, SYMCR_COUNT(mode_enumerators)),
      array("int32[5]", 1, 5, 20, 4),
      array("int32[2]", 1, 2, 8, 4),
      record("Inner", sizeof(Inner), alignof(Inner), inner_fields, SYMCR_COUNT(inner_fields)),
      union_of("Blob", sizeof(Blob), alignof(Blob)),
      union_of("Blob2", sizeof(Blob2), alignof(Blob2)),
      scalar("uint32", Kind::UInt, 4),
      record("Bits", sizeof(Bits), alignof(Bits), bits_fields, SYMCR_COUNT(bits_fields)),
      record("Basic", sizeof(Basic), alignof(Basic), basic_fields, SYMCR_COUNT(basic_fields)),
  };
  static const char* const counter_aliases[] = {"old_counter", nullptr};
  static const RootInfo roots[] = {{"basic", 13, &basic, 0, nullptr},
                                   {"counter", 1, &counter, 0, counter_aliases},
                                   {"new_root", 1, &new_root, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace a1

// ---- World B ---------------------------------------------------------------------------------
namespace b0 {
Bag bag;
using Pair = std::pair<std::string, std::int32_t>;
using Variant = std::variant<std::int32_t, std::string, Item>;
const Schema& schema() {
  static const FieldInfo pair_fields[] = {field("first", 6, offset_of(&Pair::first)),
                                          field("second", 1, offset_of(&Pair::second))};
  static const FieldInfo item_fields[] = {field("id", 1, offsetof(Item, id)),
                                          field("weight", 2, offsetof(Item, weight))};
  static const std::uint32_t alternatives[] = {1, 6, 10};
  static const FieldInfo bag_fields[] = {
      field("vec", 5, offset_of(&Bag::vec)),
      field("map", 8, offset_of(&Bag::map)),
      field("set", 9, offset_of(&Bag::set)),
      field("list", 11, offset_of(&Bag::list)),
      field("deque", 12, offset_of(&Bag::deque)),
      field("str", 6, offset_of(&Bag::str)),
      field("wide", 13, offset_of(&Bag::wide)),
      field("opt", 14, offset_of(&Bag::opt)),
      field("opt_empty", 14, offset_of(&Bag::opt_empty)),
      field("var_item", 15, offset_of(&Bag::var_item)),
      field("var_gone", 15, offset_of(&Bag::var_gone)),
      field("up", 16, offset_of(&Bag::up)),
      field("up_null", 16, offset_of(&Bag::up_null))};
  static const TypeInfo types[] = {
      scalar("int16", Kind::Int, 2),
      scalar("int32", Kind::Int, 4),
      scalar("float64", Kind::Float, 8),
      scalar("int8", Kind::Int, 1),
      scalar("uint16", Kind::UInt, 2),
      holder("std::vector<int16>", Kind::Container, sizeof(bag.vec), alignof(decltype(bag.vec)), 0,
             &symcr::ops::container<std::vector<std::int16_t>>::table),
      holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), 3,
             &symcr::ops::string<std::string>::table),
      record("std::pair<std::string,int32>", sizeof(Pair), alignof(Pair), pair_fields,
             SYMCR_COUNT(pair_fields), &symcr::ops::lifecycle<Pair>::table),
      holder("std::map<std::string,int32>", Kind::Container, sizeof(bag.map), alignof(decltype(bag.map)),
             7, &symcr::ops::container<std::map<std::string, std::int32_t>>::table, ContainerKind::Map),
      holder("std::set<int32>", Kind::Container, sizeof(bag.set), alignof(decltype(bag.set)), 1,
             &symcr::ops::container<std::set<std::int32_t>>::table, ContainerKind::Set),
      record("Item", sizeof(Item), alignof(Item), item_fields, SYMCR_COUNT(item_fields),
             &symcr::ops::lifecycle<Item>::table),
      holder("std::list<Item>", Kind::Container, sizeof(bag.list), alignof(decltype(bag.list)), 10,
             &symcr::ops::container<std::list<Item>>::table, ContainerKind::List),
      holder("std::deque<int32>", Kind::Container, sizeof(bag.deque), alignof(decltype(bag.deque)), 1,
             &symcr::ops::container<std::deque<std::int32_t>>::table, ContainerKind::Deque),
      holder("std::u16string", Kind::String, sizeof(std::u16string), alignof(std::u16string), 4,
             &symcr::ops::string<std::u16string>::table),
      holder("std::optional<Item>", Kind::Optional, sizeof(bag.opt), alignof(decltype(bag.opt)), 10,
             &symcr::ops::optional<std::optional<Item>>::table),
      variant_of("std::variant<int32,std::string,Item>", sizeof(Variant), alignof(Variant),
                 alternatives, 3, &symcr::ops::variant<Variant>::table),
      holder("std::unique_ptr<Item>", Kind::UniquePtr, sizeof(bag.up), alignof(decltype(bag.up)), 10,
             &symcr::ops::unique_ptr<std::unique_ptr<Item>>::table),
      record("Bag", sizeof(Bag), alignof(Bag), bag_fields, SYMCR_COUNT(bag_fields)),
  };
  static const RootInfo roots[] = {{"bag", 17, &bag, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace b0

namespace b1 {
Bag bag;
using Pair = std::pair<std::string, std::int64_t>;
using Variant = std::variant<std::string, double, Item>;
const Schema& schema() {
  static const FieldInfo pair_fields[] = {field("first", 5, offset_of(&Pair::first)),
                                          field("second", 1, offset_of(&Pair::second))};
  static const FieldInfo item_fields[] = {field("id", 1, offsetof(Item, id)),
                                          field("extra", 0, offsetof(Item, extra)),
                                          field("weight", 2, offsetof(Item, weight))};
  static const std::uint32_t alternatives[] = {5, 2, 8};
  static const FieldInfo bag_fields[] = {
      field("vec", 4, offset_of(&Bag::vec)),
      field("map", 7, offset_of(&Bag::map)),
      field("set", 4, offset_of(&Bag::set)),
      field("list", 9, offset_of(&Bag::list)),
      field("deque", 10, offset_of(&Bag::deque)),
      field("str", 5, offset_of(&Bag::str)),
      field("wide", 5, offset_of(&Bag::wide)),
      field("opt", 11, offset_of(&Bag::opt)),
      field("opt_empty", 11, offset_of(&Bag::opt_empty)),
      field("var_item", 12, offset_of(&Bag::var_item)),
      field("var_gone", 12, offset_of(&Bag::var_gone)),
      field("up", 13, offset_of(&Bag::up)),
      field("up_null", 13, offset_of(&Bag::up_null))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("int64", Kind::Int, 8),
      scalar("float64", Kind::Float, 8),
      scalar("int8", Kind::Int, 1),
      holder("std::vector<int32>", Kind::Container, sizeof(bag.vec), alignof(decltype(bag.vec)), 0,
             &symcr::ops::container<std::vector<std::int32_t>>::table),
      holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), 3,
             &symcr::ops::string<std::string>::table),
      record("std::pair<std::string,int64>", sizeof(Pair), alignof(Pair), pair_fields,
             SYMCR_COUNT(pair_fields), &symcr::ops::lifecycle<Pair>::table),
      holder("std::map<std::string,int64>", Kind::Container, sizeof(bag.map), alignof(decltype(bag.map)),
             6, &symcr::ops::container<std::map<std::string, std::int64_t>>::table, ContainerKind::Map),
      record("Item", sizeof(Item), alignof(Item), item_fields, SYMCR_COUNT(item_fields),
             &symcr::ops::lifecycle<Item>::table),
      holder("std::list<Item>", Kind::Container, sizeof(bag.list), alignof(decltype(bag.list)), 8,
             &symcr::ops::container<std::list<Item>>::table, ContainerKind::List),
      holder("std::deque<int32>", Kind::Container, sizeof(bag.deque), alignof(decltype(bag.deque)), 0,
             &symcr::ops::container<std::deque<std::int32_t>>::table, ContainerKind::Deque),
      holder("std::optional<Item>", Kind::Optional, sizeof(bag.opt), alignof(decltype(bag.opt)), 8,
             &symcr::ops::optional<std::optional<Item>>::table),
      variant_of("std::variant<std::string,float64,Item>", sizeof(Variant), alignof(Variant),
                 alternatives, 3, &symcr::ops::variant<Variant>::table),
      holder("std::unique_ptr<Item>", Kind::UniquePtr, sizeof(bag.up), alignof(decltype(bag.up)), 8,
             &symcr::ops::unique_ptr<std::unique_ptr<Item>>::table),
      record("Bag", sizeof(Bag), alignof(Bag), bag_fields, SYMCR_COUNT(bag_fields)),
  };
  static const RootInfo roots[] = {{"bag", 14, &bag, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace b1

// ---- World C ---------------------------------------------------------------------------------
namespace c0 {
World world;
const Schema& schema() {
  static const FieldInfo nav_fields[] = {field("lat", 1, offsetof(Nav, lat)),
                                         field("lon", 1, offsetof(Nav, lon)),
                                         field("target", 2, offsetof(Nav, target))};
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(Node, value)),
                                          field("next", 6, offsetof(Node, next)),
                                          field("other", 6, offsetof(Node, other))};
  static const FieldInfo leaf_fields[] = {field("payload", 0, offsetof(Leaf, payload))};
  static const FieldInfo world_fields[] = {
      field("nav", 3, offset_of(&World::nav)),
      field("navs", 4, offset_of(&World::navs)),
      field("head", 6, offset_of(&World::head)),
      field("target_ptr", 7, offset_of(&World::target_ptr)),
      field("lon_ptr", 8, offset_of(&World::lon_ptr)),
      field("pick", 9, offset_of(&World::pick)),
      field("again", 6, offset_of(&World::again)),
      field("outside", 7, offset_of(&World::outside)),
      field("null_ptr", 6, offset_of(&World::null_ptr)),
      field("s1", 11, offset_of(&World::s1)),
      field("s2", 11, offset_of(&World::s2)),
      field("into_node", 7, offset_of(&World::into_node))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("float64", Kind::Float, 8),
      array("int32[4]", 0, 4, 16, 4),
      record("Nav", sizeof(Nav), alignof(Nav), nav_fields, SYMCR_COUNT(nav_fields),
             &symcr::ops::lifecycle<Nav>::table),
      holder("std::vector<Nav>", Kind::Container, sizeof(std::vector<Nav>), alignof(std::vector<Nav>), 3,
             &symcr::ops::container<std::vector<Nav>>::table),
      record("Node", sizeof(Node), alignof(Node), node_fields, SYMCR_COUNT(node_fields),
             &symcr::ops::lifecycle<Node>::table),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 5, nullptr),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      holder("float64*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      holder("Nav*", Kind::Pointer, sizeof(void*), alignof(void*), 3, nullptr),
      record("Leaf", sizeof(Leaf), alignof(Leaf), leaf_fields, SYMCR_COUNT(leaf_fields),
             &symcr::ops::lifecycle<Leaf>::table),
      holder("std::shared_ptr<Leaf>", Kind::SharedPtr, sizeof(std::shared_ptr<Leaf>),
             alignof(std::shared_ptr<Leaf>), 10, &symcr::ops::shared_ptr<std::shared_ptr<Leaf>>::table),
      record("World", sizeof(World), alignof(World), world_fields, SYMCR_COUNT(world_fields)),
  };
  static const RootInfo roots[] = {{"world", 12, &world, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace c0

namespace c1 {
World world;
const Schema& schema() {
  static const FieldInfo nav_fields[] = {field("target", 2, offsetof(Nav, target)),
                                         field("lon", 1, offsetof(Nav, lon)),
                                         field("fresh", 0, offsetof(Nav, fresh)),
                                         field("lat", 1, offsetof(Nav, lat))};
  static const FieldInfo node_fields[] = {field("tag", 0, offsetof(Node, tag)),
                                          field("value", 0, offsetof(Node, value)),
                                          field("other", 6, offsetof(Node, other)),
                                          field("next", 6, offsetof(Node, next))};
  static const FieldInfo leaf_fields[] = {field("payload", 13, offsetof(Leaf, payload))};
  static const FieldInfo world_fields[] = {
      field("s2", 11, offset_of(&World::s2)),
      field("into_node", 7, offset_of(&World::into_node)),
      field("null_ptr", 6, offset_of(&World::null_ptr)),
      field("outside", 7, offset_of(&World::outside)),
      field("again", 6, offset_of(&World::again)),
      field("pick", 9, offset_of(&World::pick)),
      field("lon_ptr", 8, offset_of(&World::lon_ptr)),
      field("target_ptr", 7, offset_of(&World::target_ptr)),
      field("head", 6, offset_of(&World::head)),
      field("navs", 4, offset_of(&World::navs)),
      field("s1", 11, offset_of(&World::s1)),
      field("nav", 3, offset_of(&World::nav))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("float64", Kind::Float, 8),
      array("int32[6]", 0, 6, 24, 4),
      record("Nav", sizeof(Nav), alignof(Nav), nav_fields, SYMCR_COUNT(nav_fields),
             &symcr::ops::lifecycle<Nav>::table),
      holder("std::vector<Nav>", Kind::Container, sizeof(std::vector<Nav>), alignof(std::vector<Nav>), 3,
             &symcr::ops::container<std::vector<Nav>>::table),
      record("Node", sizeof(Node), alignof(Node), node_fields, SYMCR_COUNT(node_fields),
             &symcr::ops::lifecycle<Node>::table),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 5, nullptr),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      holder("float64*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      holder("Nav*", Kind::Pointer, sizeof(void*), alignof(void*), 3, nullptr),
      record("Leaf", sizeof(Leaf), alignof(Leaf), leaf_fields, SYMCR_COUNT(leaf_fields),
             &symcr::ops::lifecycle<Leaf>::table),
      holder("std::shared_ptr<Leaf>", Kind::SharedPtr, sizeof(std::shared_ptr<Leaf>),
             alignof(std::shared_ptr<Leaf>), 10, &symcr::ops::shared_ptr<std::shared_ptr<Leaf>>::table),
      record("World", sizeof(World), alignof(World), world_fields, SYMCR_COUNT(world_fields)),
      scalar("int64", Kind::Int, 8),
  };
  static const RootInfo roots[] = {{"world", 12, &world, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace c1

namespace c_interior {
Holder holder;
const Schema& schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(c0::Node, value)),
                                          field("next", 3, offsetof(c0::Node, next)),
                                          field("other", 3, offsetof(c0::Node, other))};
  static const FieldInfo holder_fields[] = {field("into_node", 1, offsetof(Holder, into_node)),
                                            field("node", 3, offsetof(Holder, node))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      engine_tests::holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      record("Node", sizeof(c0::Node), alignof(c0::Node), node_fields, SYMCR_COUNT(node_fields),
             &symcr::ops::lifecycle<c0::Node>::table),
      engine_tests::holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 2, nullptr),
      record("Holder", sizeof(Holder), alignof(Holder), holder_fields, SYMCR_COUNT(holder_fields)),
  };
  static const RootInfo roots[] = {{"holder", 4, &holder, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace c_interior

// ---- World D ---------------------------------------------------------------------------------
namespace d0 {
Derived derived;
const Schema& schema() {
  static const FieldInfo base_fields[] = {field("id", 0, offsetof(Base, id))};
  static const FieldInfo gone_fields[] = {field("g", 0, offsetof(Gone, g))};
  static const FieldInfo derived_fields[] = {base("Base", 1, base_offset<Derived, Base>()),
                                             base("Gone", 2, base_offset<Derived, Gone>()),
                                             field("x", 0, offset_of(&Derived::x))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      record("Base", sizeof(Base), alignof(Base), base_fields, 1),
      record("Gone", sizeof(Gone), alignof(Gone), gone_fields, 1),
      record("Derived", sizeof(Derived), alignof(Derived), derived_fields, 3),
  };
  static const RootInfo roots[] = {{"derived", 3, &derived, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace d0

namespace d1 {
Derived derived;
const Schema& schema() {
  static const FieldInfo base_fields[] = {field("id", 0, offsetof(Base, id)),
                                          field("base_added", 0, offsetof(Base, base_added))};
  static const FieldInfo extra_fields[] = {field("e", 0, offsetof(Extra, e))};
  static const FieldInfo derived_fields[] = {base("Extra", 2, base_offset<Derived, Extra>()),
                                             base("Base", 1, base_offset<Derived, Base>()),
                                             field("x", 0, offset_of(&Derived::x))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      record("Base", sizeof(Base), alignof(Base), base_fields, 2),
      record("Extra", sizeof(Extra), alignof(Extra), extra_fields, 1),
      record("Derived", sizeof(Derived), alignof(Derived), derived_fields, 3),
  };
  static const RootInfo roots[] = {{"derived", 3, &derived, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace d1

// ---- World E ---------------------------------------------------------------------------------
namespace e0 {
Small small;
Checked good;
Checked bad;
const Schema& schema() {
  static const FieldInfo small_fields[] = {
      field("a", 0, offset_of(&Small::a)),     field("flag", 1, offset_of(&Small::flag)),
      field("on", 2, offset_of(&Small::on)),   field("d", 3, offset_of(&Small::d)),
      field("v", 4, offset_of(&Small::v)),     field("s", 6, offset_of(&Small::s)),
      field("p", 8, offset_of(&Small::p)),     field("arr", 9, offset_of(&Small::arr))};
  static const FieldInfo checked_fields[] = {field("lo", 7, offsetof(Checked, lo)),
                                             field("hi", 7, offsetof(Checked, hi))};
  static const TypeInfo types[] = {
      scalar("int16", Kind::Int, 2),
      scalar("uint8", Kind::UInt, 1),
      scalar("bool", Kind::Bool, 1),
      scalar("float64", Kind::Float, 8),
      holder("std::vector<int16>", Kind::Container, sizeof(std::vector<std::int16_t>),
             alignof(std::vector<std::int16_t>), 0, &symcr::ops::container<std::vector<std::int16_t>>::table),
      scalar("int8", Kind::Int, 1),
      holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), 5,
             &symcr::ops::string<std::string>::table),
      scalar("int32", Kind::Int, 4),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 7, nullptr),
      array("int32[3]", 7, 3, 12, 4),
      record("Small", sizeof(Small), alignof(Small), small_fields, SYMCR_COUNT(small_fields)),
      record("Checked", sizeof(Checked), alignof(Checked), checked_fields, 2),
  };
  static const RootInfo roots[] = {{"small", 10, &small, 0, nullptr},
                                   {"good", 11, &good, 0, nullptr},
                                   {"bad", 11, &bad, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace e0

namespace e1 {
Small small;
Checked good;
Checked bad;
bool validate_checked(const void* object) {
  const auto* checked = static_cast<const Checked*>(object);
  return checked->lo <= checked->hi;
}
const Schema& schema() {
  static const FieldInfo small_fields[] = {
      field("arr", 9, offset_of(&Small::arr)), field("p", 8, offset_of(&Small::p)),
      field("s", 6, offset_of(&Small::s)),     field("v", 4, offset_of(&Small::v)),
      field("d", 3, offset_of(&Small::d)),     field("on", 2, offset_of(&Small::on)),
      field("flag", 1, offset_of(&Small::flag)), field("a", 0, offset_of(&Small::a))};
  static const FieldInfo checked_fields[] = {field("lo", 7, offsetof(Checked, lo)),
                                             field("hi", 7, offsetof(Checked, hi))};
  static const TypeInfo types[] = {
      scalar("int16", Kind::Int, 2),
      scalar("uint8", Kind::UInt, 1),
      scalar("bool", Kind::Bool, 1),
      scalar("float64", Kind::Float, 8),
      holder("std::vector<int16>", Kind::Container, sizeof(std::vector<std::int16_t>),
             alignof(std::vector<std::int16_t>), 0, &symcr::ops::container<std::vector<std::int16_t>>::table),
      scalar("int8", Kind::Int, 1),
      holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), 5,
             &symcr::ops::string<std::string>::table),
      scalar("int32", Kind::Int, 4),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 7, nullptr),
      array("int32[3]", 7, 3, 12, 4),
      record("Small", sizeof(Small), alignof(Small), small_fields, SYMCR_COUNT(small_fields)),
      record("Checked", sizeof(Checked), alignof(Checked), checked_fields, 2,
             &symcr::ops::lifecycle<Checked>::table, &validate_checked),
  };
  static const RootInfo roots[] = {{"small", 10, &small, 0, nullptr},
                                   {"good", 11, &good, 0, nullptr},
                                   {"bad", 11, &bad, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace e1

// ---- Graph and the performance state ---------------------------------------------------------
namespace g {
Graph graph;
const Schema& schema() {
  static const FieldInfo node_fields[] = {field("value", 0, offsetof(Node, value)),
                                          field("next", 2, offsetof(Node, next)),
                                          field("jump", 2, offsetof(Node, jump))};
  static const FieldInfo graph_fields[] = {field("first", 2, offsetof(Graph, first)),
                                           field("count", 3, offsetof(Graph, count))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      record("Node", sizeof(Node), alignof(Node), node_fields, 3, &symcr::ops::lifecycle<Node>::table),
      holder("Node*", Kind::Pointer, sizeof(void*), alignof(void*), 1, nullptr),
      scalar("int32", Kind::Int, 4),
      record("Graph", sizeof(Graph), alignof(Graph), graph_fields, 2),
  };
  static const RootInfo roots[] = {{"graph", 4, &graph, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace g

namespace p {
State state;
const Schema& schema() {
  static const FieldInfo vec_fields[] = {field("x", 0, offsetof(Vec3, x)),
                                         field("y", 0, offsetof(Vec3, y)),
                                         field("z", 0, offsetof(Vec3, z))};
  static const FieldInfo pid_fields[] = {
      field("kp", 0, offsetof(Pid, kp)), field("ki", 0, offsetof(Pid, ki)),
      field("kd", 0, offsetof(Pid, kd)), field("integrator", 0, offsetof(Pid, integrator)),
      field("last_error", 0, offsetof(Pid, last_error)), field("limit", 1, offsetof(Pid, limit))};
  static const FieldInfo state_fields[] = {
      field("position", 2, offsetof(State, position)), field("velocity", 2, offsetof(State, velocity)),
      field("attitude", 2, offsetof(State, attitude)), field("rates", 2, offsetof(State, rates)),
      field("accel", 2, offsetof(State, accel)),       field("gyro", 2, offsetof(State, gyro)),
      field("mag", 2, offsetof(State, mag)),           field("target", 2, offsetof(State, target)),
      field("pids", 4, offsetof(State, pids)),         field("mode", 5, offsetof(State, mode)),
      field("ticks", 6, offsetof(State, ticks)),       field("armed", 7, offsetof(State, armed)),
      field("lat", 8, offsetof(State, lat)),           field("lon", 8, offsetof(State, lon)),
      field("alt", 0, offsetof(State, alt)),           field("waypoint", 1, offsetof(State, waypoint))};
  static const TypeInfo types[] = {
      scalar("float32", Kind::Float, 4),
      scalar("int16", Kind::Int, 2),
      record("Vec3", sizeof(Vec3), alignof(Vec3), vec_fields, 3),
      record("Pid", sizeof(Pid), alignof(Pid), pid_fields, 6),
      array("Pid[10]", 3, 10, sizeof(Pid) * 10, alignof(Pid)),
      scalar("int32", Kind::Int, 4),
      scalar("uint32", Kind::UInt, 4),
      scalar("uint8", Kind::UInt, 1),
      scalar("float64", Kind::Float, 8),
      record("State", sizeof(State), alignof(State), state_fields, SYMCR_COUNT(state_fields)),
  };
  static const RootInfo roots[] = {{"state", 9, &state, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace p

namespace t0 {
Tree tree;
std::vector<std::int32_t> many;
const Schema& schema() {
  static const FieldInfo tree_fields[] = {field("value", 0, offset_of(&Tree::value)),
                                          field("children", 1, offset_of(&Tree::children))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      holder("std::vector<Tree>", Kind::Container, sizeof(std::vector<Tree>), alignof(std::vector<Tree>), 2,
             &symcr::ops::container<std::vector<Tree>>::table),
      record("Tree", sizeof(Tree), alignof(Tree), tree_fields, 2, &symcr::ops::lifecycle<Tree>::table),
      holder("std::vector<int32>", Kind::Container, sizeof(many), alignof(decltype(many)), 0,
             &symcr::ops::container<std::vector<std::int32_t>>::table),
  };
  static const RootInfo roots[] = {{"tree", 2, &tree, 0, nullptr}, {"many", 3, &many, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace t0

namespace t1 {
Tree tree;
std::vector<std::int8_t> many;
const Schema& schema() {
  static const FieldInfo tree_fields[] = {field("children", 1, offset_of(&Tree::children)),
                                          field("value", 0, offset_of(&Tree::value))};
  static const TypeInfo types[] = {
      scalar("int64", Kind::Int, 8),
      holder("std::vector<Tree>", Kind::Container, sizeof(std::vector<Tree>), alignof(std::vector<Tree>), 2,
             &symcr::ops::container<std::vector<Tree>>::table),
      record("Tree", sizeof(Tree), alignof(Tree), tree_fields, 2, &symcr::ops::lifecycle<Tree>::table),
      holder("std::vector<int8>", Kind::Container, sizeof(many), alignof(decltype(many)), 4,
             &symcr::ops::container<std::vector<std::int8_t>>::table),
      scalar("int8", Kind::Int, 1),
  };
  static const RootInfo roots[] = {{"tree", 2, &tree, 0, nullptr}, {"many", 3, &many, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace t1

}  // namespace engine_tests
