// Valid for g++ with -fsingle-precision-constant (0.01 is a float there, so no narrowing), and
// C++17 (std::optional), which is g++ 12's default when the command names no -std.
#include <optional>

#include <symcr/symcr.hpp>

struct LogRecord {
  float altitude_m;
  std::optional<int> satellites;
};

inline float altitude_cm() { return 12345.0f; }

SYMCR_CHECKPOINT LogRecord last_record{altitude_cm() * 0.01, 7};
