// Schema files (schema_file.hpp): the record header is laid out here rather than through
// encode_record, which always appends a payload of the live roots.
#include "schema_file.hpp"

#include <vector>

#include "crc32c.hpp"
#include "file_io.hpp"
#include "parsed_schema.hpp"
#include "record.hpp"
#include "schema_blob.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {

Status write_schema_file(const Schema& schema, const char* path) {
  const SchemaBlob& blob = schema_blob(schema);
  if (blob.size > UINT32_MAX) {
    return Status(Error::TooLarge, "schema of %zu bytes exceeds the format's 4 GiB limit",
                  blob.size);
  }
  std::vector<std::uint8_t> record(format::kRecordHeaderSize + blob.size);
  format::RecordHeader header;
  header.format_version = format::kRecordFormatVersion;
  header.header_size = format::kRecordHeaderSize;
  header.flags = format::kRecordSchemaInline;
  header.timestamp_ns = record_timestamp_ns();
  header.schema_hash = blob.hash;
  header.schema_size = static_cast<std::uint32_t>(blob.size);
  header.payload_size = 0;  // a schema file carries no values
  header.program_id = blob.program_id;
  format::encode_record_header(header, record.data());  // its checksum 0 while computed
  for (std::size_t i = 0; i < blob.size; ++i) record[format::kRecordHeaderSize + i] = blob.data[i];
  format::store32(record.data() + format::kRecordChecksumOffset,
                  crc32c(record.data(), record.size()));
  return write_file_atomically(path, record.data(), record.size(), Durability::PageCache);
}

Status parse_schema_file(const std::uint8_t* data, std::size_t size, ParsedSchema& out,
                         std::uint32_t* program_id) {
  RecordView record;
  Status status = parse_record(data, size, record);
  if (!status.ok()) return status;
  if (program_id) *program_id = record.header.program_id;
  if (record.record_size != size) {
    return Status(Error::Corrupt, "%zu unexpected bytes after the %zu-byte record",
                  size - record.record_size, record.record_size);
  }
  if (record.schema == nullptr) {
    return Status(Error::SchemaUnknown, "the record carries no schema of its own");
  }
  if (record.payload_size != 0) {
    return Status(Error::Corrupt,
                  "a checkpoint, not a schema file (it carries %zu bytes of values)",
                  record.payload_size);
  }
  return parse_schema(record.schema, record.header.schema_size, out);
}

Status read_schema_file(const char* path, ParsedSchema& out, std::uint32_t* program_id) {
  std::vector<std::uint8_t> bytes;
  std::uint64_t trailing = 0;
  Status status = read_record_file(path, bytes, trailing);
  if (!status.ok()) return status;
  status = parse_schema_file(bytes.data(), bytes.size(), out, program_id);
  if (!status.ok()) return Status(status.error(), "%s: %s", path, status.message());
  return Status();
}

}  // namespace symcr::detail
