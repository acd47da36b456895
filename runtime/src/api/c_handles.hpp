// Internal: what the C API's opaque handles hold and where its last error is kept, shared by the
// C API and the program points (which hand a restore's report to the program's hook as a
// symcr_report).
#ifndef SYMCR_SRC_C_HANDLES_HPP
#define SYMCR_SRC_C_HANDLES_HPP

#include <cstdint>
#include <memory>
#include <string>

#include "symcr/symcr.h"
#include "symcr/symcr.hpp"

struct symcr_report {
  symcr::Report report;
  std::string text;  // renderings kept alive for the caller
  std::string json;
  std::string losses;
};

namespace symcr {
namespace detail {
// The program's C freshness counter seen as a symcr::FreshnessCounter.
class CFreshnessCounter final : public FreshnessCounter {
 public:
  explicit CFreshnessCounter(const symcr_freshness_counter& counter) : counter_(counter) {}
  Status read(std::uint64_t& value) override;
  Status advance(std::uint64_t value) override;

 private:
  symcr_freshness_counter counter_;
};
}  // namespace detail
}  // namespace symcr

struct symcr_store {
  // Declared before the store, which uses it until the store is destroyed.
  std::unique_ptr<symcr::detail::CFreshnessCounter> counter;
  symcr::Store store;
};

namespace symcr {
namespace detail {
// Keeps a failure's message for symcr_last_error(); returns the C error code.
int record_c_error(const Status& status);
}  // namespace detail
}  // namespace symcr

#endif  // SYMCR_SRC_C_HANDLES_HPP
