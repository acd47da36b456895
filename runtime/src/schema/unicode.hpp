// Strings whose character width changes between builds (std::string <-> std::u16string,
// std::u32string, std::wstring) are re-encoded, not copied unit by unit: characters of 1 byte
// are UTF-8, of 2 bytes UTF-16, of 4 bytes UTF-32. Input that is not valid in its encoding is
// refused, never mangled.
#ifndef SYMCR_SRC_UNICODE_HPP
#define SYMCR_SRC_UNICODE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

namespace symcr::detail {

// Transcodes `length` little-endian code units of `from_width` bytes at `units` into code
// units of `to_width` bytes (little-endian) in `out`, replacing its contents; `out_length`
// receives the number of code units written. False, with the reason in `why`, when the input
// is not valid UTF-8/16/32 (a stray byte, an unpaired surrogate, a code point past U+10FFFF).
bool transcode_string(const std::uint8_t* units, std::uint32_t length, unsigned from_width,
                      unsigned to_width, std::vector<std::uint8_t>& out, std::uint32_t& out_length,
                      char* why, std::size_t why_size);

// "UTF-8", "UTF-16" or "UTF-32" for characters of 1, 2 or 4 bytes.
const char* encoding_name(unsigned width);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_UNICODE_HPP
