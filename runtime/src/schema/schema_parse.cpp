// Parsing a writer schema from checkpoint bytes (docs/format.md §2). The bytes are untrusted:
// every read is bounds-checked, every count is bounded by the bytes left (so allocation never
// exceeds a small multiple of the input), every type index is checked, scalar sizes are
// checked, and by-value self-containment and absurd nesting are refused.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include "parsed_schema.hpp"
#include "schema_blob.hpp"
#include "schema_sizes.hpp"
#include "symcr/format/hashes.hpp"
#include "wire.hpp"

namespace symcr::detail {

struct ParsedSchema::Storage {
  std::vector<char> strings;  // every name, NUL-terminated
  std::vector<TypeInfo> types;
  std::vector<FieldInfo> fields;
  std::vector<FieldRange> ranges;  // FieldInfo::range points here (set once all are read)
  std::vector<FieldTime> times;    // FieldInfo::time points here
  std::vector<ClockInfo> clocks;   // FieldTime::clock points here, in index order
  std::vector<EnumeratorInfo> enumerators;
  std::vector<std::uint32_t> alternatives;
  std::vector<RootInfo> roots;
  std::vector<const char*> aliases;  // nullptr-terminated groups
  Schema schema{};
  std::uint64_t hash = 0;
  std::vector<std::uint8_t> bytes;
};

ParsedSchema::ParsedSchema() : storage(new Storage()) {}
ParsedSchema::~ParsedSchema() = default;
ParsedSchema::ParsedSchema(ParsedSchema&&) noexcept = default;
ParsedSchema& ParsedSchema::operator=(ParsedSchema&&) noexcept = default;
const Schema& ParsedSchema::schema() const { return storage->schema; }
std::uint64_t ParsedSchema::hash() const { return storage->hash; }
const std::vector<std::uint8_t>& ParsedSchema::bytes() const { return storage->bytes; }

namespace {

constexpr std::size_t kNone = ~std::size_t{0};
constexpr std::uint32_t kMaxTypeSize = 0x7FFFFFFFu;

// Minimum encoded sizes, used to bound counts by the bytes that remain.
constexpr std::size_t kMinType = 1 + 4 + 4 + 4 + 2 + 1;
constexpr std::size_t kMinField = 2 + 4 + 4 + 2 + 2 + 4 + 1;
constexpr std::size_t kMinReferenceMember = 2 + 4 + 4 + 4 + 1;
constexpr std::size_t kMinRoot = 2 + 4 + 4 + 1;
constexpr std::size_t kMinEnumerator = 2 + 8;

// Where the pointers of the final tables will point, recorded as offsets while the vectors
// still grow.
struct TypeFixup {
  std::size_t name, aliases, left_to_new_build, fields, enumerators, alternatives;
  std::size_t reference_members;
};
struct NamedFixup {
  std::size_t name, aliases;
  std::size_t range = 0;  // fields with kFieldHasRange: index into Storage::ranges
  std::size_t time = 0;   // fields with kFieldClockTime: index into Storage::times
};

class Parser {
 public:
  Parser(const std::uint8_t* data, std::size_t size, ParsedSchema::Storage& storage)
      : in_(data, size), s_(storage) {}

  Status run() {
    std::uint32_t type_count = 0, root_count = 0;
    if (!in_.read(type_count) || !in_.read(root_count)) return truncated("counts");
    if (type_count > in_.remaining() / kMinType) {
      return corrupt("type count %u exceeds the schema's size", type_count);
    }
    s_.types.reserve(type_count);
    type_fixups_.reserve(type_count);
    for (std::uint32_t t = 0; t < type_count; ++t) {
      Status status = parse_type(t, type_count);
      if (!status.ok()) return status;
    }
    if (root_count > in_.remaining() / kMinRoot) {
      return corrupt("root count %u exceeds the schema's size", root_count);
    }
    s_.roots.reserve(root_count);
    for (std::uint32_t r = 0; r < root_count; ++r) {
      RootInfo root{};
      NamedFixup fixup{};
      std::uint32_t type = 0;
      if (!read_str(fixup.name) || !in_.read(type) || !in_.read(root.flags) ||
          !read_aliases(fixup.aliases)) {
        return truncated("root");
      }
      if (type >= type_count) return corrupt("root %u has type index %u out of range", r, type);
      root.type = type;
      s_.roots.push_back(root);
      root_fixups_.push_back(fixup);
    }
    if (!in_.at_end()) return corrupt("%zu bytes after the schema", in_.remaining());
    Status status = check_types();
    if (!status.ok()) return status;
    finish();
    return check_nesting();
  }

 private:
  __attribute__((format(printf, 2, 3))) Status corrupt(const char* format, ...) {
    char buffer[200];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return Status(Error::Corrupt, "invalid schema: %s", buffer);
  }
  Status truncated(const char* what) {
    return Status(Error::Corrupt, "invalid schema: truncated in %s", what);
  }

  bool read_str(std::size_t& offset) {
    std::uint16_t length = 0;
    const std::uint8_t* bytes = nullptr;
    if (!in_.read(length) || !in_.bytes(length, bytes)) return false;
    offset = s_.strings.size();
    s_.strings.insert(s_.strings.end(), bytes, bytes + length);
    s_.strings.push_back('\0');
    return true;
  }

  // Aliases: a nullptr-terminated group in s_.aliases; entries hold string offsets + 1 until
  // finish() turns them into pointers (0 stays the terminator).
  bool read_aliases(std::size_t& group) {
    std::uint8_t count = 0;
    if (!in_.read(count)) return false;
    if (count == 0) {
      group = kNone;
      return true;
    }
    if (count > in_.remaining() / 2) return false;
    group = s_.aliases.size();
    for (std::uint8_t i = 0; i < count; ++i) {
      std::size_t offset = 0;
      if (!read_str(offset)) return false;
      s_.aliases.push_back(reinterpret_cast<const char*>(offset + 1));
    }
    s_.aliases.push_back(nullptr);
    return true;
  }

  Status parse_type(std::uint32_t index, std::uint32_t type_count) {
    TypeInfo type{};
    TypeFixup fixup{kNone, kNone, kNone, kNone, kNone, kNone, kNone};
    std::uint8_t kind = 0;
    if (!in_.read(kind) || !in_.read(type.flags) || !in_.read(type.size) || !in_.read(type.align) ||
        !read_str(fixup.name) || !read_aliases(fixup.aliases) ||
        ((type.flags & kTypeLeavesMembers) && !read_aliases(fixup.left_to_new_build))) {
      return truncated("type");
    }
    if (kind < static_cast<std::uint8_t>(Kind::Bool) ||
        kind > static_cast<std::uint8_t>(Kind::SharedPtr)) {
      return corrupt("type %u has unknown kind %u", index, kind);
    }
    if (type.size > kMaxTypeSize) return corrupt("type %u has size %u", index, type.size);
    type.kind = static_cast<Kind>(kind);
    type.element = kNoType;
    auto check_index = [&](std::uint32_t value) { return value < type_count; };
    switch (type.kind) {
      case Kind::Bool:
        if (type.size != 1) return corrupt("bool type %u has size %u", index, type.size);
        break;
      case Kind::Int:
      case Kind::UInt:
        if (type.size != 1 && type.size != 2 && type.size != 4 && type.size != 8) {
          return corrupt("integer type %u has size %u", index, type.size);
        }
        break;
      case Kind::Float:
        if (type.size != 4 && type.size != 8 && type.size != 16) {
          return corrupt("floating type %u has size %u", index, type.size);
        }
        break;
      case Kind::Struct:
      case Kind::Union: {
        std::uint32_t count = 0;
        if (!in_.read(count)) return truncated("field count");
        if (count > in_.remaining() / kMinField) {
          return corrupt("type %u field count %u exceeds the schema's size", index, count);
        }
        fixup.fields = s_.fields.size();
        type.field_count = count;
        for (std::uint32_t f = 0; f < count; ++f) {
          FieldInfo field{};
          NamedFixup named{};
          if (!read_str(named.name) || !in_.read(field.type) || !in_.read(field.offset) ||
              !in_.read(field.bit_offset) || !in_.read(field.bit_width) || !in_.read(field.flags) ||
              !read_aliases(named.aliases)) {
            return truncated("field");
          }
          if (field.flags & kFieldHasRange) {
            FieldRange range{};
            if (!in_.read(range.min) || !in_.read(range.max)) return truncated("field range");
            named.range = s_.ranges.size();
            s_.ranges.push_back(range);
          }
          if (field.flags & kFieldClockTime) {
            std::size_t clock_name = 0;
            FieldTime time{};
            if (!read_str(clock_name) || !in_.read(time.never)) return truncated("field clock");
            named.time = s_.times.size();
            s_.times.push_back(time);
            time_clock_names_.push_back(clock_name);
          }
          if (!check_index(field.type)) {
            return corrupt("field %u of type %u has type index %u out of range", f, index,
                           field.type);
          }
          if (field.bit_width > 64 || field.bit_offset > 4096) {
            return corrupt("field %u of type %u has bit-field %u:%u", f, index, field.bit_offset,
                           field.bit_width);
          }
          s_.fields.push_back(field);
          field_fixups_.push_back(named);
        }
        if (type.flags & kTypeReferenceMembers) {
          Status status = parse_reference_members(index, type_count, type, fixup);
          if (!status.ok()) return status;
        }
        break;
      }
      case Kind::Enum: {
        std::uint32_t count = 0;
        if (!in_.read(type.element) || !in_.read(count)) return truncated("enum");
        if (!check_index(type.element)) return corrupt("enum %u underlying out of range", index);
        if (count > in_.remaining() / kMinEnumerator) {
          return corrupt("enum %u enumerator count %u exceeds the schema's size", index, count);
        }
        fixup.enumerators = s_.enumerators.size();
        type.enumerator_count = count;
        for (std::uint32_t e = 0; e < count; ++e) {
          std::size_t name = 0;
          EnumeratorInfo enumerator{};
          if (!read_str(name) || !in_.read(enumerator.value)) return truncated("enumerator");
          s_.enumerators.push_back(enumerator);
          enumerator_names_.push_back(name);
        }
        break;
      }
      case Kind::Array:
        if (!in_.read(type.element) || !in_.read(type.count)) return truncated("array");
        if (!check_index(type.element)) return corrupt("array %u element out of range", index);
        // Every C++ object has at least one byte: a longer array is corrupt (and would let a
        // few bytes of input drive billions of iterations).
        if (type.count > type.size) {
          return corrupt("array %u has %llu elements in %u bytes", index,
                         static_cast<unsigned long long>(type.count), type.size);
        }
        break;
      case Kind::String:
      case Kind::Optional:
      case Kind::Pointer:
      case Kind::UniquePtr:
      case Kind::SharedPtr:
        if (!in_.read(type.element)) return truncated("element");
        if (!check_index(type.element)) return corrupt("type %u element out of range", index);
        break;
      case Kind::Container:
        if (!in_.read(type.container_kind) || !in_.read(type.element)) {
          return truncated("container");
        }
        if (type.container_kind < static_cast<std::uint8_t>(ContainerKind::Vector) ||
            type.container_kind > static_cast<std::uint8_t>(ContainerKind::UnorderedMultiMap)) {
          return corrupt("container %u has unknown container kind %u", index, type.container_kind);
        }
        if (!check_index(type.element)) return corrupt("container %u element out of range", index);
        break;
      case Kind::Variant: {
        std::uint32_t count = 0;
        if (!in_.read(count)) return truncated("variant");
        if (count > in_.remaining() / 4) {
          return corrupt("variant %u alternative count %u exceeds the schema's size", index, count);
        }
        fixup.alternatives = s_.alternatives.size();
        type.alternative_count = count;
        for (std::uint32_t a = 0; a < count; ++a) {
          std::uint32_t alternative = 0;
          if (!in_.read(alternative)) return truncated("alternative");
          if (!check_index(alternative)) {
            return corrupt("variant %u alternative %u out of range", index, a);
          }
          s_.alternatives.push_back(alternative);
        }
        break;
      }
    }
    s_.types.push_back(type);
    type_fixups_.push_back(fixup);
    return Status();
  }

  // A struct's members that hold no value but may be a reference's target (format.md §2):
  // kept with the fields, after them, as FieldInfo with only a name, type, offset and aliases.
  Status parse_reference_members(std::uint32_t index, std::uint32_t type_count, TypeInfo& type,
                                 TypeFixup& fixup) {
    std::uint32_t count = 0;
    if (!in_.read(count)) return truncated("reference member count");
    if (count > in_.remaining() / kMinReferenceMember) {
      return corrupt("type %u reference member count %u exceeds the schema's size", index, count);
    }
    fixup.reference_members = s_.fields.size();
    type.reference_member_count = count;
    for (std::uint32_t m = 0; m < count; ++m) {
      FieldInfo member{};
      NamedFixup named{};
      if (!read_str(named.name) || !in_.read(member.type) || !in_.read(member.offset) ||
          !in_.read(member.flags) || !read_aliases(named.aliases)) {
        return truncated("reference member");
      }
      if (member.flags & ~std::uint32_t{kFieldBase}) {
        return corrupt("reference member %u of type %u has flags %u", m, index, member.flags);
      }
      if (member.type >= type_count) {
        return corrupt("reference member %u of type %u has type index %u out of range", m, index,
                       member.type);
      }
      s_.fields.push_back(member);
      field_fixups_.push_back(named);
    }
    return Status();
  }

  // Checks that need every type: element kinds.
  Status check_types() {
    const std::uint32_t count = static_cast<std::uint32_t>(s_.types.size());
    for (std::uint32_t t = 0; t < count; ++t) {
      const TypeInfo& type = s_.types[t];
      if (type.kind == Kind::Enum) {
        const TypeInfo& underlying = s_.types[type.element];
        if ((underlying.kind != Kind::Int && underlying.kind != Kind::UInt) ||
            underlying.size != type.size) {
          return corrupt("enum %u has an underlying type that is not an integer of its size", t);
        }
      }
      if (type.kind == Kind::String) {
        const TypeInfo& character = s_.types[type.element];
        if ((character.kind != Kind::Int && character.kind != Kind::UInt) ||
            (character.size != 1 && character.size != 2 && character.size != 4)) {
          return corrupt("string %u has a character type that is not a 1/2/4-byte integer", t);
        }
      }
    }
    return Status();
  }

  // After finish(): no type contains itself by value or nests deeper than the nesting limit.
  Status check_nesting() {
    std::vector<std::uint32_t> levels;
    std::uint32_t culprit = kNoType;
    switch (by_value_levels(s_.schema, levels, culprit)) {
      case ByValueNesting::Ok:
        return Status();
      case ByValueNesting::ContainsItself:
        return corrupt("type %u contains itself by value", culprit);
      case ByValueNesting::TooDeep:
        return corrupt("type %u nests values by value deeper than the nesting limit of %d levels",
                       culprit, kMaxValueNesting);
    }
    return Status();
  }

  void finish() {
    const char* base = s_.strings.data();
    for (const char*& alias : s_.aliases) {
      if (alias) alias = base + (reinterpret_cast<std::size_t>(alias) - 1);
    }
    auto aliases_at = [&](std::size_t group) -> const char* const* {
      return group == kNone ? nullptr : s_.aliases.data() + group;
    };
    for (std::size_t f = 0; f < s_.fields.size(); ++f) {
      s_.fields[f].name = base + field_fixups_[f].name;
      s_.fields[f].renamed_from = aliases_at(field_fixups_[f].aliases);
      if (s_.fields[f].flags & kFieldHasRange)
        s_.fields[f].range = &s_.ranges[field_fixups_[f].range];
      if (s_.fields[f].flags & kFieldClockTime)
        s_.fields[f].time = &s_.times[field_fixups_[f].time];
    }
    number_clocks(base);
    for (std::size_t e = 0; e < s_.enumerators.size(); ++e) {
      s_.enumerators[e].name = base + enumerator_names_[e];
    }
    for (std::size_t t = 0; t < s_.types.size(); ++t) {
      TypeInfo& type = s_.types[t];
      const TypeFixup& fixup = type_fixups_[t];
      type.name = base + fixup.name;
      type.renamed_from = aliases_at(fixup.aliases);
      type.left_to_new_build = aliases_at(fixup.left_to_new_build);
      if (fixup.fields != kNone) type.fields = s_.fields.data() + fixup.fields;
      if (fixup.reference_members != kNone) {
        type.reference_members = s_.fields.data() + fixup.reference_members;
      }
      if (fixup.enumerators != kNone) type.enumerators = s_.enumerators.data() + fixup.enumerators;
      if (fixup.alternatives != kNone) {
        type.alternatives = s_.alternatives.data() + fixup.alternatives;
      }
    }
    for (std::size_t r = 0; r < s_.roots.size(); ++r) {
      s_.roots[r].name = base + root_fixups_[r].name;
      s_.roots[r].renamed_from = aliases_at(root_fixups_[r].aliases);
      s_.roots[r].address = nullptr;
    }
    s_.schema.types = s_.types.data();
    s_.schema.type_count = static_cast<std::uint32_t>(s_.types.size());
    s_.schema.roots = s_.roots.data();
    s_.schema.root_count = static_cast<std::uint32_t>(s_.roots.size());
  }

  // The clocks the time fields name, numbered in the byte order of their names (format §3).
  void number_clocks(const char* base) {
    std::vector<const char*> names;
    for (std::size_t offset : time_clock_names_) names.push_back(base + offset);
    std::vector<const char*> distinct = names;
    std::sort(distinct.begin(), distinct.end(),
              [](const char* a, const char* b) { return std::strcmp(a, b) < 0; });
    distinct.erase(std::unique(distinct.begin(), distinct.end(),
                               [](const char* a, const char* b) { return !std::strcmp(a, b); }),
                   distinct.end());
    s_.clocks.clear();
    for (std::size_t c = 0; c < distinct.size(); ++c) {
      s_.clocks.push_back(ClockInfo{distinct[c], nullptr, static_cast<std::uint32_t>(c)});
    }
    for (std::size_t t = 0; t < s_.times.size(); ++t) {
      const auto found =
          std::lower_bound(distinct.begin(), distinct.end(), names[t],
                           [](const char* a, const char* b) { return std::strcmp(a, b) < 0; });
      s_.times[t].clock = &s_.clocks[static_cast<std::size_t>(found - distinct.begin())];
    }
  }

  WireReader in_;
  ParsedSchema::Storage& s_;
  std::vector<std::size_t> time_clock_names_;  // per Storage::times entry: its clock's name
  std::vector<TypeFixup> type_fixups_;
  std::vector<NamedFixup> field_fixups_;
  std::vector<NamedFixup> root_fixups_;
  std::vector<std::size_t> enumerator_names_;
};

}  // namespace

Status parse_schema(const std::uint8_t* data, std::size_t size, ParsedSchema& out,
                    const std::uint64_t* hash) {
  ParsedSchema parsed;
  if (!data && size) return Status(Error::Corrupt, "invalid schema: no bytes");
  Parser parser(data, size, *parsed.storage);
  Status status = parser.run();
  if (!status.ok()) return status;
  parsed.storage->hash = hash != nullptr ? *hash : format::fnv1a64(data, size);
  parsed.storage->bytes.assign(data, data + size);
  out = std::move(parsed);
  return Status();
}

}  // namespace symcr::detail
