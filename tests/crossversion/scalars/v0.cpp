// v0: scalar fields of their original widths and kinds.
#include <cstdint>

#include "check.hpp"

struct Sensors {
  std::int16_t widened;
  std::int64_t narrowed_fits;
  std::int64_t narrowed_overflows;
  int to_double;
  float float_to_double;
  double double_to_int;
  std::uint8_t unsigned_to_signed;
  bool flag;
  long double precise;
};

SYMCR_CHECKPOINT Sensors sensors;

int main(int argc, char** argv) {
  sensors = {-1234, 1000, 300, 77, 1.25f, 41.0, 200, true, 2.5L};
  return xv::save(argc, argv);
}
