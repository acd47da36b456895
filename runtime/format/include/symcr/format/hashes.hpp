// The checksum and hashes of the format (docs/format.md): CRC-32C, the checksum of records,
// store headers and schema areas; FNV-1a 64, the schema hash; FNV-1a 32, the program id.
#ifndef SYMCR_FORMAT_HASHES_HPP
#define SYMCR_FORMAT_HASHES_HPP

#include <cstddef>
#include <cstdint>

namespace symcr {
namespace format {

// CRC-32C (Castagnoli), bit-reflected.
constexpr std::uint32_t kCrc32cPolynomial = 0x82F63B78u;

// Extends `crc` (the CRC of the bytes before; 0 for none) by `size` bytes, so that
// crc32c(a+b) == crc32c_extend(crc32c(a), b). Four bits at a time through a 16-entry table:
// 64 bytes of flash, at a speed ample for a device's record of a few kilobytes. The host runtime
// computes the same CRC faster (runtime/src/schema/crc32c.hpp); tests compare the two. Never
// inlined: a device calls it from save, restore and the ring, and one copy is the smallest.
__attribute__((noinline)) inline std::uint32_t crc32c_extend_small(std::uint32_t crc,
                                                                   const std::uint8_t* data,
                                                                   std::size_t size) {
  static const std::uint32_t kNibble[16] = {0x00000000u, 0x105EC76Fu, 0x20BD8EDEu, 0x30E349B1u,
                                            0x417B1DBCu, 0x5125DAD3u, 0x61C69362u, 0x7198540Du,
                                            0x82F63B78u, 0x92A8FC17u, 0xA24BB5A6u, 0xB21572C9u,
                                            0xC38D26C4u, 0xD3D3E1ABu, 0xE330A81Au, 0xF36E6F75u};
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    crc = (crc >> 4) ^ kNibble[crc & 15u];
    crc = (crc >> 4) ^ kNibble[crc & 15u];
  }
  return ~crc;
}

// FNV-1a 64 of `size` bytes: a record's schema_hash of its serialised schema.
inline std::uint64_t fnv1a64(const std::uint8_t* data, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

// A record's program_id: FNV-1a 32 of the program's name, never 0; 0 for no name. Never
// inlined: a device's save and restore both call it.
__attribute__((noinline)) inline std::uint32_t program_id(const char* program) {
  if (program == nullptr || *program == '\0') return 0;
  std::uint32_t hash = 2166136261u;
  for (const char* c = program; *c; ++c) {
    hash ^= static_cast<std::uint8_t>(*c);
    hash *= 16777619u;
  }
  return hash == 0 ? 1 : hash;
}

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_HASHES_HPP
