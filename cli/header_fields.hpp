// A record header (docs/format.md §1) as named fields, shared by inspect and verify so their
// text and JSON say the same thing.
#ifndef SYMCR_CLI_HEADER_FIELDS_HPP
#define SYMCR_CLI_HEADER_FIELDS_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "json_writer.hpp"
#include "record.hpp"
#include "symcr/generated.hpp"

namespace symcr::cli {

struct HeaderField {
  std::string name;  // JSON key; also the text label
  std::string text;
  JsonScalar json;
};

// `schema` is the record's writer schema, or null when unknown. `schema_origin` says where it
// lives ("inline", "store area 1").
std::vector<HeaderField> describe_header(const detail::RecordHeader& header, const Schema* schema,
                                         const std::string& schema_origin);

// "2026-11-23T03:45:12.123456789Z"
std::string utc_iso8601(std::uint64_t timestamp_ns);
std::string hex64(std::uint64_t value);  // 16 hex digits
std::string hex32(std::uint32_t value);  // 8 hex digits

void print_fields(const std::vector<HeaderField>& fields);
void write_fields_json(JsonWriter& json, const std::vector<HeaderField>& fields);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_HEADER_FIELDS_HPP
