#include "device_format.hpp"

namespace symcr {
namespace device {
namespace detail {

const char kMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'C', 'K', 'P'};

// Four bits at a time through a 16-entry table: 64 bytes of flash instead of the 1-8 KB of the
// host's byte-wise tables, at a speed ample for a record of a few kilobytes.
std::uint32_t crc32c(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
  static const std::uint32_t kNibble[16] = {0x00000000u, 0x105EC76Fu, 0x20BD8EDEu, 0x30E349B1u,
                                            0x417B1DBCu, 0x5125DAD3u, 0x61C69362u, 0x7198540Du,
                                            0x82F63B78u, 0x92A8FC17u, 0xA24BB5A6u, 0xB21572C9u,
                                            0xC38D26C4u, 0xD3D3E1ABu, 0xE330A81Au, 0xF36E6F75u};
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    crc = (crc >> 4) ^ kNibble[crc & 15u];
    crc = (crc >> 4) ^ kNibble[crc & 15u];
  }
  return ~crc;
}

std::uint32_t program_id(const char* program) {
  if (program == nullptr || *program == '\0') return 0;
  std::uint32_t hash = 2166136261u;
  for (const char* c = program; *c; ++c) {
    hash ^= static_cast<std::uint8_t>(*c);
    hash *= 16777619u;
  }
  return hash == 0 ? 1 : hash;
}

std::uint64_t fnv1a64(const std::uint8_t* data, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

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
  const TypeInfo& type = schema.types[t];
  switch (type.kind) {
    case Kind::Bool:
      return 1;
    case Kind::Pointer:
      return 4;
    case Kind::Array:
      return wire_size(schema, type.element) * static_cast<std::size_t>(type.count);
    case Kind::Struct: {
      std::size_t total = 0;
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        total += wire_size(schema, type.fields[f].type);
      }
      return total;
    }
    default:  // Int, UInt, Enum, Float, Union: their bytes
      return type.size;
  }
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
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    if (type.kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const FieldInfo& field = type.fields[f];
      if ((field.flags & kFieldClockTime) && field.time && field.time->clock &&
          field.time->clock->index >= count) {
        count = field.time->clock->index + 1;
      }
    }
  }
  return count;
}

const ClockInfo* clock_at(const Schema& schema, std::uint32_t index) {
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    if (type.kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const FieldInfo& field = type.fields[f];
      if ((field.flags & kFieldClockTime) && field.time && field.time->clock &&
          field.time->clock->index == index) {
        return field.time->clock;
      }
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
