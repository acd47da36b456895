// Everything that cannot be restored meaningfully, each reached from one root.
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include <symcr/symcr.hpp>

struct Shape {
  virtual ~Shape() = default;
  int sides;
};
struct Base {
  int b;
};
struct Diamond : virtual Base {
  int d;
};
union Raw {
  int* pointer;
  long bits;
};
struct State {
  std::mutex lock;
  std::thread worker;
  std::atomic<int> counter;
  int& alias;
  void (*callback)(int);
  std::unique_ptr<Shape> shape;  // owning: its dynamic type would have to be rebuilt
  Diamond diamond;
  Raw raw;
  void* opaque;
};
extern int target;
SYMCR_CHECKPOINT State state{{}, {}, {}, target, nullptr, nullptr, {}, {}, nullptr};
