// Re-encoding strings between UTF-8, UTF-16 and UTF-32 (unicode.hpp).
#include "unicode.hpp"

#include <cstdio>
#include <cstring>

namespace symcr::detail {
namespace {

std::uint32_t load_unit(const std::uint8_t* p, unsigned width) {
  std::uint32_t unit = 0;
  for (unsigned b = 0; b < width; ++b) unit |= std::uint32_t{p[b]} << (8 * b);
  return unit;
}

void append_unit(std::vector<std::uint8_t>& out, std::uint32_t unit, unsigned width) {
  for (unsigned b = 0; b < width; ++b) out.push_back(static_cast<std::uint8_t>(unit >> (8 * b)));
}

bool is_surrogate(std::uint32_t c) { return c >= 0xD800 && c <= 0xDFFF; }

// Decodes one code point starting at unit `i`, advancing `i`. False on invalid input.
bool decode(const std::uint8_t* units, std::uint32_t length, unsigned width, std::uint32_t& i,
            std::uint32_t& code_point) {
  const std::uint32_t first = load_unit(units + std::size_t{i} * width, width);
  if (width == 4) {
    ++i;
    code_point = first;
    return first <= 0x10FFFF && !is_surrogate(first);
  }
  if (width == 2) {
    ++i;
    if (!is_surrogate(first)) {
      code_point = first;
      return true;
    }
    if (first > 0xDBFF || i >= length) return false;  // a low surrogate first, or cut off
    const std::uint32_t second = load_unit(units + std::size_t{i} * 2, 2);
    if (second < 0xDC00 || second > 0xDFFF) return false;
    ++i;
    code_point = 0x10000 + ((first - 0xD800) << 10) + (second - 0xDC00);
    return true;
  }
  // UTF-8: the shortest form only, no surrogates, at most U+10FFFF.
  unsigned extra = 0;
  std::uint32_t minimum = 0;
  if (first < 0x80) {
    ++i;
    code_point = first;
    return true;
  } else if ((first & 0xE0) == 0xC0) {
    extra = 1, minimum = 0x80, code_point = first & 0x1F;
  } else if ((first & 0xF0) == 0xE0) {
    extra = 2, minimum = 0x800, code_point = first & 0x0F;
  } else if ((first & 0xF8) == 0xF0) {
    extra = 3, minimum = 0x10000, code_point = first & 0x07;
  } else {
    return false;
  }
  if (length - i - 1 < extra) return false;
  for (unsigned k = 1; k <= extra; ++k) {
    const std::uint8_t next = units[i + k];
    if ((next & 0xC0) != 0x80) return false;
    code_point = (code_point << 6) | (next & 0x3F);
  }
  i += 1 + extra;
  return code_point >= minimum && code_point <= 0x10FFFF && !is_surrogate(code_point);
}

void encode(std::uint32_t c, unsigned width, std::vector<std::uint8_t>& out, std::uint32_t& count) {
  if (width == 4) {
    append_unit(out, c, 4);
    ++count;
  } else if (width == 2) {
    if (c < 0x10000) {
      append_unit(out, c, 2);
      ++count;
    } else {
      append_unit(out, 0xD800 + ((c - 0x10000) >> 10), 2);
      append_unit(out, 0xDC00 + ((c - 0x10000) & 0x3FF), 2);
      count += 2;
    }
  } else if (c < 0x80) {
    out.push_back(static_cast<std::uint8_t>(c));
    ++count;
  } else if (c < 0x800) {
    out.push_back(static_cast<std::uint8_t>(0xC0 | (c >> 6)));
    out.push_back(static_cast<std::uint8_t>(0x80 | (c & 0x3F)));
    count += 2;
  } else if (c < 0x10000) {
    out.push_back(static_cast<std::uint8_t>(0xE0 | (c >> 12)));
    out.push_back(static_cast<std::uint8_t>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<std::uint8_t>(0x80 | (c & 0x3F)));
    count += 3;
  } else {
    out.push_back(static_cast<std::uint8_t>(0xF0 | (c >> 18)));
    out.push_back(static_cast<std::uint8_t>(0x80 | ((c >> 12) & 0x3F)));
    out.push_back(static_cast<std::uint8_t>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<std::uint8_t>(0x80 | (c & 0x3F)));
    count += 4;
  }
}

}  // namespace

const char* encoding_name(unsigned width) {
  return width == 1 ? "UTF-8" : width == 2 ? "UTF-16" : "UTF-32";
}

bool transcode_string(const std::uint8_t* units, std::uint32_t length, unsigned from_width,
                      unsigned to_width, std::vector<std::uint8_t>& out, std::uint32_t& out_length,
                      char* why, std::size_t why_size) {
  out.clear();
  out_length = 0;
  if ((from_width != 1 && from_width != 2 && from_width != 4) ||
      (to_width != 1 && to_width != 2 && to_width != 4)) {
    std::snprintf(why, why_size, "characters of %u bytes cannot be re-encoded as %u bytes",
                  from_width, to_width);
    return false;
  }
  out.reserve(std::size_t{length} * to_width);
  for (std::uint32_t i = 0; i < length;) {
    const std::uint32_t at = i;
    std::uint32_t code_point = 0;
    if (!decode(units, length, from_width, i, code_point)) {
      std::snprintf(why, why_size, "not valid %s at character %u: cannot be re-encoded as %s",
                    encoding_name(from_width), at, encoding_name(to_width));
      return false;
    }
    encode(code_point, to_width, out, out_length);
  }
  return true;
}

}  // namespace symcr::detail
