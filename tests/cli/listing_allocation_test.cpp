// The CLI's value listings (inspect, inspect --json, diff, verify) allocate no more than the
// input justifies: a small checkpoint whose schema has a 60 KB field name over 20,000 one-byte
// leaves once made them hold every leaf's full path (1.2 GB) and abort. Each command runs in a
// child process under a 1 GiB address-space limit and must finish normally.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "schema_tables.hpp"
#include "symcr/ops.hpp"
#include "symcr/symcr.hpp"

namespace {

using namespace schema_tables;

constexpr std::size_t kLeafCount = 20000;
std::uint8_t leaves[kLeafCount];
const std::string long_name(60000, 'n');

struct Outcome {
  int exit_code = -1;  // -1: killed by a signal
  std::string error_output;
};

// Sanitizers reserve terabytes of address space: the limit only applies without them (the
// commands' outcomes are checked either way).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kCanLimitAddressSpace = false;
#else
constexpr bool kCanLimitAddressSpace = true;
#endif

// Runs the CLI with `args` under the address-space limit, its standard output discarded.
Outcome run_cli_limited(const std::vector<std::string>& args, const std::string& scratch) {
  const std::string errors = scratch + ".stderr";
  const pid_t child = ::fork();
  if (child == 0) {
    if (kCanLimitAddressSpace) {
      const rlimit limit{rlim_t{1} << 30, rlim_t{1} << 30};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    const int null = ::open("/dev/null", O_WRONLY);
    const int error = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (null < 0 || error < 0 || ::dup2(null, 1) < 0 || ::dup2(error, 2) < 0) ::_exit(125);
    std::vector<char*> argv;
    static std::string program = SYMCR_CLI_PATH;
    argv.push_back(program.data());
    std::vector<std::string> copies = args;
    for (std::string& arg : copies) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(126);
  }
  Outcome outcome;
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) != child) return outcome;
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  std::ifstream in(errors);
  std::stringstream text;
  text << in.rdbuf();
  outcome.error_output = text.str();
  return outcome;
}

std::string scratch_path(const char* name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/symcr_listing_" + name + "_" +
         std::to_string(::getpid());
}

TEST(CliListingAllocation, LongNamesOverManyLeavesAreListedWithinTheLimit) {
  static const FieldInfo holder_fields[] = {field(long_name.c_str(), 1, 0)};
  static const TypeInfo types[] = {
      scalar("uint8", Kind::UInt, 1),
      array("uint8[20000]", 0, kLeafCount, kLeafCount, 1),
      record("Holder", kLeafCount, 1, holder_fields, 1),
  };
  static const symcr::RootInfo roots[] = {{"r", 2, leaves, 0, nullptr}};
  static const symcr::Schema schema{types, 3, roots, 1, nullptr};
  for (std::size_t i = 0; i < kLeafCount; ++i) leaves[i] = static_cast<std::uint8_t>(i % 251);

  const std::string file = scratch_path("long_names") + ".ckpt";
  ASSERT_TRUE(symcr::checkpoint(schema, file.c_str()).ok());
  std::ifstream written(file, std::ios::binary | std::ios::ate);
  ASSERT_LT(static_cast<std::size_t>(written.tellg()), 100000u);  // a small file

  const std::vector<std::vector<std::string>> commands = {
      {"inspect", file}, {"inspect", "--json", file}, {"diff", file, file}, {"verify", file}};
  for (const auto& command : commands) {
    const Outcome outcome = run_cli_limited(command, file);
    EXPECT_EQ(outcome.exit_code, 0) << command[0] << (command.size() > 2 ? " " + command[1] : "")
                                    << ": " << outcome.error_output;
  }
  std::remove(file.c_str());
  std::remove((file + ".stderr").c_str());
}

// Leaves each under its own chain of 40 nested structs take more nodes than 128 bytes per
// payload byte: the listing is refused (TooLarge, exit 2) before it grows, nothing printed.
struct Link {
  std::uint8_t f;
};
constexpr std::uint32_t kChainDepth = 40;
constexpr std::size_t kChainCount = 100000;
std::uint8_t chains[kChainCount];

TEST(CliListingAllocation, AListingBeyondItsBoundIsRefusedCleanly) {
  static const std::vector<FieldInfo> link_fields = [] {
    std::vector<FieldInfo> fields;
    for (std::uint32_t t = 0; t < kChainDepth; ++t) fields.push_back(field("f", t, 0));
    return fields;
  }();
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (std::uint32_t t = 0; t <= kChainDepth; ++t) out.push_back("Link" + std::to_string(t));
    return out;
  }();
  static const std::vector<TypeInfo> types = [] {
    std::vector<TypeInfo> out{scalar("uint8", Kind::UInt, 1)};
    for (std::uint32_t t = 1; t <= kChainDepth; ++t) {
      out.push_back(record(names[t].c_str(), sizeof(Link), 1, &link_fields[t - 1], 1));
    }
    out.push_back(array("Link40[100000]", kChainDepth, kChainCount, kChainCount, 1));
    return out;
  }();
  static const symcr::RootInfo roots[] = {{"chains", kChainDepth + 1, chains, 0, nullptr}};
  static const symcr::Schema schema{types.data(), static_cast<std::uint32_t>(types.size()),
                                    roots, 1, nullptr};

  const std::string file = scratch_path("chains") + ".ckpt";
  ASSERT_TRUE(symcr::checkpoint(schema, file.c_str()).ok());
  for (const auto& command : std::vector<std::vector<std::string>>{
           {"inspect", file}, {"inspect", "--json", file}, {"diff", file, file}}) {
    const Outcome outcome = run_cli_limited(command, file);
    EXPECT_EQ(outcome.exit_code, 2) << command[0] << ": " << outcome.error_output;
    EXPECT_NE(outcome.error_output.find("listing the values would take more than 64 MiB"),
              std::string::npos)
        << outcome.error_output;
  }
  // verify keeps no listing: it decodes and counts every leaf.
  const Outcome verified = run_cli_limited({"verify", file}, file);
  EXPECT_EQ(verified.exit_code, 0) << verified.error_output;
  std::remove(file.c_str());
  std::remove((file + ".stderr").c_str());
}

// The decoder keeps each container's path (a reference may name its elements): a 60 KB field
// name over 100,000 small containers once made that 6 GB. Past the bound the commands refuse
// (TooLarge), never abort.
std::vector<std::vector<std::uint8_t>> many_containers(100000);

TEST(CliListingAllocation, LongNamesOverManyContainersAreBoundedToo) {
  static const FieldInfo holder_fields[] = {field(long_name.c_str(), 2, 0)};
  static const TypeInfo types[] = {
      scalar("uint8", Kind::UInt, 1),
      holder("std::vector<uint8>", Kind::Container, sizeof(std::vector<std::uint8_t>),
             alignof(std::vector<std::uint8_t>), 0,
             &symcr::ops::container<std::vector<std::uint8_t>>::table),
      holder("std::vector<std::vector<uint8>>", Kind::Container, sizeof(many_containers),
             alignof(decltype(many_containers)), 1,
             &symcr::ops::container<std::vector<std::vector<std::uint8_t>>>::table),
      record("Holder", sizeof(many_containers), alignof(decltype(many_containers)),
             holder_fields, 1),
  };
  static const symcr::RootInfo roots[] = {{"r", 3, &many_containers, 0, nullptr}};
  static const symcr::Schema schema{types, 4, roots, 1, nullptr};

  const std::string file = scratch_path("containers") + ".ckpt";
  ASSERT_TRUE(symcr::checkpoint(schema, file.c_str()).ok());
  for (const auto& command : std::vector<std::vector<std::string>>{
           {"inspect", file}, {"inspect", "--json", file}, {"diff", file, file}, {"verify", file}}) {
    const Outcome outcome = run_cli_limited(command, file);
    EXPECT_GE(outcome.exit_code, 0) << command[0] << " was killed: " << outcome.error_output;
    if (command[0] != "verify") {
      EXPECT_EQ(outcome.exit_code, 2) << command[0] << ": " << outcome.error_output;
      EXPECT_NE(outcome.error_output.find("paths would take more than"), std::string::npos)
          << outcome.error_output;
    }
  }
  std::remove(file.c_str());
  std::remove((file + ".stderr").c_str());
}

}  // namespace
