// What a schema's types take on the wire and how deep their values nest (docs/format.md §3):
// facts of the schema alone, which the schema parser checks and every payload reader bounds
// its reads by. Internal to the runtime.
#ifndef SYMCR_SRC_SCHEMA_SCHEMA_SIZES_HPP
#define SYMCR_SRC_SCHEMA_SCHEMA_SIZES_HPP

#include <cstdint>
#include <vector>

#include "symcr/generated.hpp"

namespace symcr::detail {

// The nesting limit (docs/format.md §3): one budget for every kind of nesting, so that no
// schema or payload can take a recursive encoder or decoder deeper than this many levels. A
// type's values hold at most this many levels by value (the schema parser refuses a deeper
// type), and a value is charged its type's by-value levels plus, for every container element
// and unique_ptr pointee on the way to it, one level and that element type's by-value levels:
// saving refuses, and every reader of a payload refuses, a value charged more.
constexpr int kMaxValueNesting = 2048;
// Elements that encode to no bytes (empty structs) are not bounded by the payload's size: an
// array or container of more of them than this is refused.
constexpr std::uint64_t kMaxEmptyElements = std::uint64_t{1} << 20;

// Per writer type, computed once per schema: the fewest payload bytes a value takes (what
// bounds a count in a hostile payload), and the bytes every value takes when that does not
// depend on the value (scalars, unions, and structs and arrays of those).
struct WireSizes {
  static constexpr std::uint64_t kVariable = ~std::uint64_t{0};
  std::vector<std::uint64_t> least;
  std::vector<std::uint64_t> fixed;   // kVariable when value-dependent
  std::vector<std::uint32_t> levels;  // by_value_levels
  std::uint32_t clock_count = 0;      // schema_clocks(writer).size(): readings that end a payload
};
// For a parsed schema (whose types nest by value within the limit).
WireSizes wire_sizes(const Schema& writer);
// WireSizes::levels of `writer`: by_value_levels, each capped one past the limit (a program's
// own schema is not parsed: a value of a type past it is refused when met).
std::vector<std::uint32_t> value_levels(const Schema& writer);

// The clocks `schema`'s time fields name (kFieldClockTime), by ClockInfo::index: a payload of
// a schema with clocks ends with the writing process's epoch and one reading per clock
// (docs/format.md §3). An index no field names (a hand-written table's gap) is null.
std::vector<const ClockInfo*> schema_clocks(const Schema& schema);

// Per type, the levels of values its values hold by value: 0 for a type that holds none, a
// struct or union one more than its deepest field, an array or optional one more than its
// element, a variant one more than its deepest alternative. (Containers, unique_ptrs and
// pointers hold theirs elsewhere; an enum's or string's element is an integer.) Computed
// without recursion. Fails, naming the type in `culprit`, when a type contains itself by
// value or holds more than kMaxValueNesting levels.
enum class ByValueNesting : std::uint8_t { Ok, ContainsItself, TooDeep };
ByValueNesting by_value_levels(const Schema& schema, std::vector<std::uint32_t>& levels,
                               std::uint32_t& culprit);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCHEMA_SCHEMA_SIZES_HPP
