// Schema files: a build's schema on disk, so that tools (`symcr plan`) can resolve a checkpoint
// against a build without running it. A schema file is a record (docs/format.md §1) with the
// schema inline and an empty payload; the build writes it next to the program.
#ifndef SYMCR_SRC_SCHEMA_FILE_HPP
#define SYMCR_SRC_SCHEMA_FILE_HPP

#include <cstddef>
#include <cstdint>

#include "parsed_schema.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// Writes `schema` to `path` atomically (as checkpoint() does: temp file, rename, mode 0600).
Status write_schema_file(const Schema& schema, const char* path);

// Parses a schema file's bytes: a valid record whose schema is inline and whose payload is
// empty (a checkpoint is refused with a message saying so). `program_id`, when given, receives
// the build's program identity from the record header.
Status parse_schema_file(const std::uint8_t* data, std::size_t size, ParsedSchema& out,
                         std::uint32_t* program_id = nullptr);

// Reads and parses the schema file at `path`.
Status read_schema_file(const char* path, ParsedSchema& out, std::uint32_t* program_id = nullptr);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCHEMA_FILE_HPP
