// A store file in a private directory, opened with build A's schema and `options`, for the
// store's tests (store_test.cpp, crash_loop_test.cpp).
#ifndef SYMCR_TESTS_RUNTIME_STORE_FIXTURE_HPP
#define SYMCR_TESTS_RUNTIME_STORE_FIXTURE_HPP

#include <gtest/gtest.h>

#include <string>

#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {

class StoreFixture : public ::testing::Test {
 protected:
  TempDir dir;
  std::string path = dir.file("copter.store");
  symcr::StoreOptions options;

  void open(symcr::Store& store, const symcr::Schema& schema = schema_a) {
    const symcr::Status status = symcr::Store::open(path.c_str(), schema, options, store);
    ASSERT_TRUE(status.ok()) << status.message();
  }
  // Opens, saves seeds first..last (sequences first..last on a new store), closes.
  void save_seeds(int first, int last) {
    symcr::Store store;
    open(store);
    for (int seed = first; seed <= last; ++seed) {
      fill_a(seed);
      const symcr::Status status = store.save();
      ASSERT_TRUE(status.ok()) << status.message();
    }
  }
};

}  // namespace file_tests

#endif  // SYMCR_TESTS_RUNTIME_STORE_FIXTURE_HPP
