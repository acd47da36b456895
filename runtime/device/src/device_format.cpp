#include "device_format.hpp"

namespace symcr {
namespace device {
namespace detail {

namespace {

// Types nest by value only as deep as the source does; the bound guards hand-written tables.
constexpr int kMaxNesting = 64;

std::uint32_t first_unheld_at(const Schema& schema, std::uint32_t t, int depth) {
  if (t >= schema.type_count || depth > kMaxNesting) return t;
  const TypeView type = type_at(schema, t);
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
    case Kind::Array:  // more elements than the target's std::size_t counts: not in memory
      if (compact(schema) == nullptr && schema.types[t].count != type.count) return t;
      return first_unheld_at(schema, type.element, depth + 1);
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        const std::uint32_t unheld =
            first_unheld_at(schema, field_at(schema, t, f).type, depth + 1);
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

// format::wire_size_of's rule over the view: a struct's fields, an array's elements, else the
// value's own bytes.
std::size_t wire_size(const Schema& schema, std::uint32_t t) {
  const TypeView type = type_at(schema, t);
  if (type.kind == Kind::Struct) {
    std::size_t total = 0;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      total += wire_size(schema, field_at(schema, t, f).type);
    }
    return total;
  }
  if (type.kind == Kind::Array) {
    return wire_size(schema, type.element) * static_cast<std::size_t>(type.count);
  }
  return format::own_wire_size(type);
}

std::size_t pointer_count(const Schema& schema, std::uint32_t t) {
  const TypeView type = type_at(schema, t);
  switch (type.kind) {
    case Kind::Pointer:
      return 1;
    case Kind::Array:
      return pointer_count(schema, type.element) * static_cast<std::size_t>(type.count);
    case Kind::Struct: {
      std::size_t total = 0;
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        total += pointer_count(schema, field_at(schema, t, f).type);
      }
      return total;
    }
    default:
      return 0;
  }
}

// The clock of the first time field (in the structs' order) whose clock has index `index`, or,
// with kNoType, one more than the greatest index of any: a walk of its own, to stop there.
const ClockInfo* clocks_walk(const Schema& schema, std::uint32_t index, std::uint32_t* count) {
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeView type = type_at(schema, t);
    if (type.kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const FieldTime* time = field_at(schema, t, f).time;
      if (time == nullptr) continue;
      if (time->clock->index == index) return time->clock;
      if (time->clock->index >= *count) *count = time->clock->index + 1;
    }
  }
  return nullptr;
}

std::uint32_t clock_count(const Schema& schema) {
  std::uint32_t count = 0;
  clocks_walk(schema, kNoType, &count);
  return count;
}

const ClockInfo* clock_at(const Schema& schema, std::uint32_t index) {
  std::uint32_t ignored = 0;
  return clocks_walk(schema, index, &ignored);
}

PayloadShape payload_shape(const Schema& schema) {
  return PayloadShape{values_size(schema), clock_count(schema), nullptr, 0};
}

std::size_t values_size(const Schema& schema) {
  std::size_t total = 0;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    total += wire_size(schema, schema.roots[r].type);
  }
  return total;
}

std::uint64_t bits_at(std::uint64_t raw, unsigned offset, unsigned width, bool is_signed) {
  const unsigned shift = 64 - width;
  raw <<= shift - offset;  // the field's top bit at bit 63
  return is_signed ? static_cast<std::uint64_t>(static_cast<std::int64_t>(raw) >> shift)
                   : raw >> shift;
}

bool follow_path(const Schema& schema, std::uint32_t root, const std::uint32_t* steps,
                 std::size_t step_count, std::size_t* offset, std::uint32_t* type) {
  if (root >= schema.root_count) return false;
  std::uint32_t t = schema.roots[root].type;
  std::size_t at = 0;
  for (std::size_t i = 0; i < step_count; ++i) {
    if (t >= schema.type_count) return false;
    const TypeView current = type_at(schema, t);
    if (current.kind == Kind::Struct) {
      // Fields, then reference members (docs/format.md §2): same build, same offsets.
      if (steps[i] >= current.member_count) return false;
      const FieldView field = field_at(schema, t, steps[i]);
      if (field.bit_width != 0) return false;  // no address to point at
      at += field.offset;
      t = field.type;
    } else if (current.kind == Kind::Array) {
      if (steps[i] >= current.count || current.element >= schema.type_count) return false;
      at += static_cast<std::size_t>(steps[i]) * type_at(schema, current.element).size;
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
