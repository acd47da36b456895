// An array type of 2^32 elements: more than the compact tables' 32-bit count holds.
#include <cstdint>
#include <symcr/symcr.hpp>

struct Log {
  std::uint8_t (*bytes)[0x100000000ull];  // its pointee's type is in the tables
};
SYMCR_CHECKPOINT Log log_state;
