// Helpers shared by the payload engine's tests: save with one build's schema, restore with
// another's through a writer schema parsed from bytes (as the file layer does).
#ifndef SYMCR_TESTS_RUNTIME_ENGINE_TEST_UTIL_HPP
#define SYMCR_TESTS_RUNTIME_ENGINE_TEST_UTIL_HPP

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "encode.hpp"
#include "parsed_schema.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "symcr/symcr.hpp"

namespace engine_tests {

struct Saved {
  std::vector<std::uint8_t> schema;
  std::uint64_t hash = 0;
  std::vector<std::uint8_t> payload;
};

inline Saved save(const symcr::Schema& schema) {
  Saved saved;
  const symcr::detail::SchemaBlob& blob = symcr::detail::schema_blob(schema);
  saved.schema.assign(blob.data, blob.data + blob.size);
  saved.hash = blob.hash;
  const symcr::Status status = symcr::detail::encode_payload(schema, saved.payload);
  EXPECT_TRUE(status.ok()) << status.message();
  return saved;
}

inline symcr::Report load(const Saved& saved, const symcr::Schema& reader, bool strict = false,
                          std::size_t payload_size = static_cast<std::size_t>(-1)) {
  symcr::detail::ParsedSchema writer;
  const symcr::Status status =
      symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), writer);
  EXPECT_TRUE(status.ok()) << status.message();
  symcr::RestoreOptions options;
  options.strict = strict;
  const std::size_t size = payload_size == static_cast<std::size_t>(-1) ? saved.payload.size()
                                                                         : payload_size;
  return symcr::detail::restore_payload(writer.schema(), saved.hash, saved.payload.data(), size,
                                        reader, options);
}

inline const symcr::ReportEntry* entry(const symcr::Report& report, const std::string& path) {
  for (const symcr::ReportEntry& candidate : report.entries()) {
    if (candidate.path == path) return &candidate;
  }
  return nullptr;
}

// Asserts that `path` is in the report with `decision` and a detail containing `detail_part`.
inline void expect_entry(const symcr::Report& report, const std::string& path,
                         symcr::Decision decision, const std::string& detail_part = "",
                         int lossy = -1) {
  // A path can have a schema-level entry and value-level ones: prefer the one with `decision`.
  const symcr::ReportEntry* found = entry(report, path);
  for (const symcr::ReportEntry& candidate : report.entries()) {
    if (candidate.path == path && candidate.decision == decision) {
      found = &candidate;
      break;
    }
  }
  ASSERT_NE(found, nullptr) << "no report entry for " << path << "\n" << report.to_text();
  EXPECT_EQ(found->decision, decision)
      << path << ": " << symcr::decision_name(found->decision) << " " << found->detail;
  EXPECT_NE(found->detail.find(detail_part), std::string::npos)
      << path << ": detail '" << found->detail << "' lacks '" << detail_part << "'";
  if (lossy >= 0) {
    EXPECT_EQ(found->lossy, lossy != 0) << path;
  }
}

}  // namespace engine_tests

#endif  // SYMCR_TESTS_RUNTIME_ENGINE_TEST_UTIL_HPP
