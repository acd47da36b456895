// A hostile count must never make restore allocate more than the input justifies.
//
// Regression test for a bug the fuzzing work found: a container whose writer element encodes to
// nothing (an empty struct) may have up to 2^20 elements (docs/format.md §3), and restore used
// to reserve count x the *reader's* element size before appending. A reader element that grew
// to 64 KiB turned a 4-byte count into a 64 GiB reservation and, with -fno-exceptions, a crash.
// Restore now refuses such a checkpoint cleanly in its check pass (state untouched).
//
// The restore runs in a child process so that the crash fails this test only.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
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


// A child process's verdict: exited 0 (the checks it ran held), not killed.
void expect_child_passed(pid_t child) {
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died of signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Sanitizers reserve terabytes of address space: an address-space limit only works without.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kCanLimitAddressSpace = false;
#else
constexpr bool kCanLimitAddressSpace = true;
#endif

// Runs `check` in a child limited to a minute of CPU (reading a terabyte of hole takes many
// minutes) and expects it to hold.
template <typename Check>
void expect_within_a_cpu_minute(Check check) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const rlimit one_minute{60, 60};
    if (::setrlimit(RLIMIT_CPU, &one_minute) != 0) ::_exit(3);
    ::_exit(check() ? 0 : 1);
  }
  expect_child_passed(child);
}

std::string scratch_path(const char* name) {
  return std::string(::testing::TempDir()) + "symcr_hostile_" + std::to_string(::getpid()) + "_" +
         name;
}

TEST(HostileAllocation, SparseMultiGigabyteCheckpointFileIsRefusedWithoutReadingIt) {
  chain = Chain{7, {}};
  const std::string path = scratch_path("sparse.ckpt");
  ASSERT_TRUE(symcr::checkpoint(chain_schema(), path.c_str()).ok());
  // A valid checkpoint followed by 3 GiB of hole: a few KB on disk.
  ASSERT_EQ(::truncate(path.c_str(), std::int64_t{3} << 30), 0) << std::strerror(errno);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (kCanLimitAddressSpace) {
      const rlimit one_gigabyte{std::uint64_t{1} << 30, std::uint64_t{1} << 30};
      if (::setrlimit(RLIMIT_AS, &one_gigabyte) != 0) ::_exit(3);
    }
    chain.value = 55;
    bool refused = false;
    std::thread([&] {
      const symcr::Report report = symcr::restore(chain_schema(), path.c_str());
      refused = report.status().error() == symcr::Error::Corrupt &&
                std::strstr(report.status().message(), "unexpected bytes after the") != nullptr;
    }).join();
    ::_exit(refused && chain.value == 55 ? 0 : 1);
  }
  expect_child_passed(child);
  ::unlink(path.c_str());
  chain = Chain{};
}

TEST(HostileAllocation, DamagedStoreHeaderInATerabyteSparseFileIsSalvagedWithoutScanningIt) {
  const std::string path = scratch_path("sparse.store");
  {
    symcr::Store store;
    symcr::StoreOptions options;
    options.slots = 4;
    options.slot_size = 4096;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), chain_schema(), options, store).ok());
    for (std::int32_t value = 1; value <= 6; ++value) {
      chain.value = value;
      ASSERT_TRUE(store.save().ok());
    }
  }
  const int fd = ::open(path.c_str(), O_WRONLY);
  ASSERT_GE(fd, 0);
  const std::uint8_t zeros[40] = {};
  ASSERT_EQ(::pwrite(fd, zeros, sizeof zeros, 0), static_cast<ssize_t>(sizeof zeros));
  ::close(fd);
  // The file system may not hold a file this large: then there is nothing to scan.
  if (::truncate(path.c_str(), std::int64_t{1} << 40) != 0) {
    ::unlink(path.c_str());
    GTEST_SKIP() << "no sparse 1 TiB file here: " << std::strerror(errno);
  }
  // Finding the six records reads none of the hole.
  expect_within_a_cpu_minute([&path] {
    chain.value = 0;
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open_readonly(path.c_str(), chain_schema(), store);
    const symcr::Report report = opened.ok() ? store.restore_latest() : symcr::Report();
    return opened.ok() && report.ok() && chain.value == 6;
  });
  ::unlink(path.c_str());
  chain = Chain{};
}

TEST(HostileAllocation, ATerabyteOfZerosIsRefusedAsAStoreWithoutScanningIt) {
  const std::string path = scratch_path("zeros.store");
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ASSERT_GE(fd, 0);
  ::close(fd);
  if (::truncate(path.c_str(), std::int64_t{1} << 40) != 0) {
    ::unlink(path.c_str());
    GTEST_SKIP() << "no sparse 1 TiB file here: " << std::strerror(errno);
  }
  // No record in it, so no schema area to look for: looking page by page took minutes.
  expect_within_a_cpu_minute([&path] {
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open_readonly(path.c_str(), chain_schema(), store);
    return !opened.ok() && std::strstr(opened.message(), "bad magic") != nullptr;
  });
  ::unlink(path.c_str());
}

}  // namespace
}  // namespace reliability
