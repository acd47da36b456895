// A writer schema parsed from checkpoint bytes (docs/format.md §2). Internal to the runtime;
// the CLI, generator and tests may include it too.
#ifndef SYMCR_SRC_PARSED_SCHEMA_HPP
#define SYMCR_SRC_PARSED_SCHEMA_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// Owns its strings and tables and exposes them as a symcr::Schema (roots have null addresses).
// Validated on parse.
class ParsedSchema {
 public:
  ParsedSchema();
  ~ParsedSchema();
  ParsedSchema(ParsedSchema&&) noexcept;
  ParsedSchema& operator=(ParsedSchema&&) noexcept;
  const Schema& schema() const;
  std::uint64_t hash() const;
  const std::vector<std::uint8_t>& bytes() const;  // the serialised form it was parsed from

  struct Storage;
  std::unique_ptr<Storage> storage;
};
// `hash`, when given, is the bytes' FNV-1a 64 hash, which the caller already computed.
Status parse_schema(const std::uint8_t* data, std::size_t size, ParsedSchema& out,
                    const std::uint64_t* hash = nullptr);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PARSED_SCHEMA_HPP
