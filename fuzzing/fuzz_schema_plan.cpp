// libFuzzer target (b): the schema parser and the resolver/planner with two arbitrary schemas,
// then a payload decoded along the plan.
//
// Input: control byte, u32 length + writer schema bytes, u32 length + reader schema bytes,
// then the payload (docs/format.md §2, §3).
//   control bits 0-3  where the payload is restored: a test program's world (fuzz_worlds.hpp),
//                     or with bit 4 set, a live layout built from the parsed reader schema
//   control bit 5     strict mode
//   control bit 6     the built layout gives every struct a symcr_validate (byte parity)
//   control bit 7     the built layout restores the writer schema into itself (unchanged build)
//
// A parsed schema describes another build's memory, which restore never interprets; to
// restore into a *parsed* reader, the harness lays its types out itself (sizes, offsets,
// alignment computed here, like a compiler would) in an arena, so the reader is as
// trustworthy as generated code. Kinds whose restore needs per-type C++ operations (strings,
// containers, optionals, variants, smart pointers) become empty structs in that layout; the
// test-program worlds cover them with real operations.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_worlds.hpp"
#include "parsed_schema.hpp"
#include "plan.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "visit.hpp"

namespace {

using symcr::Kind;
using symcr::TypeInfo;

constexpr std::uint64_t kMaxTypeSize = 1u << 16;
constexpr std::uint64_t kMaxArena = 1u << 20;

bool parity_validate(const void* object) {
  return (*static_cast<const std::uint8_t*>(object) & 1) == 0;
}

// A reader schema with a layout of our own over the parsed names, kinds and fields.
class BuiltReader {
 public:
  bool build(const symcr::Schema& parsed, bool validators) {
    const std::uint32_t n = parsed.type_count;
    types_.assign(parsed.types, parsed.types + n);
    state_.assign(n, 0);
    fields_.resize(n);
    for (std::uint32_t t = 0; t < n; ++t) {
      if (!layout(t, validators, 0)) return false;
    }
    std::uint64_t arena_size = 0;
    std::vector<std::uint64_t> offsets;
    for (std::uint32_t r = 0; r < parsed.root_count; ++r) {
      const TypeInfo& type = types_[parsed.roots[r].type];
      arena_size = align_up(arena_size, 16);
      offsets.push_back(arena_size);
      arena_size += type.size;
      if (arena_size > kMaxArena) return false;
    }
    arena_.assign(arena_size / 16 + 1, Chunk{});
    roots_.assign(parsed.roots, parsed.roots + parsed.root_count);
    for (std::uint32_t r = 0; r < parsed.root_count; ++r) {
      roots_[r].address = reinterpret_cast<std::uint8_t*>(arena_.data()) + offsets[r];
    }
    schema_ = symcr::Schema{types_.data(), n, roots_.data(), parsed.root_count, nullptr};
    return true;
  }
  const symcr::Schema& schema() const { return schema_; }
  const std::uint8_t* bytes() const { return reinterpret_cast<const std::uint8_t*>(arena_.data()); }
  std::size_t size() const { return arena_.size() * sizeof(Chunk); }

 private:
  struct alignas(16) Chunk {
    std::uint8_t bytes[16] = {};
  };
  static std::uint64_t align_up(std::uint64_t v, std::uint64_t a) { return (v + a - 1) / a * a; }

  // Depth is bounded by the parser's by-value nesting limit; by-value cycles were refused.
  bool layout(std::uint32_t t, bool validators, int depth) {
    if (state_[t] == 2) return true;
    if (state_[t] == 1 || depth > 300) return false;
    state_[t] = 1;
    TypeInfo& type = types_[t];
    type.ops = nullptr;
    type.lifecycle = nullptr;
    type.validate = nullptr;
    switch (type.kind) {
      case Kind::Bool: case Kind::Int: case Kind::UInt: case Kind::Float:
        type.align = std::min<std::uint32_t>(type.size, 16);
        break;
      case Kind::Enum:
        if (type.element >= types_.size() || !layout(type.element, validators, depth + 1)) return false;
        type.size = types_[type.element].size;
        type.align = types_[type.element].align;
        break;
      case Kind::Union:
        type.size = std::max<std::uint32_t>(1, std::min<std::uint32_t>(type.size, kMaxTypeSize));
        type.align = 1;
        break;
      case Kind::Array: {
        if (type.element >= types_.size() || !layout(type.element, validators, depth + 1)) return false;
        const TypeInfo& element = types_[type.element];
        if (element.size && type.count > kMaxTypeSize / element.size) return false;
        type.size = static_cast<std::uint32_t>(type.count * element.size);
        type.align = element.align;
        break;
      }
      case Kind::Pointer:
        type.size = type.align = sizeof(void*);
        break;
      case Kind::Struct: {
        std::vector<symcr::FieldInfo>& fields = fields_[t];
        fields.assign(type.fields, type.fields + type.field_count);
        std::uint64_t offset = 0;
        std::uint32_t align = 1;
        for (symcr::FieldInfo& field : fields) {
          if (field.type >= types_.size() || !layout(field.type, validators, depth + 1)) return false;
          const TypeInfo& ft = types_[field.type];
          offset = align_up(offset, ft.align);
          field.offset = static_cast<std::uint32_t>(offset);
          if (field.bit_width) {
            const std::uint32_t bits = ft.size * 8;
            field.bit_width = static_cast<std::uint16_t>(std::min<std::uint32_t>(field.bit_width, bits));
            if (field.bit_offset + field.bit_width > bits) field.bit_offset = 0;
          }
          offset += ft.size;
          align = std::max(align, ft.align);
          if (offset > kMaxTypeSize) return false;
        }
        type.fields = fields.data();
        type.size = static_cast<std::uint32_t>(std::max<std::uint64_t>(1, align_up(offset, align)));
        type.align = align;
        if (validators) type.validate = &parity_validate;
        break;
      }
      default:
        // Needs C++ operations the harness cannot synthesise: an empty struct of this name.
        type.kind = Kind::Struct;
        type.fields = nullptr;
        type.field_count = 0;
        type.size = 1;
        type.align = 1;
        break;
    }
    if (type.align == 0) type.align = 1;
    state_[t] = 2;
    return true;
  }

  std::vector<TypeInfo> types_;
  std::vector<std::uint8_t> state_;
  std::vector<std::vector<symcr::FieldInfo>> fields_;
  std::vector<symcr::RootInfo> roots_;
  std::vector<Chunk> arena_;
  symcr::Schema schema_{};
};

bool take(const std::uint8_t*& data, std::size_t& size, const std::uint8_t*& out,
          std::size_t& out_size) {
  if (size < 4) return false;
  const std::uint32_t length = symcr::format::load32(data);
  data += 4;
  size -= 4;
  if (length > size) return false;
  out = data;
  out_size = length;
  data += length;
  size -= length;
  return true;
}

[[noreturn]] void fail(const char* what, const symcr::Report& report) {
  std::fprintf(stderr, "symcr fuzz: %s\n%s\n", what, report.to_text().c_str());
  std::abort();
}

// Plans are cached by (writer hash, reader Schema address). The harness's readers live for one
// input and the next may reuse their addresses, which a program's static schema never does:
// a key of its own per input keeps a plan from being served for another reader.
std::uint64_t unique_key() {
  static std::uint64_t next = 0x5eed000000000000ull;
  return ++next;
}

struct NullVisitor : symcr::detail::ValueVisitor {
  void leaf(const char*, const symcr::TypeInfo&, const std::uint8_t*, std::size_t,
            const char*) override {}
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t control = data[0];
  ++data;
  --size;
  const std::uint8_t *writer_bytes = nullptr, *reader_bytes = nullptr;
  std::size_t writer_size = 0, reader_size = 0;
  if (!take(data, size, writer_bytes, writer_size)) return 0;
  const bool have_reader = take(data, size, reader_bytes, reader_size);
  const std::uint8_t* payload = have_reader ? data : nullptr;
  const std::size_t payload_size = have_reader ? size : 0;

  symcr::detail::ParsedSchema writer;
  if (!symcr::detail::parse_schema(writer_bytes, writer_size, writer).ok()) return 0;
  const std::uint64_t writer_hash = symcr::format::fnv1a64(writer_bytes, writer_size);
  NullVisitor visitor;
  (void)symcr::detail::visit_payload(writer.schema(), payload, payload_size, visitor);

  symcr::detail::ParsedSchema reader;
  const bool reader_parsed =
      have_reader && symcr::detail::parse_schema(reader_bytes, reader_size, reader).ok();
  symcr::RestoreOptions options;
  options.strict = (control & 0x20) != 0;

  if (!(control & 0x10)) {
    // Into a test program built with real operations.
    const unsigned world = (control & 0x0f) % fuzz::kWorldCount;
    fuzz::reset_world(world);
    const std::vector<std::uint8_t> before = fuzz::world_snapshot(world);
    const symcr::Report report = symcr::detail::restore_payload(
        writer.schema(), writer_hash, payload, payload_size, fuzz::world_schema(world), options);
    if (!report.ok() && fuzz::world_snapshot(world) != before) {
      fail("a refused restore modified the live state", report);
    }
    if (!fuzz::world_rules_hold(world)) fail("a restored value breaks the reader's rules", report);
    fuzz::reset_world(world);
    // And plan the two arbitrary schemas against each other (names only, no live memory).
    if (reader_parsed) {
      symcr::Status status;
      (void)symcr::detail::plan_for(writer.schema(), unique_key(), reader.schema(), status);
      (void)symcr::detail::plan_for(reader.schema(), unique_key(), writer.schema(), status);
    }
    return 0;
  }

  // Into a live layout of the parsed reader (or of the writer itself: an unchanged build).
  const symcr::Schema& shape = (control & 0x80) || !reader_parsed ? writer.schema() : reader.schema();
  auto built = std::make_unique<BuiltReader>();
  if (!built->build(shape, (control & 0x40) != 0)) return 0;
  const std::vector<std::uint8_t> before(built->bytes(), built->bytes() + built->size());
  const symcr::Report report = symcr::detail::restore_payload(
      writer.schema(), unique_key(), payload, payload_size, built->schema(), options);
  (void)report.to_text();
  if (!report.ok() && std::memcmp(before.data(), built->bytes(), before.size()) != 0) {
    fail("a refused restore modified the live state", report);
  }
  return 0;
}
