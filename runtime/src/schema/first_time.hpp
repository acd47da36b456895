// A flag that says yes once per process: which restore is the first of its kind, the one that
// takes the path with the least code to bring into cold caches.
#ifndef SYMCR_SRC_FIRST_TIME_HPP
#define SYMCR_SRC_FIRST_TIME_HPP

#include <atomic>

namespace symcr::detail {

class FirstTime {
 public:
  // True for the first caller only. Read before it is written: every later call costs a load,
  // not an atomic exchange.
  bool claim() { return !taken_.load(std::memory_order_relaxed) && !taken_.exchange(true); }

 private:
  std::atomic<bool> taken_{false};
};

}  // namespace symcr::detail

#endif
