// Schema files (runtime/src/api/schema_file.hpp): written from a live schema, read back without it.
#include "schema_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <string>

#include "fixture_tables.hpp"
#include "parsed_schema.hpp"
#include "schema_blob.hpp"
#include "symcr/symcr.hpp"

namespace {

std::string scratch(const char* name) {
  return std::string(::testing::TempDir()) + "symcr_cli_unit_" + std::to_string(::getpid()) +
         "_" + name;
}

TEST(SchemaFile, RoundTripsTheBuildsSchema) {
  const std::string path = scratch("build.schema");
  ASSERT_TRUE(symcr::detail::write_schema_file(cli_fixture::schema(), path.c_str()).ok());
  symcr::detail::ParsedSchema parsed;
  const symcr::Status status = symcr::detail::read_schema_file(path.c_str(), parsed);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(parsed.hash(), symcr::detail::schema_blob(cli_fixture::schema()).hash);
  ASSERT_EQ(parsed.schema().root_count, 2u);
  EXPECT_STREQ(parsed.schema().roots[0].name, "copter");
  EXPECT_EQ(parsed.schema().roots[0].address, nullptr);
  ::unlink(path.c_str());
}

TEST(SchemaFile, RefusesACheckpoint) {
  const std::string path = scratch("values.ckpt");
  cli_fixture::fill_state(1);
  ASSERT_TRUE(symcr::checkpoint(cli_fixture::schema(), path.c_str()).ok());
  symcr::detail::ParsedSchema parsed;
  const symcr::Status status = symcr::detail::read_schema_file(path.c_str(), parsed);
  EXPECT_EQ(status.error(), symcr::Error::Corrupt);
  EXPECT_NE(std::strstr(status.message(), "a checkpoint, not a schema file"), nullptr)
      << status.message();
  ::unlink(path.c_str());
}

TEST(SchemaFile, ReportsAMissingFile) {
  symcr::detail::ParsedSchema parsed;
  EXPECT_EQ(symcr::detail::read_schema_file("/nonexistent/x.schema", parsed).error(),
            symcr::Error::Io);
}

}  // namespace
