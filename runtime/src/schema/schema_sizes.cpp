// A schema's wire sizes, nesting levels and clocks (schema_sizes.hpp).
#include "schema_sizes.hpp"

#include <algorithm>
#include <utility>

#include "symcr/format/payload.hpp"

namespace symcr::detail {
namespace {

// Sizes saturate here rather than wrap: no payload is that large.
constexpr std::uint64_t kHuge = std::uint64_t{1} << 62;

// A size of an untrusted schema's values: it saturates at kHuge instead of wrapping.
struct SaturatingSize {
  std::uint64_t value;
  explicit SaturatingSize(std::uint64_t v) : value(v) {}
  SaturatingSize operator+(SaturatingSize other) const {
    const std::uint64_t sum = value + other.value;
    return SaturatingSize(sum < value || sum > kHuge ? kHuge : sum);
  }
  SaturatingSize operator*(SaturatingSize count) const {
    return SaturatingSize(value != 0 && count.value > kHuge / value ? kHuge : value * count.value);
  }
};

// Each type's least and fixed wire size, by the format core's rule (format::wire_size_of).
class SizeFacts {
 public:
  SizeFacts(const Schema& writer, WireSizes& out) : writer_(writer), out_(out) {
    out_.least.assign(writer.type_count, kUnknown);
    out_.fixed.assign(writer.type_count, WireSizes::kVariable);
  }
  // By-value nesting is acyclic and bounded in a parsed schema, so this recursion is too. Once
  // per schema: cold (compiled for size).
  __attribute__((cold)) void compute(std::uint32_t t) {
    if (out_.least[t] != kUnknown) return;
    const TypeInfo& type = writer_.types[t];
    bool fixed = format::fixed_wire_kind(type.kind);
    const std::uint64_t least =
        format::wire_size_of<SaturatingSize>(type, [this, &fixed](std::uint32_t member) {
          compute(member);
          fixed = fixed && out_.fixed[member] != WireSizes::kVariable;
          return SaturatingSize(out_.least[member]);
        }).value;
    out_.least[t] = least;
    if (fixed && least < kHuge) out_.fixed[t] = least;
  }

 private:
  static constexpr std::uint64_t kUnknown = ~std::uint64_t{0} - 1;
  const Schema& writer_;
  WireSizes& out_;
};

}  // namespace

__attribute__((cold)) WireSizes wire_sizes(const Schema& writer) {
  WireSizes sizes;
  SizeFacts facts(writer, sizes);
  for (std::uint32_t t = 0; t < writer.type_count; ++t) facts.compute(t);
  sizes.levels = value_levels(writer);
  sizes.clock_count = static_cast<std::uint32_t>(schema_clocks(writer).size());
  return sizes;
}

std::vector<const ClockInfo*> schema_clocks(const Schema& schema) {
  std::vector<const ClockInfo*> clocks;
  format::for_each_field_clock(schema, [&clocks](const ClockInfo& clock) {
    if (clock.index >= clocks.size()) clocks.resize(clock.index + std::size_t{1}, nullptr);
    clocks[clock.index] = &clock;
  });
  return clocks;
}

__attribute__((cold)) std::vector<std::uint32_t> value_levels(const Schema& writer) {
  std::vector<std::uint32_t> levels;
  std::uint32_t culprit = kNoType;
  if (by_value_levels(writer, levels, culprit) != ByValueNesting::Ok) {
    // Only a schema that was not parsed (a program's own) gets here: its values are refused.
    for (std::uint32_t& level : levels)
      level = std::min<std::uint32_t>(level, kMaxValueNesting + 1);
  }
  return levels;
}

namespace {

// The `i`th type `t` holds by value, or kNoType after the last.
std::uint32_t held_by_value(const TypeInfo& type, std::uint32_t i) {
  switch (type.kind) {
    case Kind::Struct:
    case Kind::Union:
      return i < type.field_count ? type.fields[i].type : kNoType;
    case Kind::Array:
    case Kind::Optional:
      return i == 0 ? type.element : kNoType;
    case Kind::Variant:
      return i < type.alternative_count ? type.alternatives[i] : kNoType;
    default:
      return kNoType;
  }
}

}  // namespace

__attribute__((cold)) ByValueNesting by_value_levels(const Schema& schema,
                                                     std::vector<std::uint32_t>& levels,
                                                     std::uint32_t& culprit) {
  constexpr std::uint32_t kUnvisited = ~std::uint32_t{0};
  constexpr std::uint32_t kOnPath = kUnvisited - 1;
  levels.assign(schema.type_count, kUnvisited);
  // Depth-first with an explicit path (type, next held type to visit), on the heap.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> path;
  for (std::uint32_t start = 0; start < schema.type_count; ++start) {
    if (levels[start] != kUnvisited) continue;
    levels[start] = kOnPath;
    path.emplace_back(start, 0);
    while (!path.empty()) {
      const std::uint32_t t = path.back().first;
      const TypeInfo& type = schema.types[t];
      const std::uint32_t held = held_by_value(type, path.back().second);
      if (held != kNoType) {
        ++path.back().second;
        if (held >= schema.type_count) continue;  // an unparsed (own) schema's type is trusted
        if (levels[held] == kOnPath) {
          culprit = held;
          return ByValueNesting::ContainsItself;
        }
        if (levels[held] == kUnvisited) {
          levels[held] = kOnPath;
          path.emplace_back(held, 0);
        }
        continue;
      }
      std::uint32_t level = 0;
      for (std::uint32_t i = 0; (held_by_value(type, i)) != kNoType; ++i) {
        const std::uint32_t h = held_by_value(type, i);
        if (h < schema.type_count) level = std::max(level, levels[h] + 1);
      }
      if (level > static_cast<std::uint32_t>(kMaxValueNesting)) {
        culprit = t;
        return ByValueNesting::TooDeep;
      }
      levels[t] = level;
      path.pop_back();
    }
  }
  return ByValueNesting::Ok;
}

}  // namespace symcr::detail
