// Fixed-width little-endian loads and stores: every multi-byte field of symcr's files
// (docs/format.md) is little-endian. Byte by byte, so they hold on any host and alignment.
#ifndef SYMCR_FORMAT_BYTES_HPP
#define SYMCR_FORMAT_BYTES_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace symcr {
namespace format {

inline void store16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void store32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline void store64(std::uint8_t* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline std::uint16_t load16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t load32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline std::uint64_t load64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

// `size` bytes, kMove <= size <= 2 * kMove: the first kMove and the last kMove.
template <std::size_t kMove>
inline void copy_twice(std::uint8_t* to, const std::uint8_t* from, std::size_t size) {
  std::uint8_t head[kMove], tail[kMove];
  std::memcpy(head, from, kMove);
  std::memcpy(tail, from + size - kMove, kMove);
  std::memcpy(to, head, kMove);
  std::memcpy(to + size - kMove, tail, kMove);
}

// Copies `size` bytes between buffers that do not overlap. Up to 32 bytes take two moves
// (overlapping unless the size is a power of two) instead of a call of memcpy, which costs more
// than such a copy: a decoder copies values of a few bytes each.
inline void copy_bytes(std::uint8_t* to, const std::uint8_t* from, std::size_t size) {
  if (size > 32) {
    std::memcpy(to, from, size);
  } else if (size >= 16) {
    copy_twice<16>(to, from, size);
  } else if (size >= 8) {
    copy_twice<8>(to, from, size);
  } else if (size >= 4) {
    copy_twice<4>(to, from, size);
  } else if (size >= 2) {
    copy_twice<2>(to, from, size);
  } else if (size == 1) {
    *to = *from;
  }
}

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_BYTES_HPP
