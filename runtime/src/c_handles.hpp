// Internal: what the C API's opaque handles hold and where its last error is kept, shared by the
// C API and the program points (which hand a restore's report to the program's hook as a
// symcr_report).
#ifndef SYMCR_SRC_C_HANDLES_HPP
#define SYMCR_SRC_C_HANDLES_HPP

#include <string>

#include "symcr/symcr.h"
#include "symcr/symcr.hpp"

struct symcr_report {
  symcr::Report report;
  std::string text;  // renderings kept alive for the caller
  std::string json;
  std::string losses;
};

struct symcr_store {
  symcr::Store store;
};

namespace symcr {
namespace detail {
// Keeps a failure's message for symcr_last_error(); returns the C error code.
int record_c_error(const Status& status);
}  // namespace detail
}  // namespace symcr

#endif  // SYMCR_SRC_C_HANDLES_HPP
