// CRC-32C (Castagnoli), the checksum of records, store headers and schema areas: the host's
// fast implementations of the format core's CRC (symcr/format/hashes.hpp).
#ifndef SYMCR_SRC_CRC32C_HPP
#define SYMCR_SRC_CRC32C_HPP

#include <cstddef>
#include <cstdint>

namespace symcr::detail {

// Extends `crc` (the CRC of the bytes before; 0 for none) by `size` bytes, so that
// crc32c(a+b) == crc32c_extend(crc32c(a), b). Uses SSE4.2 when the CPU has it.
std::uint32_t crc32c_extend(std::uint32_t crc, const void* data, std::size_t size);
inline std::uint32_t crc32c(const void* data, std::size_t size) {
  return crc32c_extend(0, data, size);
}

// Copies `size` bytes from `source` to `destination` (not overlapping) and extends `crc` by
// them, in one pass: each word is checksummed as it goes from one to the other, so the bytes
// are read once (a copy and then a checksum of data larger than the cache read them twice from
// memory) and the checksum is of exactly the bytes written, whatever writes `source` meanwhile.
std::uint32_t crc32c_copy(std::uint32_t crc, void* destination, const void* source,
                          std::size_t size);

// crc32c(a+b) from crc32c(a), crc32c(b) and b's length: a few dozen 32x32 GF(2) matrix
// squarings (tens of thousands of instructions), worth it only to avoid a pass over megabytes.
std::uint32_t crc32c_combine(std::uint32_t crc_a, std::uint32_t crc_b, std::uint64_t length_b);

// A byte string's share of every CRC-32C that covers it, for bytes checked again and again (a
// schema every standalone record carries inline): crc32c_extend_span(crc, crc32c_span(s, n))
// == crc32c_extend(crc, s, n), without reading the bytes again.
struct Crc32cSpan {
  std::uint32_t crc = 0;  // crc32c of the bytes
  // The operator moving a CRC over n bytes (a product with x^(8 n) modulo the polynomial), by
  // the register's nibbles: eight lookups rather than a 32-step product per use.
  std::uint32_t shift[8][16] = {};
};
Crc32cSpan crc32c_span(const void* data, std::size_t size);
std::uint32_t crc32c_extend_span(std::uint32_t crc, const Crc32cSpan& span);

// The two implementations behind crc32c_extend, exposed so tests can compare them.
std::uint32_t crc32c_extend_portable(std::uint32_t crc, const void* data, std::size_t size);
bool crc32c_hardware_available();
// Only when crc32c_hardware_available().
std::uint32_t crc32c_extend_hardware(std::uint32_t crc, const void* data, std::size_t size);
std::uint32_t crc32c_copy_hardware(std::uint32_t crc, void* destination, const void* source,
                                   std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_CRC32C_HPP
