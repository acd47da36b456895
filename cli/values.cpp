// Leaf rendering: integers in decimal, floats in the shortest form that reads back to the same
// bits, enums by enumerator name, strings quoted and escaped, unions as their raw bytes.
#include "values.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "engine.hpp"

namespace symcr::cli {
namespace {

std::uint64_t load_unsigned(const std::uint8_t* bytes, std::size_t size) {
  std::uint64_t value = 0;
  for (std::size_t i = size; i-- > 0;) value = (value << 8) | bytes[i];
  return value;
}

std::int64_t load_signed(const std::uint8_t* bytes, std::size_t size) {
  const std::uint64_t raw = load_unsigned(bytes, size);
  if (size >= 8) return static_cast<std::int64_t>(raw);
  const std::uint64_t sign = std::uint64_t{1} << (8 * size - 1);
  return static_cast<std::int64_t>((raw ^ sign) - sign);
}

// Shortest %g precision that reads back to exactly `value` (so 42.28 prints as 42.28).
template <typename T>
std::string shortest(T value, int max_precision, T (*parse)(const char*, char**),
                     const char* format) {
  if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  char buffer[64];
  int precision = 1;
  for (; precision <= max_precision; ++precision) {
    std::snprintf(buffer, sizeof buffer, format, precision, value);
    const T back = parse(buffer, nullptr);
    if (std::memcmp(&back, &value, sizeof(T) < 10 ? sizeof(T) : 10) == 0) break;
  }
  // %g switches to an exponent when the precision is below the magnitude (100 -> "1e+02"):
  // spell out numbers of moderate magnitude in full instead.
  const int exponent = value == 0 ? 0 : static_cast<int>(std::floor(std::log10(std::fabs(value))));
  if (std::strchr(buffer, 'e') != nullptr && exponent >= precision && exponent < max_precision) {
    std::snprintf(buffer, sizeof buffer, format, exponent + 1, value);
  }
  return buffer;
}

float parse_float(const char* s, char** end) { return std::strtof(s, end); }
double parse_double(const char* s, char** end) { return std::strtod(s, end); }
long double parse_long_double(const char* s, char** end) { return std::strtold(s, end); }

void render_float(const TypeInfo& type, const std::uint8_t* bytes, Value& out) {
  double as_double = 0;
  if (type.size == 4) {
    float f;
    std::memcpy(&f, bytes, 4);
    out.text = shortest<float>(f, 9, parse_float, "%.*g");
    as_double = f;
  } else if (type.size == 8) {
    std::memcpy(&as_double, bytes, 8);
    out.text = shortest<double>(as_double, 17, parse_double, "%.*g");
  } else {
    // x87 extended precision: the low 10 bytes of 16 (docs/format.md §3).
    long double ld = 0;
    static_assert(sizeof(long double) >= 10, "x87 long double");
    std::memcpy(&ld, bytes, 10);
    out.text = shortest<long double>(ld, 21, parse_long_double, "%.*Lg");
    as_double = static_cast<double>(ld);
  }
  out.json = std::isfinite(as_double) ? JsonScalar::of_double(as_double) : JsonScalar::of(out.text);
}

void append_utf8(std::string& out, std::uint32_t code) {
  if (code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) code = 0xFFFD;
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

// The characters of a std::basic_string as UTF-8: 1-byte characters as they are, UTF-16 code
// units with surrogate pairs joined, UTF-32 as code points.
std::string string_contents(const std::uint8_t* bytes, std::size_t size, std::uint32_t width) {
  if (width <= 1) return std::string(reinterpret_cast<const char*>(bytes), size);
  std::string out;
  for (std::size_t i = 0; i + width <= size; i += width) {
    std::uint32_t code = static_cast<std::uint32_t>(load_unsigned(bytes + i, width));
    if (width == 2 && code >= 0xD800 && code < 0xDC00 && i + 2 * width <= size) {
      const auto low = static_cast<std::uint32_t>(load_unsigned(bytes + i + width, width));
      if (low >= 0xDC00 && low < 0xE000) {
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        i += width;
      }
    }
    append_utf8(out, code);
  }
  return out;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (byte < 0x20 || byte == 0x7F) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

class Collector : public detail::ValueVisitor {
 public:
  Collector(const Schema& writer, std::vector<Value>* out) : writer_(writer), out_(out) {}

  void leaf(const char* path, const TypeInfo& type, const std::uint8_t* bytes, std::size_t size,
            const char* text) override {
    if (!out_) return;
    Value value;
    value.path = path;
    value.type = type.name ? type.name : "?";
    render(type, bytes, size, text, value);
    out_->push_back(std::move(value));
  }

 private:
  bool underlying_is_signed(const TypeInfo& type) const {
    return type.element < writer_.type_count && writer_.types[type.element].kind == Kind::Int;
  }

  void render(const TypeInfo& type, const std::uint8_t* bytes, std::size_t size,
              const char* text, Value& out) const {
    char number[32];
    switch (type.kind) {
      case Kind::Bool:
        out.text = bytes[0] ? "true" : "false";
        out.json = JsonScalar::of(bytes[0] != 0);
        return;
      case Kind::Int: {
        const std::int64_t v = load_signed(bytes, size);
        std::snprintf(number, sizeof number, "%" PRId64, v);
        out.text = number;
        out.json = JsonScalar::of_int(v);
        return;
      }
      case Kind::UInt: {
        const std::uint64_t v = load_unsigned(bytes, size);
        std::snprintf(number, sizeof number, "%" PRIu64, v);
        out.text = number;
        out.json = JsonScalar::of_uint(v);
        return;
      }
      case Kind::Float:
        render_float(type, bytes, out);
        return;
      case Kind::Enum: {
        const bool is_signed = underlying_is_signed(type);
        const std::int64_t v = is_signed ? load_signed(bytes, size)
                                         : static_cast<std::int64_t>(load_unsigned(bytes, size));
        for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
          if (type.enumerators[e].value == v && type.enumerators[e].name) {
            out.text = type.enumerators[e].name;
            out.json = JsonScalar::of(out.text);
            return;
          }
        }
        if (is_signed) std::snprintf(number, sizeof number, "%" PRId64, v);
        else std::snprintf(number, sizeof number, "%" PRIu64, static_cast<std::uint64_t>(v));
        out.text = std::string(number) + " (no enumerator)";
        out.json = is_signed ? JsonScalar::of_int(v)
                             : JsonScalar::of_uint(static_cast<std::uint64_t>(v));
        return;
      }
      case Kind::String: {
        const std::uint32_t width =
            type.element < writer_.type_count ? writer_.types[type.element].size : 1;
        std::string contents = string_contents(bytes, size, width);
        out.text = quoted(contents);
        out.json = JsonScalar::of(std::move(contents));
        return;
      }
      case Kind::Pointer:
      case Kind::SharedPtr:
        out.text = text ? text : "?";
        out.json = out.text == "null" ? JsonScalar::null() : JsonScalar::of(out.text);
        return;
      default: {  // Union and anything opaque: raw bytes as written
        std::string hex = "0x";
        for (std::size_t i = 0; i < size; ++i) {
          std::snprintf(number, sizeof number, "%02x", bytes[i]);
          hex += number;
        }
        out.text = "bytes " + hex;
        out.json = JsonScalar::of(hex);
        return;
      }
    }
  }

  const Schema& writer_;
  std::vector<Value>* out_;
};

}  // namespace

Status decode_values(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     std::vector<Value>& out) {
  out.clear();
  Collector collector(writer, &out);
  return detail::visit_payload(writer, payload, size, collector);
}

Status check_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size) {
  Collector discard(writer, nullptr);
  return detail::visit_payload(writer, payload, size, discard);
}

}  // namespace symcr::cli
