// Leaf rendering: integers in decimal, floats in the shortest form that reads back to the same
// bits, enums by enumerator name, strings quoted and escaped, unions as their raw bytes.
#include "values.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include "visit.hpp"

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
    // Over the value bytes only: long double's 10 of its 16.
    const std::size_t value_bytes = sizeof(T) < 10 ? sizeof(T) : 10;
    // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): the same bits are meant (-0 != 0)
    if (std::memcmp(&back, &value, value_bytes) == 0) break;
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
    if (width == 2 && code >= 0xD800 && code < 0xDC00 && i + 2 * std::size_t{width} <= size) {
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
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
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

bool underlying_is_signed(const Schema& writer, const TypeInfo& type) {
  return type.element < writer.type_count && writer.types[type.element].kind == Kind::Int;
}

void render(const Schema& writer, const TypeInfo& type, const std::uint8_t* bytes, std::size_t size,
            const char* text, Value& out) {
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
      const bool is_signed = underlying_is_signed(writer, type);
      const std::int64_t v = is_signed ? load_signed(bytes, size)
                                       : static_cast<std::int64_t>(load_unsigned(bytes, size));
      for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
        if (type.enumerators[e].value == v && type.enumerators[e].name) {
          out.text = type.enumerators[e].name;
          out.json = JsonScalar::of(out.text);
          return;
        }
      }
      if (is_signed)
        std::snprintf(number, sizeof number, "%" PRId64, v);
      else
        std::snprintf(number, sizeof number, "%" PRIu64, static_cast<std::uint64_t>(v));
      out.text = std::string(number) + " (no enumerator)";
      out.json =
          is_signed ? JsonScalar::of_int(v) : JsonScalar::of_uint(static_cast<std::uint64_t>(v));
      return;
    }
    case Kind::String: {
      const std::uint32_t width =
          type.element < writer.type_count ? writer.types[type.element].size : 1;
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

// Counts the leaves only.
class Counter : public detail::ValueVisitor {
 public:
  void leaf(const char*, const TypeInfo&, const std::uint8_t*, std::size_t, const char*) override {
    ++count;
  }
  std::size_t count = 0;
};

}  // namespace

// Keeps each leaf with the frames of its path that no earlier leaf shares: the frames on the
// walker's stack become nodes only when a leaf under them is kept.
class Recorder : public detail::ValueVisitor {
 public:
  Recorder(ValueListing& listing, std::size_t budget) : listing_(listing), budget_(budget) {}

  void enter(const detail::PathFrame& frame) override {
    stack_.push_back({frame, ValueListing::kNoNode});
  }
  void leave() override {
    stack_.pop_back();
    if (kept_ > stack_.size()) kept_ = stack_.size();
  }
  void leaf(const char*, const TypeInfo& type, const std::uint8_t* bytes, std::size_t size,
            const char* text) override {
    if (too_large) return;
    for (; kept_ < stack_.size(); ++kept_) {
      const std::uint32_t parent = kept_ == 0 ? ValueListing::kNoNode : stack_[kept_ - 1].node;
      stack_[kept_].node = static_cast<std::uint32_t>(listing_.nodes_.size());
      listing_.nodes_.push_back({stack_[kept_].frame, parent});
    }
    std::uint32_t target = ValueListing::kNoTarget;
    if (text) {
      // The walker renders each reference's target once and hands out the same text.
      const auto found = targets_.find(text);
      if (found != targets_.end()) {
        target = found->second;
      } else {
        target = static_cast<std::uint32_t>(listing_.targets_.size());
        listing_.targets_.emplace_back(text);
        targets_.emplace(text, target);
        used_ += listing_.targets_.back().size() + sizeof(std::string) + 2 * sizeof(void*);
      }
    }
    listing_.leaves_.push_back(
        {&type, bytes, size, stack_.empty() ? ValueListing::kNoNode : stack_.back().node, target});
    used_ += sizeof(ValueListing::Leaf);
    too_large = used_ + listing_.nodes_.size() * sizeof(ValueListing::Node) > budget_;
  }

  bool too_large = false;

 private:
  struct Open {
    detail::PathFrame frame;
    std::uint32_t node;
  };
  ValueListing& listing_;
  const std::size_t budget_;
  std::size_t used_ = 0;
  std::vector<Open> stack_;
  std::size_t kept_ = 0;  // stack_[0, kept_) are nodes already
  std::unordered_map<const char*, std::uint32_t> targets_;
};

std::size_t listing_budget(std::size_t payload_size) {
  constexpr std::size_t kFloor = std::size_t{64} << 20;
  constexpr std::size_t kPerPayloadByte = 128;
  return payload_size > kFloor / kPerPayloadByte ? payload_size * kPerPayloadByte : kFloor;
}

Status ValueListing::decode(const Schema& writer, const std::uint8_t* payload, std::size_t size) {
  writer_ = &writer;
  nodes_.clear();
  leaves_.clear();
  targets_.clear();
  const std::size_t budget = listing_budget(size);
  Recorder recorder(*this, budget);
  Status status = detail::visit_payload(writer, payload, size, recorder);
  if (status.ok() && recorder.too_large) {
    status = Status(Error::TooLarge,
                    "listing the values would take more than %zu MiB (at most 128 bytes per "
                    "byte of the %zu-byte payload, or 64 MiB)",
                    budget >> 20, size);
  }
  if (!status.ok()) {
    nodes_ = {};
    leaves_ = {};
    targets_ = {};
  }
  return status;
}

void ValueListing::append_path(std::uint32_t node, std::string& out) const {
  // Iterative, not recursive: a path is as deep as the payload nests.
  std::vector<std::uint32_t> chain;
  for (; node != kNoNode; node = nodes_[node].parent) chain.push_back(node);
  for (std::size_t i = chain.size(); i-- > 0;) detail::append_path(out, nodes_[chain[i]].frame);
}

std::string ValueListing::path(std::size_t leaf) const {
  std::string out;
  append_path(leaves_[leaf].node, out);
  return out;
}

std::string ValueListing::text(std::size_t leaf) const {
  const Leaf& l = leaves_[leaf];
  Value value;
  render(*writer_, *l.type, l.bytes, l.size, target_text(l), value);
  return std::move(value.text);
}

Value ValueListing::value(std::size_t leaf) const {
  const Leaf& l = leaves_[leaf];
  Value value;
  value.path = path(leaf);
  value.type = l.type->name ? l.type->name : "?";
  render(*writer_, *l.type, l.bytes, l.size, target_text(l), value);
  return value;
}

Status check_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     std::size_t* leaf_count) {
  Counter counter;
  const Status status = detail::visit_payload(writer, payload, size, counter);
  if (leaf_count) *leaf_count = counter.count;
  return status;
}

}  // namespace symcr::cli
