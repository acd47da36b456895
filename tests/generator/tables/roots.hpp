#ifndef SYMCR_TESTS_GENERATOR_TABLES_ROOTS_HPP
#define SYMCR_TESTS_GENERATOR_TABLES_ROOTS_HPP

#include "types.hpp"

extern fleet::Everything everything;
namespace fleet {
extern int fleet_counter;
}
class Registry {
 public:
  static const void* count_address() { return &count; }

 private:
  SYMCR_CHECKPOINT static int count;
};
const void* hidden_root_address();
int* local_static_address();

#endif  // SYMCR_TESTS_GENERATOR_TABLES_ROOTS_HPP
