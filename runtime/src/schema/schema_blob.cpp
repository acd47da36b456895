// Serialisation of a running build's schema (docs/format.md §2) and its FNV-1a 64 hash.
#include <cstring>
#include <utility>

#include "device_format.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "schema_sizes.hpp"
#include "symcr/format/hashes.hpp"
#include "wire.hpp"

// compute_schema_facts runs once per schema and process (the result is cached, see
// schema_cache.cpp): marked cold, so compiled for size even at -O3. serialise_schema is not:
// building a restore plan serialises the writer schema too.
namespace symcr::detail {
namespace {

// Names longer than the format's u16 length are cut; canonical C++ names never come close.
void put_str(std::vector<std::uint8_t>& out, const char* text) {
  std::size_t length = text ? std::strlen(text) : 0;
  if (length > 0xFFFF) length = 0xFFFF;
  put_u16(out, static_cast<std::uint16_t>(length));
  if (length) out.insert(out.end(), text, text + length);
}

void put_aliases(std::vector<std::uint8_t>& out, const char* const* aliases) {
  std::size_t count = 0;
  while (aliases && aliases[count] && count < 0xFF) ++count;
  put_u8(out, static_cast<std::uint8_t>(count));
  for (std::size_t i = 0; i < count; ++i) put_str(out, aliases[i]);
}

void put_f64(std::vector<std::uint8_t>& out, double value) { put_le(out, value); }

}  // namespace

void serialise_schema(const Schema& schema, std::vector<std::uint8_t>& out) {
  put_u32(out, schema.type_count);
  put_u32(out, schema.root_count);
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    put_u8(out, static_cast<std::uint8_t>(type.kind));
    put_u32(out, type.flags);
    put_u32(out, type.size);
    put_u32(out, type.align);
    put_str(out, type.name);
    put_aliases(out, type.renamed_from);
    if (type.flags & kTypeLeavesMembers) put_aliases(out, type.left_to_new_build);
    switch (type.kind) {
      case Kind::Struct:
      case Kind::Union:
        put_u32(out, type.field_count);
        for (std::uint32_t f = 0; f < type.field_count; ++f) {
          const FieldInfo& field = type.fields[f];
          put_str(out, field.name);
          put_u32(out, field.type);
          put_u32(out, field.offset);
          put_u16(out, field.bit_offset);
          put_u16(out, field.bit_width);
          // A range flag without bounds (a hand-written table's slip) is no range.
          std::uint32_t flags = field.flags;
          if (field.range == nullptr) flags &= ~std::uint32_t{kFieldHasRange};
          if (field.time == nullptr || field.time->clock == nullptr ||
              field.time->clock->name == nullptr) {
            flags &= ~std::uint32_t{kFieldClockTime};
          }
          put_u32(out, flags);
          put_aliases(out, field.renamed_from);
          if (flags & kFieldHasRange) {
            put_f64(out, field.range->min);
            put_f64(out, field.range->max);
          }
          if (flags & kFieldClockTime) {
            put_str(out, field.time->clock->name);
            put_le(out, field.time->never);
          }
        }
        if (type.flags & kTypeReferenceMembers) {
          put_u32(out, type.reference_member_count);
          for (std::uint32_t m = 0; m < type.reference_member_count; ++m) {
            const FieldInfo& member = type.reference_members[m];
            put_str(out, member.name);
            put_u32(out, member.type);
            put_u32(out, member.offset);
            put_u32(out, member.flags & kFieldBase);
            put_aliases(out, member.renamed_from);
          }
        }
        break;
      case Kind::Enum:
        put_u32(out, type.element);
        put_u32(out, type.enumerator_count);
        for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
          put_str(out, type.enumerators[e].name);
          put_le(out, type.enumerators[e].value);
        }
        break;
      case Kind::Array:
        put_u32(out, type.element);
        put_u64(out, type.count);
        break;
      case Kind::String:
        put_u32(out, type.element);
        break;
      case Kind::Container:
        put_u8(out, type.container_kind);
        put_u32(out, type.element);
        break;
      case Kind::Optional:
      case Kind::Pointer:
      case Kind::UniquePtr:
      case Kind::SharedPtr:
        put_u32(out, type.element);
        break;
      case Kind::Variant:
        put_u32(out, type.alternative_count);
        for (std::uint32_t a = 0; a < type.alternative_count; ++a) {
          put_u32(out, type.alternatives[a]);
        }
        break;
      case Kind::Bool:
      case Kind::Int:
      case Kind::UInt:
      case Kind::Float:
        break;
    }
  }
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    const RootInfo& root = schema.roots[r];
    put_str(out, root.name);
    put_u32(out, root.type);
    put_u32(out, root.flags);
    put_aliases(out, root.renamed_from);
  }
}

void serialise_blob(const Schema& schema, SchemaBlob& blob) {
  blob.storage.clear();
  serialise_schema(schema, blob.storage);
  blob.data = blob.storage.data();
  blob.size = blob.storage.size();
  blob.hash = format::fnv1a64(blob.data, blob.size);
}

namespace {

constexpr std::size_t kMaxFlatRuns = 64;  // beyond this a type is cheaper to walk

// Appends the runs of `type` placed at `base` to `runs`; false if it is not plain.
__attribute__((cold)) bool flat_runs_of(const Schema& schema, std::uint32_t type_index,
                                        std::uint32_t base, std::vector<FlatRun>& runs, int depth) {
  if (depth > 64 || type_index >= schema.type_count) return false;
  const TypeInfo& type = schema.types[type_index];
  auto append = [&runs](std::uint32_t offset, std::uint32_t length) {
    if (!runs.empty() && runs.back().offset + runs.back().length == offset) {
      runs.back().length += length;
    } else {
      runs.push_back(FlatRun{offset, length});
    }
    return runs.size() <= kMaxFlatRuns;
  };
  switch (type.kind) {
    case Kind::Int:
    case Kind::UInt:
    case Kind::Enum:
      return append(base, type.size);
    case Kind::Float:
      return type.size != 16 && append(base, type.size);
    case Kind::Union:
      return append(base, type.size);
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        const FieldInfo& field = type.fields[f];
        if (field.bit_width ||
            !flat_runs_of(schema, field.type, base + field.offset, runs, depth + 1)) {
          return false;
        }
      }
      return true;
    case Kind::Array: {
      if (type.element >= schema.type_count) return false;
      const std::uint32_t stride = schema.types[type.element].size;
      for (std::uint64_t i = 0; i < type.count; ++i) {
        if (!flat_runs_of(schema, type.element, base + static_cast<std::uint32_t>(i * stride), runs,
                          depth + 1)) {
          return false;
        }
      }
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

__attribute__((cold)) void mark_with_bases(const TypeInfo* types, std::uint32_t type_count,
                                           std::vector<std::uint32_t>& pending,
                                           std::vector<bool>& marked) {
  // Each type is visited once: a corrupt schema's base fields may form cycles or diamonds.
  marked.resize(type_count, false);
  while (!pending.empty()) {
    const std::uint32_t t = pending.back();
    pending.pop_back();
    if (t >= type_count || marked[t]) continue;
    marked[t] = true;
    if (types[t].kind != Kind::Struct) continue;
    for (std::uint32_t f = 0; f < types[t].field_count; ++f) {
      if (types[t].fields[f].flags & kFieldBase) pending.push_back(types[t].fields[f].type);
    }
  }
}

__attribute__((cold)) SchemaFacts compute_schema_facts(const Schema& schema) {
  SchemaFacts facts;
  facts.flat_first.assign(schema.type_count, kNotFlat);
  facts.flat_count.assign(schema.type_count, 0);
  facts.flat_wire_size.assign(schema.type_count, 0);
  facts.has_pointer_fields.assign(schema.type_count, false);
  // The flat runs' wire size is the format's rule's (their bytes are their memory bytes).
  WireSizes sizes = wire_sizes(schema);
  facts.nesting_levels = std::move(sizes.levels);
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    const TypeInfo& type = schema.types[t];
    if (type.kind != Kind::Struct) continue;
    if ((type.flags & kTypeDynamicType) && type.lifecycle && type.lifecycle->vtable) {
      facts.dynamic_types.push_back(SchemaFacts::DynamicType{type.lifecycle->vtable, t});
    }
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const std::uint32_t field_type = type.fields[f].type;
      if (field_type < schema.type_count && schema.types[field_type].kind == Kind::Pointer) {
        facts.has_pointer_fields[t] = true;
      }
    }
  }
  std::vector<FlatRun> runs;
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    runs.clear();
    if (!flat_runs_of(schema, t, 0, runs, 0)) continue;
    facts.flat_first[t] = static_cast<std::uint32_t>(facts.flat_runs.size());
    facts.flat_count[t] = static_cast<std::uint32_t>(runs.size());
    facts.flat_wire_size[t] = static_cast<std::uint32_t>(sizes.fixed[t]);
    facts.flat_runs.insert(facts.flat_runs.end(), runs.begin(), runs.end());
  }
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    if (schema.types[t].kind == Kind::Pointer) facts.has_raw_pointers = true;
    if (schema.types[t].kind == Kind::Pointer || schema.types[t].kind == Kind::SharedPtr) {
      facts.has_references = true;
    }
  }
  facts.clocks = schema_clocks(schema);
  return facts;
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::UInt:
      return "uint";
    case Kind::Float:
      return "float";
    case Kind::Enum:
      return "enum";
    case Kind::Struct:
      return "struct";
    case Kind::Union:
      return "union";
    case Kind::Array:
      return "array";
    case Kind::String:
      return "string";
    case Kind::Container:
      return "container";
    case Kind::Optional:
      return "optional";
    case Kind::Variant:
      return "variant";
    case Kind::Pointer:
      return "pointer";
    case Kind::UniquePtr:
      return "unique_ptr";
    case Kind::SharedPtr:
      return "shared_ptr";
  }
  return "unknown";
}

}  // namespace symcr::detail
