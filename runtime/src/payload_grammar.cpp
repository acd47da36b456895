// The payload grammar's size facts, path text and fault reports (payload_grammar.hpp).
#include "payload_grammar.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <utility>

#include "payload_error.hpp"

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

// Paths are rendered only for reports and errors: cold.
__attribute__((cold)) void append_path(std::string& path, const PathFrame& frame) {
  char buffer[48];
  switch (frame.kind) {
    case PathFrame::Kind::Name:
      if (!path.empty()) path += '.';
      path += frame.name;
      return;
    case PathFrame::Kind::Index:
      std::snprintf(buffer, sizeof buffer, "[%" PRIu64 "]", frame.index);
      path += buffer;
      return;
    case PathFrame::Kind::Heap:
      std::snprintf(buffer, sizeof buffer, "heap#%" PRIu64 "(", frame.index);
      path += buffer;
      path += frame.name;
      path += ')';
      return;
    case PathFrame::Kind::Alternative:
      path += '<';
      path += frame.name;
      path += '>';
      return;
  }
}

__attribute__((cold)) std::string render_path(const PathFrame* frames, std::size_t count) {
  std::string path;
  for (std::size_t i = 0; i < count; ++i) append_path(path, frames[i]);
  return path;
}

bool PayloadReader::heap_count(std::uint32_t& count) {
  if (!in_.read(count)) return truncated("heap count");
  // A heap object takes at least its 5-byte header.
  if (count > in_.remaining() / 5) return fail("heap count %u exceeds the payload", count);
  return true;
}

bool PayloadReader::heap_object(std::uint32_t ordinal, std::uint32_t& type, std::uint8_t& owner) {
  if (!in_.read(type) || !in_.read(owner)) return truncated("heap object");
  if (type >= writer_.type_count) return fail("heap object %u has type %u", ordinal, type);
  if (owner > format::kHeapOwnerShared) return fail("heap object %u has owner %u", ordinal, owner);
  return true;
}

bool PayloadReader::reference_count(std::uint32_t& count) {
  if (!in_.read(count)) return truncated("reference count");
  // A reference takes at least an object reference without steps: base, object, step count and
  // target.
  if (count > in_.remaining() / format::object_reference_size(0)) {
    return fail("reference count %u exceeds the payload", count);
  }
  return true;
}

bool PayloadReader::clock_readings(ClockReadings& out) {
  out = ClockReadings();
  if (sizes_.clock_count == 0) return true;
  if (!in_.bytes(format::clock_readings_size(sizes_.clock_count), out.bytes)) {
    return truncated("clock readings");
  }
  out.epoch = format::load64(out.bytes);
  out.count = sizes_.clock_count;
  return true;
}

bool PayloadReader::finish() {
  if (in_.at_end()) return true;
  return fail("%zu bytes after the payload's references", in_.remaining());
}

// A step into a struct is a field index (then a reference member's: format.md §2), into an array an
// element index, into an optional or unique_ptr 0 (its value), into a variant an alternative index,
// into a string a character index (bounded by the string's length once restored).
bool PayloadReader::step_into(std::uint32_t i, std::uint32_t& type, std::uint32_t step) {
  const TypeInfo& t = writer_.types[type];
  switch (t.kind) {
    case Kind::Struct: {
      const FieldInfo* member = step_member(t, step);
      if (!member) return fail("reference %u: no field %u in %s", i, step, t.name);
      type = member->type;
      return true;
    }
    case Kind::Array:
      if (step >= t.count) return fail("reference %u: index %u beyond %s", i, step, t.name);
      type = t.element;
      return true;
    case Kind::Optional:
    case Kind::UniquePtr:
      if (step != 0) return fail("reference %u: step %u into %s", i, step, t.name);
      type = t.element;
      return true;
    case Kind::Variant:
      if (step >= t.alternative_count) {
        return fail("reference %u: alternative %u of %s", i, step, t.name);
      }
      type = t.alternatives[step];
      return true;
    case Kind::String:
      type = t.element;
      return true;
    default:
      return fail("reference %u: a step into %s", i, t.name);
  }
}

bool PayloadReader::truncated(const char* what) { return fail("truncated in %s", what); }
bool PayloadReader::invalid_bool(std::uint8_t value) { return fail("bool value %u", value); }
bool PayloadReader::empty_array(const TypeInfo& type) {
  return fail("array of %" PRIu64 " empty elements", type.count);
}
bool PayloadReader::container_too_long(std::uint32_t count) {
  return fail("container count %u exceeds the payload", count);
}
bool PayloadReader::invalid_flag(const TypeInfo& type, std::uint8_t flag) {
  return fail("%s flag %u", type.kind == Kind::Optional ? "optional" : "unique_ptr", flag);
}
bool PayloadReader::invalid_alternative(std::uint32_t index) {
  return fail("variant index %u", index);
}
bool PayloadReader::shared_outside() { return fail("shared_ptr marked as outside"); }
bool PayloadReader::too_deep() {
  return fail("values nest deeper than the nesting limit of %d levels", kMaxValueNesting);
}
bool PayloadReader::invalid_reference(std::uint32_t i, const char* what, std::uint32_t value) {
  return fail("reference %u %s %u", i, what, value);
}
bool PayloadReader::missing_base(std::uint32_t i, const Reference& ref) {
  if (ref.base == kBaseObject) return fail("reference %u to a missing object %u", i, ref.a);
  return fail("reference %u to a missing element %u of container %u", i, ref.b, ref.a);
}
bool PayloadReader::wrong_target(std::uint32_t i, std::uint32_t type, std::uint32_t target) {
  return fail("reference %u: steps end at type %u, not %u", i, type, target);
}

bool PayloadReader::fail(const char* format, ...) {
  va_list args;
  va_start(args, format);
  set_corrupt_payload(error_, format, args);
  va_end(args);
  return false;
}

}  // namespace symcr::detail
