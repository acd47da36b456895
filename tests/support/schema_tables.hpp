// Shorthands for hand-written schema tables in the form symcr-gen emits (TypeInfo / FieldInfo
// aggregates, written out in full by the generator). Shared by the runtime, reliability and
// fuzzing tests and the benchmarks, which describe their state by hand to test the engine
// without the generator. Append-only like the structs: a new TypeInfo member goes last here too.
#ifndef SYMCR_TESTS_SUPPORT_SCHEMA_TABLES_HPP
#define SYMCR_TESTS_SUPPORT_SCHEMA_TABLES_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/generated.hpp"

namespace schema_tables {

using symcr::FieldInfo;
using symcr::Kind;
using symcr::TypeInfo;
using symcr::kNoType;

constexpr TypeInfo scalar(const char* name, Kind kind, std::uint32_t size) {
  return {name, kind, 0, size, size, nullptr, 0, nullptr, 0, kNoType, 0,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}
constexpr TypeInfo record(const char* name, std::uint32_t size, std::uint32_t align,
                          const FieldInfo* fields, std::uint32_t count,
                          const symcr::Lifecycle* lifecycle = nullptr,
                          bool (*validate)(const void*) = nullptr,
                          const char* const* renamed_from = nullptr,
                          void (*migrate)(void*, const symcr::OldValues&) = nullptr) {
  return {name, Kind::Struct, 0, size, align, fields, count, nullptr, 0, kNoType, 0,
          nullptr, 0, 0, nullptr, lifecycle, validate, renamed_from, migrate, nullptr, nullptr, 0};
}
constexpr TypeInfo union_of(const char* name, std::uint32_t size, std::uint32_t align) {
  return {name, Kind::Union, 0, size, align, nullptr, 0, nullptr, 0, kNoType, 0,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}
constexpr TypeInfo enumeration(const char* name, std::uint32_t size, std::uint32_t underlying,
                               const symcr::EnumeratorInfo* enumerators, std::uint32_t count) {
  return {name, Kind::Enum, symcr::kTypeScopedEnum, size, size, nullptr, 0, enumerators, count,
          underlying, 0, nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}
constexpr TypeInfo array(const char* name, std::uint32_t element, std::uint64_t count,
                         std::uint32_t size, std::uint32_t align) {
  return {name, Kind::Array, 0, size, align, nullptr, 0, nullptr, 0, element, count,
          nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}
// Container, Optional, UniquePtr, SharedPtr, Pointer and String types: an element and ops.
constexpr TypeInfo holder(const char* name, Kind kind, std::uint32_t size, std::uint32_t align,
                          std::uint32_t element, const void* ops,
                          symcr::ContainerKind container = symcr::ContainerKind::Vector,
                          const symcr::Lifecycle* lifecycle = nullptr) {
  return {name, kind, 0, size, align, nullptr, 0, nullptr, 0, element, 0, nullptr, 0,
          kind == Kind::Container ? static_cast<std::uint8_t>(container) : std::uint8_t{0},
          ops, lifecycle, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}
constexpr TypeInfo variant_of(const char* name, std::uint32_t size, std::uint32_t align,
                              const std::uint32_t* alternatives, std::uint32_t count,
                              const void* ops) {
  return {name, Kind::Variant, 0, size, align, nullptr, 0, nullptr, 0, kNoType, 0,
          alternatives, count, 0, ops, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, 0};
}

constexpr FieldInfo field(const char* name, std::uint32_t type, std::size_t offset,
                          const char* const* renamed_from = nullptr) {
  return {name, type, static_cast<std::uint32_t>(offset), 0, 0, 0, renamed_from, nullptr, nullptr};
}
// A bit-field of `width` bits from `bit_offset` of the storage unit at offset 0.
constexpr FieldInfo bit_field(const char* name, std::uint32_t type, std::uint16_t bit_offset,
                              std::uint16_t width) {
  return {name, type, 0, bit_offset, width, 0, nullptr, nullptr, nullptr};
}
constexpr FieldInfo base(const char* name, std::uint32_t type, std::size_t offset) {
  return {name, type, static_cast<std::uint32_t>(offset), 0, 0, symcr::kFieldBase, nullptr,
          nullptr, nullptr};
}
// `range` must outlive the tables: a namespace-scope or static constant.
constexpr FieldInfo ranged(const char* name, std::uint32_t type, std::size_t offset,
                           const symcr::FieldRange& range) {
  return {name, type, static_cast<std::uint32_t>(offset), 0, 0, symcr::kFieldHasRange, nullptr,
          &range, nullptr};
}
// A time of `time.clock` (kFieldClockTime); `time` must outlive the tables.
constexpr FieldInfo timed(const char* name, std::uint32_t type, std::size_t offset,
                          const symcr::FieldTime& time) {
  return {name, type, static_cast<std::uint32_t>(offset), 0, 0, symcr::kFieldClockTime, nullptr,
          nullptr, &time};
}

}  // namespace schema_tables

#endif  // SYMCR_TESTS_SUPPORT_SCHEMA_TABLES_HPP
