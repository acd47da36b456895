// Hand-written schemas for the payload engine's tests, in the form symcr-gen emits: static
// FieldInfo/TypeInfo/RootInfo tables over real variables, offsets from offsetof (or
// symcr::ops::offset_of where offsetof is not allowed), ops from <symcr/ops.hpp>.
// The generator replaces this file once it exists.
//
// Every "world" comes in two builds, namespace ..0 (the writer: the old build) and ..1 (the
// reader: the patched build), with really different struct definitions.
#ifndef SYMCR_TESTS_RUNTIME_HANDWRITTEN_SCHEMAS_HPP
#define SYMCR_TESTS_RUNTIME_HANDWRITTEN_SCHEMAS_HPP

#include <cstddef>
#include <cstdint>
#include <deque>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "schema_tables.hpp"
#include "symcr/ops.hpp"
#include "symcr/generated.hpp"

namespace engine_tests {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

template <typename Derived, typename Base>
std::size_t base_offset() {
  alignas(Derived) static unsigned char storage[sizeof(Derived)];
  auto* derived = reinterpret_cast<Derived*>(storage);
  return static_cast<std::size_t>(reinterpret_cast<unsigned char*>(static_cast<Base*>(derived)) -
                                  storage);
}

// =============================================================================================
// World A: scalars, structs, arrays, unions, enums, bit-fields, roots.
namespace a0 {
enum class Mode : std::uint8_t { STABILIZE = 0, AUTO = 1, GUIDED = 2, LAND = 3 };
struct Inner {
  std::int32_t first;
  std::int32_t second;
  float third;
};
union Blob {
  std::uint32_t word;
  float real;
};
union Blob2 {
  std::uint32_t word;
  std::uint16_t half;
};
struct Bits {
  std::uint32_t a : 3;
  std::uint32_t b : 5;
  std::int32_t c : 4;
};
struct Basic {
  std::int16_t heading;
  std::int32_t narrow_fit;
  std::int32_t narrow_nofit;
  float ratio;
  double precise;
  std::int32_t to_float_ok;
  std::int32_t to_float_bad;
  double to_int_ok;
  double to_int_bad;
  Mode mode;
  Mode mode_unknown;
  std::int32_t removed;
  std::uint8_t same;
  std::int32_t grow[3];
  std::int32_t shrink[4];
  Inner inner;
  Blob blob;
  Blob2 blob2;
  Inner kind_change;
  Bits bits;
  std::int32_t speed;  // the reader gives it a range
};
extern Basic basic;
extern std::int32_t old_counter;
extern std::int32_t gone_root;
const symcr::Schema& schema();
}  // namespace a0

namespace a1 {
enum class Mode : std::int32_t { LAND = 0, AUTO = 5, STABILIZE = 7, RTL = 9 };
struct Inner {
  float third;
  std::int32_t first;
  std::int32_t added_inner = 5;
  std::int32_t second;
};
union Blob {
  float real;
  std::uint32_t word;
};
union Blob2 {
  std::uint64_t wide;
  std::uint32_t word;
};
struct Bits {
  std::uint32_t a : 5;
  std::int32_t c : 3;
  std::uint32_t b : 6;
};
struct Basic {
  std::int32_t added = 77;
  double ratio = -1;
  float precise = -1;
  std::int32_t yaw = -1;
  std::int16_t narrow_fit = -1;
  std::int16_t narrow_nofit = -1;
  float to_float_ok = -1, to_float_bad = -1;
  std::int32_t to_int_ok = -1, to_int_bad = -1;
  Mode mode = Mode::RTL, mode_unknown = Mode::RTL;
  std::uint8_t same = 0;
  std::int32_t grow[5] = {-1, -1, -1, -1, -1};
  std::int32_t shrink[2] = {-1, -1};
  Inner inner;
  Blob blob{};
  Blob2 blob2{};
  std::int32_t kind_change = -1;
  Bits bits{};
  std::int32_t speed = -1;
};
extern Basic basic;
extern std::int32_t counter;
extern std::int32_t new_root;
const symcr::Schema& schema();
}  // namespace a1

// =============================================================================================
// World B: strings and containers.
namespace b0 {
struct Item {
  std::int32_t id;
  double weight;
  bool operator<(const Item& other) const { return id < other.id; }
};
struct Bag {
  std::vector<std::int16_t> vec;
  std::map<std::string, std::int32_t> map;
  std::set<std::int32_t> set;
  std::list<Item> list;
  std::deque<std::int32_t> deque;
  std::string str;
  std::u16string wide;
  std::optional<Item> opt;
  std::optional<Item> opt_empty;
  std::variant<std::int32_t, std::string, Item> var_item;
  std::variant<std::int32_t, std::string, Item> var_gone;
  std::unique_ptr<Item> up;
  std::unique_ptr<Item> up_null;
};
extern Bag bag;
const symcr::Schema& schema();
}  // namespace b0

namespace b1 {
struct Item {
  std::int64_t id = -1;
  std::int32_t extra = 42;
  double weight = -1;
};
struct Bag {
  std::vector<std::int32_t> vec;
  std::map<std::string, std::int64_t> map;
  std::vector<std::int32_t> set;  // the patch made the set a vector
  std::list<Item> list;
  std::deque<std::int32_t> deque;
  std::string str;
  std::string wide;  // narrowed to 8-bit characters
  std::optional<Item> opt;
  std::optional<Item> opt_empty{Item{}};
  std::variant<std::string, double, Item> var_item;  // int32 removed, alternatives reordered
  std::variant<std::string, double, Item> var_gone;
  std::unique_ptr<Item> up;
  std::unique_ptr<Item> up_null{new Item()};
};
extern Bag bag;
const symcr::Schema& schema();
}  // namespace b1

// =============================================================================================
// World C: pointers, sharing, cycles, heap objects.
namespace c0 {
struct Node {
  std::int32_t value;
  Node* next;
  Node* other;
};
struct Nav {
  double lat;
  double lon;
  std::int32_t target[4];
};
struct Leaf {
  std::int32_t payload;
};
struct World {
  Nav nav;
  std::vector<Nav> navs;
  Node* head;
  std::int32_t* target_ptr;   // -> nav.target[2]
  double* lon_ptr;            // -> nav.lon
  Nav* pick;                  // -> navs[1]
  Node* again;                // the same node as head->next
  std::int32_t* outside;      // -> a non-root static
  Node* null_ptr;
  std::shared_ptr<Leaf> s1;
  std::shared_ptr<Leaf> s2;   // the same Leaf
  std::int32_t* into_node;    // -> head->value (after head: resolves inside the heap object)
};
extern World world;
const symcr::Schema& schema();
}  // namespace c0

namespace c1 {
struct Node {
  std::int32_t tag = 9;
  std::int32_t value = -1;
  Node* other = nullptr;
  Node* next = nullptr;
};
struct Nav {
  std::int32_t target[6] = {};
  double lon = 0;
  std::int32_t fresh = 3;
  double lat = 0;
};
struct Leaf {
  std::int64_t payload = -1;
};
struct World {
  std::shared_ptr<Leaf> s2;
  std::int32_t* into_node = nullptr;
  Node* null_ptr = nullptr;
  std::int32_t* outside = nullptr;
  Node* again = nullptr;
  Nav* pick = nullptr;
  double* lon_ptr = nullptr;
  std::int32_t* target_ptr = nullptr;
  Node* head = nullptr;
  std::vector<Nav> navs;
  std::shared_ptr<Leaf> s1;
  Nav nav;
};
extern World world;
const symcr::Schema& schema();
}  // namespace c1

// A world whose first pointer targets the inside of a heap object met only later.
namespace c_interior {
struct Holder {
  std::int32_t* into_node;  // met first: -> node->value
  c0::Node* node;
};
extern Holder holder;
const symcr::Schema& schema();
}  // namespace c_interior

// =============================================================================================
// World D: base classes.
namespace d0 {
struct Base {
  std::int32_t id;
};
struct Gone {
  std::int32_t g;
};
struct Derived : Base, Gone {
  std::int32_t x;
};
extern Derived derived;
const symcr::Schema& schema();
}  // namespace d0

namespace d1 {
struct Base {
  std::int32_t id = -1;
  std::int32_t base_added = 11;  // the base gained a field
};
struct Extra {
  std::int32_t e = 21;
};
struct Derived : Extra, Base {  // base Extra added, base Gone removed
  std::int32_t x = -1;
};
extern Derived derived;
const symcr::Schema& schema();
}  // namespace d1

// =============================================================================================
// World E: a small flat state for corruption tests, and a validated type.
namespace e0 {
struct Small {
  std::int16_t a;
  std::uint8_t flag;
  bool on;
  double d;
  std::vector<std::int16_t> v;
  std::string s;
  std::int32_t* p;  // -> arr[1]
  std::int32_t arr[3];
};
struct Checked {
  std::int32_t lo;
  std::int32_t hi;
};
extern Small small;
extern Checked good;
extern Checked bad;
const symcr::Schema& schema();
}  // namespace e0

namespace e1 {
struct Small {
  std::int32_t arr[3] = {-1, -1, -1};
  std::int32_t* p = nullptr;
  std::string s = "reader";
  std::vector<std::int16_t> v{9, 9};
  double d = -1;
  bool on = false;
  std::uint8_t flag = 0;
  std::int16_t a = -1;
  bool operator==(const Small& o) const {
    return arr[0] == o.arr[0] && arr[1] == o.arr[1] && arr[2] == o.arr[2] && p == o.p &&
           s == o.s && v == o.v && d == o.d && on == o.on && flag == o.flag && a == o.a;
  }
};
struct Checked {
  std::int32_t lo = -1;
  std::int32_t hi = -1;
};
bool validate_checked(const void* object);  // lo <= hi
extern Small small;
extern Checked good;
extern Checked bad;
const symcr::Schema& schema();
}  // namespace e1

// =============================================================================================
// A pointer graph of many nodes (performance and allocation tests).
namespace g {
struct Node {
  std::int64_t value;
  Node* next;
  Node* jump;
};
struct Graph {
  Node* first;
  std::int32_t count;
};
extern Graph graph;
const symcr::Schema& schema();
}  // namespace g

// A ~300-byte state with ~100 scalar fields (the specimen's order of magnitude).
namespace p {
struct Vec3 {
  float x, y, z;
};
struct Pid {
  float kp, ki, kd, integrator, last_error;
  std::int16_t limit;
};
struct State {
  Vec3 position, velocity, attitude, rates, accel, gyro, mag, target;
  Pid pids[10];
  std::int32_t mode;
  std::uint32_t ticks;
  std::uint8_t armed;
  double lat, lon;
  float alt;
  std::int16_t waypoint;
};
extern State state;
const symcr::Schema& schema();
}  // namespace p

// A type recursive through a container, and a vector of many values to narrow.
namespace t0 {
struct Tree {
  std::int32_t value;
  std::vector<Tree> children;
};
extern Tree tree;
extern std::vector<std::int32_t> many;
const symcr::Schema& schema();
}  // namespace t0

namespace t1 {
struct Tree {
  std::vector<Tree> children;
  std::int64_t value = -1;
};
extern Tree tree;
extern std::vector<std::int8_t> many;
const symcr::Schema& schema();
}  // namespace t1

}  // namespace engine_tests

#endif  // SYMCR_TESTS_RUNTIME_HANDWRITTEN_SCHEMAS_HPP
