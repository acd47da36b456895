#include "device_format.hpp"

namespace symcr {
namespace device {
namespace detail {

namespace {

// Types nest by value only as deep as the source does; the bound guards hand-written tables.
constexpr int kMaxNesting = 64;

std::uint32_t first_unheld_at(const Schema& schema, std::uint32_t t, int depth) {
  if (t >= schema.type_count || depth > kMaxNesting) return t;
  const TypeInfo& type = schema.types[t];
  switch (type.kind) {
    case Kind::Bool:
    case Kind::Union:
      return kNoType;
    case Kind::Int:
    case Kind::UInt:
    case Kind::Enum:
      return type.size >= 1 && type.size <= 8 ? kNoType : t;
    case Kind::Float:
      return type.size == 4 || type.size == 8 ? kNoType : t;
    case Kind::Pointer:  // the pointee is not saved through the pointer: a path names it
      return type.element < schema.type_count ? kNoType : t;
    case Kind::Array:
      return first_unheld_at(schema, type.element, depth + 1);
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        const std::uint32_t unheld = first_unheld_at(schema, type.fields[f].type, depth + 1);
        if (unheld != kNoType) return unheld;
      }
      return kNoType;
    default:
      return t;
  }
}

}  // namespace

std::uint32_t first_unheld_type(const Schema& schema) {
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    const std::uint32_t unheld = first_unheld_at(schema, schema.roots[r].type, 0);
    if (unheld != kNoType) return unheld;
  }
  return kNoType;
}

std::size_t wire_size(const Schema& schema, std::uint32_t t) {
  return format::wire_size_of<std::size_t>(
      schema.types[t], [&schema](std::uint32_t member) { return wire_size(schema, member); });
}

std::size_t pointer_count(const Schema& schema, std::uint32_t t) {
  const TypeInfo& type = schema.types[t];
  switch (type.kind) {
    case Kind::Pointer:
      return 1;
    case Kind::Array:
      return pointer_count(schema, type.element) * static_cast<std::size_t>(type.count);
    case Kind::Struct: {
      std::size_t total = 0;
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        total += pointer_count(schema, type.fields[f].type);
      }
      return total;
    }
    default:
      return 0;
  }
}

std::uint32_t clock_count(const Schema& schema) {
  std::uint32_t count = 0;
  format::for_each_field_clock(schema, [&count](const ClockInfo& clock) {
    if (clock.index >= count) count = clock.index + 1;
  });
  return count;
}

// The first field's clock of that index: a loop of its own, to stop there.
const ClockInfo* clock_at(const Schema& schema, std::uint32_t index) {
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    if (type.kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const ClockInfo* clock = format::field_clock(type.fields[f]);
      if (clock != nullptr && clock->index == index) return clock;
    }
  }
  return nullptr;
}

std::size_t values_size(const Schema& schema) {
  std::size_t total = 0;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    total += wire_size(schema, schema.roots[r].type);
  }
  return total;
}

bool follow_path(const Schema& schema, std::uint32_t root, const std::uint32_t* steps,
                 std::size_t step_count, std::size_t* offset, std::uint32_t* type) {
  if (root >= schema.root_count) return false;
  std::uint32_t t = schema.roots[root].type;
  std::size_t at = 0;
  for (std::size_t i = 0; i < step_count; ++i) {
    if (t >= schema.type_count) return false;
    const TypeInfo& current = schema.types[t];
    if (current.kind == Kind::Struct) {
      // Fields, then reference members (docs/format.md §2): same build, same offsets.
      const std::uint32_t member = steps[i] - current.field_count;
      if (steps[i] >= current.field_count && member >= current.reference_member_count) {
        return false;
      }
      const FieldInfo& field = steps[i] < current.field_count ? current.fields[steps[i]]
                                                              : current.reference_members[member];
      if (field.bit_width != 0) return false;  // no address to point at
      at += field.offset;
      t = field.type;
    } else if (current.kind == Kind::Array) {
      if (steps[i] >= current.count || current.element >= schema.type_count) return false;
      at += static_cast<std::size_t>(steps[i]) * schema.types[current.element].size;
      t = current.element;
    } else {
      return false;
    }
  }
  *offset = at;
  *type = t;
  return t < schema.type_count;
}

}  // namespace detail
}  // namespace device
}  // namespace symcr
