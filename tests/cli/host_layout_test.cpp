// symcr convert's layout of a build known only by its schema file: the schema's declared sizes
// never drive an allocation beyond what the conversion's input justifies.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "host_layout.hpp"
#include "schema_tables.hpp"

namespace {

using namespace schema_tables;

// Eight roots of uint8[2^31 - 1]: 16 GiB declared by a schema of a few hundred bytes.
const symcr::Schema& huge_schema() {
  static const TypeInfo types[] = {scalar("uint8", Kind::UInt, 1),
                                   array("uint8[2147483647]", 0, 2147483647u, 2147483647u, 1)};
  static const symcr::RootInfo roots[] = {
      {"r0", 1, nullptr, 0, nullptr}, {"r1", 1, nullptr, 0, nullptr},
      {"r2", 1, nullptr, 0, nullptr}, {"r3", 1, nullptr, 0, nullptr},
      {"r4", 1, nullptr, 0, nullptr}, {"r5", 1, nullptr, 0, nullptr},
      {"r6", 1, nullptr, 0, nullptr}, {"r7", 1, nullptr, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 8, nullptr};
  return schema;
}

TEST(HostLayout, DeclaredSizesBeyondTheInputAreRefusedBeforeAllocating) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    // Sanitizers reserve terabytes of address space; without them, 1 GiB is plenty here.
    const rlimit one_gigabyte{std::uint64_t{1} << 30, std::uint64_t{1} << 30};
    if (::setrlimit(RLIMIT_AS, &one_gigabyte) != 0) ::_exit(3);
#endif
    symcr::cli::HostLayout layout;
    const symcr::Status status = layout.lay_out(huge_schema(), 234);
    ::_exit(status.error() == symcr::Error::TooLarge &&
                    std::strstr(status.message(), "more than a conversion") != nullptr
                ? 0
                : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died of signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "not refused as TooLarge";
}

TEST(HostLayout, RootsTheInputJustifiesAreLaidOut) {
  static const TypeInfo types[] = {scalar("uint8", Kind::UInt, 1),
                                   array("uint8[100]", 0, 100, 100, 1)};
  static const symcr::RootInfo roots[] = {{"small", 1, nullptr, 0, nullptr}};
  const symcr::Schema schema{types, 2, roots, 1, nullptr};
  symcr::cli::HostLayout layout;
  ASSERT_TRUE(layout.lay_out(schema, 234).ok());
  ASSERT_NE(layout.schema().roots[0].address, nullptr);
  EXPECT_EQ(static_cast<const std::uint8_t*>(layout.schema().roots[0].address)[99], 0);
}

}  // namespace
