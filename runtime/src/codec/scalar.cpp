// Scalar reading, conversion and storing (see scalar.hpp).
#include "scalar.hpp"

#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace symcr::detail {
namespace {

bool is_signed_integer(const Schema& schema, const TypeInfo& type) {
  if (type.kind == Kind::Enum) return schema.types[type.element].kind == Kind::Int;
  return type.kind == Kind::Int;
}

std::int64_t signed_min(unsigned bytes) {
  return bytes >= 8 ? INT64_MIN : -(std::int64_t{1} << (bytes * 8 - 1));
}
std::int64_t signed_max(unsigned bytes) {
  return bytes >= 8 ? INT64_MAX : (std::int64_t{1} << (bytes * 8 - 1)) - 1;
}
std::uint64_t unsigned_max(unsigned bytes) {
  return bytes >= 8 ? UINT64_MAX : (std::uint64_t{1} << (bytes * 8)) - 1;
}

// Integer (tagged signed or unsigned) into an integer of `bytes`, signedness `to_signed`.
bool integer_fits(const Number& in, unsigned bytes, bool to_signed, Number& out) {
  if (to_signed) {
    out.tag = Number::Tag::Signed;
    if (in.tag == Number::Tag::Signed) {
      if (in.s < signed_min(bytes) || in.s > signed_max(bytes)) return false;
      out.s = in.s;
    } else {
      if (in.u > static_cast<std::uint64_t>(signed_max(bytes))) return false;
      out.s = static_cast<std::int64_t>(in.u);
    }
  } else {
    out.tag = Number::Tag::Unsigned;
    if (in.tag == Number::Tag::Signed) {
      if (in.s < 0 || static_cast<std::uint64_t>(in.s) > unsigned_max(bytes)) return false;
      out.u = static_cast<std::uint64_t>(in.s);
    } else {
      if (in.u > unsigned_max(bytes)) return false;
      out.u = in.u;
    }
  }
  return true;
}

}  // namespace

long double Number::as_long_double() const {
  switch (tag) {
    case Tag::Signed:
      return static_cast<long double>(s);
    case Tag::Unsigned:
      return static_cast<long double>(u);
    case Tag::Floating:
      return f;
  }
  return 0;
}

bool read_number(const Schema& schema, const TypeInfo& type, const std::uint8_t* bytes,
                 Number& out) {
  switch (type.kind) {
    case Kind::Bool:
      if (bytes[0] > 1) return false;
      out.tag = Number::Tag::Unsigned;
      out.u = bytes[0];
      return true;
    case Kind::Float:
      out.tag = Number::Tag::Floating;
      if (type.size == 4) {
        float value;
        std::memcpy(&value, bytes, 4);
        out.f = value;
      } else if (type.size == 8) {
        double value;
        std::memcpy(&value, bytes, 8);
        out.f = value;
      } else {
        long double value = 0;
        std::memcpy(&value, bytes, 10);
        out.f = value;
      }
      return true;
    default: {
      std::uint64_t raw = 0;
      std::memcpy(&raw, bytes, type.size > 8 ? 8 : type.size);
      if (is_signed_integer(schema, type)) {
        const unsigned bits = type.size * 8;
        if (bits < 64 && ((raw >> (bits - 1)) & 1u)) raw |= ~((std::uint64_t{1} << bits) - 1);
        out.tag = Number::Tag::Signed;
        out.s = static_cast<std::int64_t>(raw);
      } else {
        out.tag = Number::Tag::Unsigned;
        out.u = raw;
      }
      return true;
    }
  }
}

namespace {

// "<value> <problem> <type>" into `why`; false, for `return refuse(...)`. Only a refusal formats
// the value: printing a number costs far more than converting it.
__attribute__((noinline, cold)) bool refuse(const Number& in, const char* problem,
                                            const char* type_name, char* why,
                                            std::size_t why_size) {
  char text[64];
  format_number(in, text, sizeof text);
  std::snprintf(why, why_size, "%s %s%s%s", text, problem, type_name ? " " : "",
                type_name ? type_name : "");
  return false;
}

}  // namespace

bool convert_number(const Schema& schema, const TypeInfo& type, const Number& in, Number& out,
                    char* why, std::size_t why_size) {
  if (type.kind == Kind::Float) {
    out.tag = Number::Tag::Floating;
    if (in.tag == Number::Tag::Floating) {
      const long double value = in.f;
      if (std::isfinite(value)) {
        const long double limit = type.size == 4 ? FLT_MAX : type.size == 8 ? DBL_MAX : LDBL_MAX;
        if (std::fabs(value) > limit) {
          return refuse(in, "out of range of", type.name, why, why_size);
        }
      }
      out.f = type.size == 4   ? static_cast<float>(value)
              : type.size == 8 ? static_cast<double>(value)
                               : value;
      return true;
    }
    // Integer to floating: only values that survive the round trip exactly.
    const long double exact = in.as_long_double();
    long double stored = exact;
    if (type.size == 4) stored = static_cast<float>(exact);
    if (type.size == 8) stored = static_cast<double>(exact);
    bool round_trips = stored == exact;
    if (round_trips && in.tag == Number::Tag::Signed && stored >= 0x1p63L) round_trips = false;
    if (round_trips && in.tag == Number::Tag::Unsigned && stored >= 0x1p64L) round_trips = false;
    if (!round_trips) {
      return refuse(in, "not exactly representable as", type.name, why, why_size);
    }
    out.f = stored;
    return true;
  }
  const bool to_signed = is_signed_integer(schema, type);
  const unsigned bytes = type.size;
  Number integer = in;
  if (in.tag == Number::Tag::Floating) {
    const long double value = in.f;
    if (!std::isfinite(value) || std::trunc(value) != value) {
      return refuse(in, "is not an integer for", type.name, why, why_size);
    }
    if (value < 0) {
      if (value < -0x1p63L) {
        return refuse(in, "out of range of", type.name, why, why_size);
      }
      integer.tag = Number::Tag::Signed;
      integer.s = static_cast<std::int64_t>(value);
    } else {
      if (value >= 0x1p64L) {
        return refuse(in, "out of range of", type.name, why, why_size);
      }
      integer.tag = Number::Tag::Unsigned;
      integer.u = static_cast<std::uint64_t>(value);
    }
  }
  if (type.kind == Kind::Bool) {
    const bool zero_or_one =
        integer.tag == Number::Tag::Signed ? (integer.s == 0 || integer.s == 1) : integer.u <= 1;
    if (!zero_or_one) {
      return refuse(in, "is not a bool", nullptr, why, why_size);
    }
    out.tag = Number::Tag::Unsigned;
    out.u = integer.tag == Number::Tag::Signed ? static_cast<std::uint64_t>(integer.s) : integer.u;
    return true;
  }
  if (!integer_fits(integer, bytes, to_signed, out)) {
    return refuse(in, "out of range of", type.name, why, why_size);
  }
  if (type.kind == Kind::Enum) {
    const std::int64_t value =
        out.tag == Number::Tag::Signed ? out.s : static_cast<std::int64_t>(out.u);
    for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
      if (type.enumerators[e].value == value) return true;
    }
    return refuse(in, "is not an enumerator of", type.name, why, why_size);
  }
  return true;
}

bool fits_bits(const Number& value, unsigned width, bool is_signed) {
  if (width >= 64) return true;
  if (is_signed) {
    const std::int64_t v =
        value.tag == Number::Tag::Signed ? value.s : static_cast<std::int64_t>(value.u);
    if (value.tag == Number::Tag::Unsigned && value.u > static_cast<std::uint64_t>(INT64_MAX))
      return false;
    const std::int64_t low = -(std::int64_t{1} << (width - 1));
    const std::int64_t high = (std::int64_t{1} << (width - 1)) - 1;
    return v >= low && v <= high;
  }
  if (value.tag == Number::Tag::Signed && value.s < 0) return false;
  const std::uint64_t v =
      value.tag == Number::Tag::Signed ? static_cast<std::uint64_t>(value.s) : value.u;
  return v <= (std::uint64_t{1} << width) - 1;
}

void store_number(const Schema& schema, const TypeInfo& type, const Number& value,
                  std::uint8_t* dst) {
  (void)schema;
  if (type.kind == Kind::Float) {
    if (type.size == 4) {
      const float v = static_cast<float>(value.f);
      std::memcpy(dst, &v, 4);
    } else if (type.size == 8) {
      const double v = static_cast<double>(value.f);
      std::memcpy(dst, &v, 8);
    } else {
      const long double v = value.f;
      std::memcpy(dst, &v, 10);  // the other bytes of the 16 are padding
    }
    return;
  }
  const std::uint64_t raw =
      value.tag == Number::Tag::Signed ? static_cast<std::uint64_t>(value.s) : value.u;
  std::memcpy(dst, &raw, type.size > 8 ? 8 : type.size);
}

void store_bits(std::uint8_t* unit, unsigned bit_offset, unsigned width, const Number& value) {
  const unsigned bytes = (bit_offset + width + 7u) / 8u;
  unsigned __int128 raw = 0;
  std::memcpy(&raw, unit, bytes);
  const unsigned __int128 mask =
      (width >= 64 ? static_cast<unsigned __int128>(~std::uint64_t{0})
                   : static_cast<unsigned __int128>((std::uint64_t{1} << width) - 1))
      << bit_offset;
  const std::uint64_t bits =
      value.tag == Number::Tag::Signed ? static_cast<std::uint64_t>(value.s) : value.u;
  raw = (raw & ~mask) | ((static_cast<unsigned __int128>(bits) << bit_offset) & mask);
  std::memcpy(unit, &raw, bytes);
}

void format_number(const Number& value, char* buffer, std::size_t size) {
  switch (value.tag) {
    case Number::Tag::Signed:
      std::snprintf(buffer, size, "%" PRId64, value.s);
      return;
    case Number::Tag::Unsigned:
      std::snprintf(buffer, size, "%" PRIu64, value.u);
      return;
    case Number::Tag::Floating:
      std::snprintf(buffer, size, "%.17Lg", value.f);
      return;
  }
}

}  // namespace symcr::detail
