// Shorthands for hand-written schema tables in the form symcr-gen emits (see
// tests/runtime/handwritten_schemas.hpp), for the CLI's fixture programs.
#ifndef SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP
#define SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/ops.hpp"
#include "symcr/schema.hpp"

namespace cli_fixture {

using symcr::Kind;
using symcr::kNoType;

constexpr symcr::TypeInfo scalar(const char* name, Kind kind, std::uint32_t size) {
  return {name, kind, 0, size, size, nullptr, 0, nullptr, 0, kNoType, 0,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr};
}
constexpr symcr::TypeInfo record(const char* name, std::uint32_t size, std::uint32_t align,
                                 const symcr::FieldInfo* fields, std::uint32_t count) {
  return {name, Kind::Struct, 0, size, align, fields, count, nullptr, 0, kNoType, 0,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr};
}
constexpr symcr::TypeInfo enumeration(const char* name, std::uint32_t size,
                                      std::uint32_t underlying,
                                      const symcr::EnumeratorInfo* enumerators,
                                      std::uint32_t count) {
  return {name, Kind::Enum, symcr::kTypeScopedEnum, size, size, nullptr, 0, enumerators, count,
          underlying, 0, nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr};
}
constexpr symcr::TypeInfo array(const char* name, std::uint32_t element, std::uint64_t count,
                                std::uint32_t size, std::uint32_t align) {
  return {name, Kind::Array, 0, size, align, nullptr, 0, nullptr, 0, element, count,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr};
}
constexpr symcr::TypeInfo holder(const char* name, Kind kind, std::uint32_t size,
                                 std::uint32_t align, std::uint32_t element, const void* ops,
                                 std::uint8_t container_kind = 0) {
  return {name, kind, 0, size, align, nullptr, 0, nullptr, 0, element, 0, nullptr, 0,
          container_kind, ops, nullptr, nullptr, nullptr, nullptr};
}
inline symcr::FieldInfo field(const char* name, std::uint32_t type, std::size_t offset,
                              const char* const* renamed_from = nullptr) {
  return {name, type, static_cast<std::uint32_t>(offset), 0, 0, 0, renamed_from, 0.0, 0.0};
}

// Each fixture build defines these.
const symcr::Schema& schema();
void fill_state(int seed);  // distinct, checkable contents per seed

}  // namespace cli_fixture

#endif  // SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP
