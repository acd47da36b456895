// describe_header and its formatting helpers.
#include "header_fields.hpp"

#include <time.h>

#include <cinttypes>
#include <cstdio>

#include "terminal.hpp"

namespace symcr::cli {

std::string utc_iso8601(std::uint64_t timestamp_ns) {
  const time_t seconds = static_cast<time_t>(timestamp_ns / 1000000000u);
  tm utc{};
  if (gmtime_r(&seconds, &utc) == nullptr) return "?";
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%09uZ", utc.tm_year + 1900,
                utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec,
                static_cast<unsigned>(timestamp_ns % 1000000000u));
  return text;
}

std::string hex64(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

std::string hex32(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "%08" PRIx32, value);
  return text;
}

std::vector<HeaderField> describe_header(const detail::RecordHeader& h, const Schema* schema,
                                         const std::string& schema_origin) {
  std::vector<HeaderField> fields;
  auto add_number = [&fields](const char* name, std::uint64_t value) {
    fields.push_back({name, std::to_string(value), JsonScalar::of_uint(value)});
  };
  add_number("format_version", h.format_version);
  add_number("sequence", h.sequence);
  fields.push_back(
      {"time", utc_iso8601(h.timestamp_ns), JsonScalar::of(utc_iso8601(h.timestamp_ns))});
  add_number("timestamp_ns", h.timestamp_ns);
  add_number("header_size", h.header_size);
  add_number("schema_size", h.schema_size);
  add_number("payload_size", h.payload_size);
  add_number("record_size", std::uint64_t{h.header_size} + h.schema_size + h.payload_size);
  fields.push_back({"schema_hash", hex64(h.schema_hash), JsonScalar::of(hex64(h.schema_hash))});
  fields.push_back({"program_id", h.program_id ? hex32(h.program_id) : "none (anonymous)",
                    JsonScalar::of(h.program_id ? hex32(h.program_id) : "")});
  std::string where = schema_origin;
  if (schema) {
    where += ", " + std::to_string(schema->type_count) + " types, " +
             std::to_string(schema->root_count) + " roots";
  }
  fields.push_back({"schema", where, JsonScalar::of(schema_origin)});
  const bool authenticated = (h.flags & symcr::format::kRecordAuthenticated) != 0;
  fields.push_back({"authenticated",
                    authenticated ? "HMAC-SHA-256, key id " + std::to_string(h.key_id) +
                                        " (symcr verify --key-file checks it)"
                                  : "no",
                    // JSON: the key id, or null for a record without a MAC.
                    authenticated ? JsonScalar::of_uint(h.key_id) : JsonScalar::null()});
  // Only records that passed parse_record are described, so the checksum held.
  fields.push_back({"checksum", "ok (crc32c " + hex32(h.checksum) + ")", JsonScalar::of("ok")});
  return fields;
}

void print_fields(const std::vector<HeaderField>& fields) {
  Table table;
  for (const HeaderField& field : fields) {
    if (field.name == "timestamp_ns") continue;  // the text shows `time`
    table.add({{field.name}, {field.text}});
  }
  print(table.render(Terminal::for_stdout()));
}

void write_fields_json(JsonWriter& json, const std::vector<HeaderField>& fields) {
  json.object_begin();
  for (const HeaderField& field : fields) json.field(field.name, field.json);
  json.object_end();
}

}  // namespace symcr::cli
