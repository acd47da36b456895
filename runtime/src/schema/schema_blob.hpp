// A running build's schema in its serialised form (docs/format.md §2), its hash and its
// program's identity. Internal to the runtime; the CLI, generator and tests may include it too.
#ifndef SYMCR_SRC_SCHEMA_BLOB_HPP
#define SYMCR_SRC_SCHEMA_BLOB_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "symcr/generated.hpp"

namespace symcr::detail {

// The serialised form of a running build's schema and its FNV-1a 64 hash: symcr-gen's
// (Schema::serialised), or serialised once per Schema object and cached.
// Thread-compatible (compute before sharing).
struct SchemaBlob {
  SchemaBlob() = default;
  SchemaBlob(const SchemaBlob&) = delete;  // `data` may point into `storage`
  SchemaBlob& operator=(const SchemaBlob&) = delete;
  const std::uint8_t* data = nullptr;  // the generated constant, or storage's bytes
  std::size_t size = 0;
  std::uint64_t hash = 0;
  std::uint32_t program_id = 0;  // format::program_id(schema.program)
  std::vector<std::uint8_t> storage;
};
// Serialises `schema` into `blob` (its storage) and hashes it (schema_blob.cpp).
void serialise_blob(const Schema& schema, SchemaBlob& blob);

// `schema`'s blob, serialised at its first use and cached (schema_cache.cpp).
const SchemaBlob& schema_blob(const Schema& schema);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCHEMA_BLOB_HPP
