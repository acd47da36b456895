// symcr::OldValues: a migration hook's read-only view of a checkpointed value (old_values.hpp).
// Fields are found by walking the writer value's payload encoding along the grammar
// (payload_grammar.hpp) from its start, skipping the fields before the one asked for; every
// step is bounded by the view's size and the nesting depth, so a hostile checkpoint can only
// make a query fail.
#include "symcr/old_values.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include "old_values_view.hpp"
#include "payload_grammar.hpp"
#include "scalar.hpp"

namespace symcr {
namespace {

using detail::Number;

bool is_number(Kind kind) {
  return kind == Kind::Bool || kind == Kind::Int || kind == Kind::UInt || kind == Kind::Float ||
         kind == Kind::Enum;
}

// A sink that only measures: walk_value skips fixed-size runs whole.
struct Measure {
  static constexpr bool kEveryValue = false;
  void push(const detail::PathFrame&) {}
  void pop() {}
  void leaf(const TypeInfo&, const std::uint8_t*, std::size_t) {}
  void pointer(const TypeInfo&, const std::uint8_t*, std::uint32_t) {}
  void container(const TypeInfo&, std::uint32_t) {}
};

std::uint32_t read_u32(const std::uint8_t* bytes) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

// The bytes `count` consecutive values of `type` at `bytes` take, within `size`; false when
// the bytes are short or malformed.
bool values_size(const Schema& writer, const detail::WireSizes& sizes, std::uint32_t type,
                 std::uint64_t count, const std::uint8_t* bytes, std::size_t size,
                 std::size_t& out) {
  const std::uint64_t fixed = sizes.fixed[type];
  if (fixed != detail::WireSizes::kVariable) {
    if (fixed != 0 && count > size / fixed) return false;
    out = static_cast<std::size_t>(fixed * count);
    return true;
  }
  Status status;
  detail::PayloadReader in(writer, sizes, status);
  in.start(bytes, size);
  Measure measure;
  // Variable-size values take at least one byte each, so this loop ends within `size` steps.
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!detail::walk_value(in, type, in.object_depth(type), measure)) return false;
  }
  out = static_cast<std::size_t>(in.position() - bytes);
  return true;
}

// Finds the member `field` of the struct value `in`: its own fields first (a base class is a
// field named after its type), then the fields of its bases, nearest first.
bool find_field(const Schema& writer, const detail::WireSizes& sizes, std::uint32_t type,
                const std::uint8_t* bytes, std::size_t size, const char* field, int depth,
                std::uint32_t& out_type, const std::uint8_t*& out_bytes, std::size_t& out_size) {
  const TypeInfo& info = writer.types[type];
  if (info.kind != Kind::Struct || depth > detail::kMaxValueNesting) return false;
  for (int pass = 0; pass < 2; ++pass) {
    std::size_t used = 0;
    for (std::uint32_t f = 0; f < info.field_count; ++f) {
      const FieldInfo& member = info.fields[f];
      std::size_t length = 0;
      if (!values_size(writer, sizes, member.type, 1, bytes + used, size - used, length)) {
        return false;
      }
      if (pass == 0 && member.name && std::strcmp(member.name, field) == 0) {
        out_type = member.type;
        out_bytes = bytes + used;
        out_size = length;
        return true;
      }
      if (pass == 1 && (member.flags & kFieldBase) &&
          find_field(writer, sizes, member.type, bytes + used, length, field, depth + 1, out_type,
                     out_bytes, out_size)) {
        return true;
      }
      used += length;
    }
  }
  return false;
}

bool read_value(const Schema& writer, std::uint32_t type, const std::uint8_t* bytes,
                std::size_t size, Number& out) {
  const TypeInfo& info = writer.types[type];
  if (!is_number(info.kind) || size < info.size) return false;
  if (info.kind == Kind::Enum) {
    if (info.element >= writer.type_count) return false;
    const Kind underlying = writer.types[info.element].kind;
    if (underlying != Kind::Int && underlying != Kind::UInt) return false;
  }
  return detail::read_number(writer, info, bytes, out);
}

// Converts with restore's own rules (detail::convert_number) into a scalar of `kind`/`size`.
bool convert(const Number& in, Kind kind, std::uint32_t size, Number& out) {
  TypeInfo target{};
  target.name = "";
  target.kind = kind;
  target.size = size;
  target.element = kNoType;
  const Schema none{};
  char why[96];
  return detail::convert_number(none, target, in, out, why, sizeof why);
}

// A number read from the payload and converted to a scalar of `kind`/`size`.
bool read_converted(const Schema& writer, std::uint32_t type, const std::uint8_t* bytes,
                    std::size_t size, Kind kind, std::uint32_t kind_size, Number& out) {
  Number in;
  return read_value(writer, type, bytes, size, in) && convert(in, kind, kind_size, out);
}

}  // namespace

OldValues::OldValues(const Schema& writer, const detail::WireSizes& sizes, std::uint32_t type,
                     const std::uint8_t* bytes, std::size_t size) {
  if (type >= writer.type_count || (!bytes && size)) return;
  writer_ = &writer;
  sizes_ = &sizes;
  type_ = type;
  bytes_ = bytes;
  size_ = size;
}

const char* OldValues::type_name() const {
  return writer_ && writer_->types[type_].name ? writer_->types[type_].name : "";
}

bool OldValues::locate(const char* field, Span& out) const {
  if (!writer_) return false;
  if (!field) {
    out = Span{type_, bytes_, size_};
    return true;
  }
  return find_field(*writer_, *sizes_, type_, bytes_, size_, field, 0, out.type, out.bytes,
                    out.size);
}

bool OldValues::has(const char* field) const {
  Span span{};
  return locate(field, span);
}

bool OldValues::get(const char* field, bool& out) const {
  Span span{};
  Number converted;
  if (!locate(field, span) ||
      !read_converted(*writer_, span.type, span.bytes, span.size, Kind::Bool, 1, converted)) {
    return false;
  }
  out = converted.u != 0;
  return true;
}

bool OldValues::get(const char* field, std::int64_t& out) const {
  Span span{};
  Number converted;
  if (!locate(field, span) ||
      !read_converted(*writer_, span.type, span.bytes, span.size, Kind::Int, 8, converted)) {
    return false;
  }
  out = converted.s;
  return true;
}

bool OldValues::get(const char* field, std::uint64_t& out) const {
  Span span{};
  Number converted;
  if (!locate(field, span) ||
      !read_converted(*writer_, span.type, span.bytes, span.size, Kind::UInt, 8, converted)) {
    return false;
  }
  out = converted.u;
  return true;
}

bool OldValues::get(const char* field, double& out) const {
  Span span{};
  Number in;
  if (!locate(field, span) || !read_value(*writer_, span.type, span.bytes, span.size, in)) {
    return false;
  }
  const long double value = in.as_long_double();
  if (std::isfinite(value) && std::fabs(value) > DBL_MAX) return false;  // an x87 extended
  out = static_cast<double>(value);
  return true;
}

bool OldValues::get(const char* field, std::string& out) const {
  Span span{};
  if (!locate(field, span)) return false;
  const TypeInfo& info = writer_->types[span.type];
  if (info.element >= writer_->type_count) return false;
  const TypeInfo& character = writer_->types[info.element];
  const bool bytewise =
      (character.kind == Kind::Int || character.kind == Kind::UInt) && character.size == 1;
  if (!bytewise) return false;
  if (info.kind == Kind::String) {
    // the walk checked the length against the bytes when the field was located.
    const std::uint32_t length = read_u32(span.bytes);
    out.assign(reinterpret_cast<const char*>(span.bytes + 4), length);
    return true;
  }
  if (info.kind == Kind::Array) {
    const auto* chars = reinterpret_cast<const char*>(span.bytes);
    const void* nul = std::memchr(chars, 0, span.size);
    out.assign(chars, nul ? static_cast<const char*>(nul) - chars : span.size);
    return true;
  }
  return false;
}

bool OldValues::enumerator(const char* field, const char*& name) const {
  Span span{};
  Number in;
  if (!locate(field, span) || writer_->types[span.type].kind != Kind::Enum ||
      !read_value(*writer_, span.type, span.bytes, span.size, in)) {
    return false;
  }
  const TypeInfo& info = writer_->types[span.type];
  const std::int64_t value = in.tag == Number::Tag::Signed ? in.s : static_cast<std::int64_t>(in.u);
  for (std::uint32_t e = 0; e < info.enumerator_count; ++e) {
    if (info.enumerators[e].value == value && info.enumerators[e].name) {
      name = info.enumerators[e].name;
      return true;
    }
  }
  return false;
}

OldValues OldValues::child(const char* field) const {
  Span span{};
  if (!locate(field, span)) return OldValues();
  const TypeInfo& info = writer_->types[span.type];
  if (info.kind == Kind::Optional || info.kind == Kind::UniquePtr) {
    // the walk checked the flag and the contained value when the field was located.
    if (span.bytes[0] != 1) return OldValues();
    return OldValues(*writer_, *sizes_, info.element, span.bytes + 1, span.size - 1);
  }
  return OldValues(*writer_, *sizes_, span.type, span.bytes, span.size);
}

std::size_t OldValues::count(const char* field) const {
  Span span{};
  if (!locate(field, span)) return 0;
  const TypeInfo& info = writer_->types[span.type];
  if (info.kind == Kind::Array) return static_cast<std::size_t>(info.count);
  if (info.kind == Kind::Container) return read_u32(span.bytes);
  return 0;
}

OldValues OldValues::element(const char* field, std::size_t index) const {
  Span span{};
  if (!locate(field, span)) return OldValues();
  const TypeInfo& info = writer_->types[span.type];
  const std::uint8_t* first = span.bytes;
  std::size_t size = span.size;
  std::uint64_t count = 0;
  if (info.kind == Kind::Array) {
    count = info.count;
  } else if (info.kind == Kind::Container) {
    count = read_u32(span.bytes);
    first += 4;
    size -= 4;
  } else {
    return OldValues();
  }
  if (index >= count) return OldValues();
  std::size_t before = 0, length = 0;
  if (!values_size(*writer_, *sizes_, info.element, index, first, size, before) ||
      !values_size(*writer_, *sizes_, info.element, 1, first + before, size - before, length)) {
    return OldValues();
  }
  return OldValues(*writer_, *sizes_, info.element, first + before, length);
}

}  // namespace symcr

namespace symcr::detail {

struct OldValuesAccess {
  static OldValues view(const Schema& writer, const WireSizes& sizes, std::uint32_t type,
                        const std::uint8_t* bytes, std::size_t size) {
    return OldValues(writer, sizes, type, bytes, size);
  }
};

OldValues old_values_view(const Schema& writer, const WireSizes& sizes, std::uint32_t type,
                          const std::uint8_t* bytes, std::size_t size) {
  return OldValuesAccess::view(writer, sizes, type, bytes, size);
}

}  // namespace symcr::detail
