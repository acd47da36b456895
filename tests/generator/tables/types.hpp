// Types covering every kind symcr supports (generator/README.md), with public members so that the test can compare
// the generated tables against what g++ computes (sizeof, alignof, offsetof).
#ifndef SYMCR_TESTS_GENERATOR_TABLES_TYPES_HPP
#define SYMCR_TESTS_GENERATOR_TABLES_TYPES_HPP

#include <array>
#include <cstdint>
#include <deque>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include <symcr/symcr.hpp>

namespace fleet {

enum class Mode : std::uint8_t { Idle = 0, Auto = 5, Land = 9 };
enum Legacy : long { First = -3, Second = 1000000000000 };

template <typename T>
class Param {  // an AP_Int8-style wrapper: private value
 public:
  T get() const { return value_; }
  void set(T v) { value_ = v; }
  const void* value_address() const { return &value_; }

 private:
  T value_{};
};
using Int8Param = Param<std::int8_t>;

struct Waypoint {
  double lat;
  double lon;
  float alt;
};

struct Bits {
  std::uint8_t tag;
  unsigned armed : 1;
  unsigned motors : 4;
  unsigned : 0;
  int trim : 7;
  bool flag : 1;
};

struct Base {
  std::int16_t base_value;
};
struct Other {
  double other_value;
};
class Vehicle : public Base, protected Other {
 public:
  int id;
  const void* other_address() const { return &other_value; }
  const void* secret_address() const { return &secret_; }
  const void* hidden_address() const { return &hidden_; }
  static std::size_t slot_size() { return sizeof(Slot); }
  std::size_t slot_count() const { return slots_.size(); }
  void add_slot(int s) { slots_.push_back(Slot{s, 0}); }

 protected:
  long hidden_ = 0;

 private:
  struct Slot {  // a private nested type, also as a container element
    int s;
    double weight;
  };
  char secret_ = 's';
  std::vector<Slot> slots_;
};

union Raw {
  std::uint32_t word;
  float value;
  std::uint8_t bytes[6];
};

struct Node {
  int value;
  Node* next;
};

struct Limits {
  float throttle SYMCR_RANGE(0, 1);
  double altitude SYMCR_RANGE(-100.5, 1e4);
  int yaw SYMCR_RENAMED_FROM("heading") SYMCR_RENAMED_FROM("bearing");
};

struct Everything {
  bool b;
  char c;
  signed char sc;
  unsigned char uc;
  short s;
  unsigned short us;
  int i;
  unsigned u;
  long l;
  unsigned long ul;
  long long ll;
  unsigned long long ull;
  wchar_t wc;
  char16_t c16;
  char32_t c32;
  float f;
  double d;
  long double ld;
  Mode mode;
  Legacy legacy;
  int grid[2][3];
  Int8Param param;
  Bits bits;
  Vehicle vehicle;
  Raw raw;
  struct {
    int inner_a;
    short inner_b;
  } unnamed;
  union {
    int anon_i;
    float anon_f;
  };
  Node* head;
  std::string name;
  std::vector<Waypoint> route;
  std::array<short, 4> trims;
  std::deque<int> recent;
  std::list<double> samples;
  std::map<std::string, Waypoint> named;
  std::unordered_map<int, std::string> labels;
  std::set<int> visited;
  std::optional<double> home_alt;
  std::pair<int, double> range;
  std::tuple<int, double, char> triple;
  std::unique_ptr<Waypoint> rally;
  std::shared_ptr<Node> shared;
  std::variant<int, std::string, Waypoint> status;
  Limits limits;
};

}  // namespace fleet

#endif  // SYMCR_TESTS_GENERATOR_TABLES_TYPES_HPP
