// A hostile count must never make restore allocate more than the input justifies.
//
// Regression test for a bug the fuzzing work found: a container whose writer element encodes to
// nothing (an empty struct) may have up to 2^20 elements (docs/format.md §3), and restore used
// to reserve count x the *reader's* element size before appending. A reader element that grew
// to 64 KiB turned a 4-byte count into a 64 GiB reservation and, with -fno-exceptions, a crash.
// Restore now refuses such a checkpoint cleanly in its check pass (state untouched).
//
// The restore runs in a child process so that the crash fails this test only.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "reliability_schemas.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

struct Big {
  std::uint8_t data[65536];
};
struct Empty {};
std::vector<Big> bigs;
std::vector<Empty> empties;

const symcr::Schema& reader_schema() {
  static const FieldInfo big_fields[] = {field("data", 1, 0)};
  static const TypeInfo types[] = {
      scalar("uint8", Kind::UInt, 1),
      array("uint8[65536]", 0, 65536, 65536, 1),
      record("Big", sizeof(Big), alignof(Big), big_fields, 1, &symcr::ops::lifecycle<Big>::table),
      holder("std::vector<Big>", Kind::Container, sizeof(bigs), alignof(std::vector<Big>), 2,
             &symcr::ops::container<std::vector<Big>>::table),
  };
  static const symcr::RootInfo roots[] = {{"bigs", 3, &bigs, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};
  return schema;
}

// The old build: the element type had no fields yet.
const symcr::Schema& writer_schema() {
  static const TypeInfo types[] = {
      record("Big", sizeof(Empty), alignof(Empty), nullptr, 0, &symcr::ops::lifecycle<Empty>::table),
      holder("std::vector<Big>", Kind::Container, sizeof(empties), alignof(std::vector<Empty>), 0,
             &symcr::ops::container<std::vector<Empty>>::table),
  };
  static const symcr::RootInfo roots[] = {{"bigs", 1, &empties, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  return schema;
}

TEST(HostileAllocation, EmptyElementsIntoALargeReaderElementAreRefusedNotAllocated) {
  empties.resize(std::size_t{1} << 20);
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(writer_schema(), buffer).ok());
  empties.clear();
  empties.shrink_to_fit();
  ASSERT_LT(buffer.size(), 512u);  // a tiny checkpoint

  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // On a thread of its own, so that a throw from restore terminates the child rather than
    // being caught by the test framework.
    bool refused = false;
    std::thread([&] {
      const symcr::Report report =
          symcr::restore_from_buffer(reader_schema(), buffer.data(), buffer.size());
      refused = !report.ok();
    }).join();
    // Refused cleanly, nothing allocated for the elements.
    ::_exit(refused && bigs.capacity() == 0 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status)) << "restore crashed (signal " << WTERMSIG(status)
                                 << ") on a " << buffer.size() << "-byte checkpoint";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "restore accepted 2^20 elements of 64 KiB from a 4-byte count";
}

}  // namespace
}  // namespace reliability
