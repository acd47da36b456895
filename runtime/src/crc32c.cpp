// CRC-32C: SSE4.2 `crc32` instruction when the CPU has it (chosen at run time, so the rest of
// the build needs no -msse4.2), else slicing-by-8 tables.
#include "crc32c.hpp"

#include <cstring>

#if defined(__x86_64__)
#include <nmmintrin.h>
#endif

namespace symcr::detail {
namespace {

constexpr std::uint32_t kPolynomial = 0x82F63B78u;  // Castagnoli, bit-reflected

struct SlicingTables {
  std::uint32_t table[8][256];
};

constexpr SlicingTables make_tables() {
  SlicingTables t{};
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    std::uint32_t crc = byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ ((crc & 1u) ? kPolynomial : 0u);
    t.table[0][byte] = crc;
  }
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    for (int slice = 1; slice < 8; ++slice) {
      const std::uint32_t prev = t.table[slice - 1][byte];
      t.table[slice][byte] = (prev >> 8) ^ t.table[0][prev & 0xFFu];
    }
  }
  return t;
}

constexpr SlicingTables kTables = make_tables();

std::uint64_t load_le64(const std::uint8_t* p) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | p[i];
  return value;
}

}  // namespace

std::uint32_t crc32c_extend_portable(std::uint32_t crc, const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  std::uint32_t c = ~crc;
  const auto& t = kTables.table;
  while (size >= 8) {
    const std::uint64_t word = load_le64(p) ^ c;
    c = t[7][word & 0xFF] ^ t[6][(word >> 8) & 0xFF] ^ t[5][(word >> 16) & 0xFF] ^
        t[4][(word >> 24) & 0xFF] ^ t[3][(word >> 32) & 0xFF] ^ t[2][(word >> 40) & 0xFF] ^
        t[1][(word >> 48) & 0xFF] ^ t[0][word >> 56];
    p += 8;
    size -= 8;
  }
  while (size-- > 0) c = (c >> 8) ^ t[0][(c ^ *p++) & 0xFF];
  return ~c;
}

#if defined(__x86_64__)

bool crc32c_hardware_available() {
  static const bool available = __builtin_cpu_supports("sse4.2");
  return available;
}

__attribute__((target("sse4.2"))) std::uint32_t crc32c_extend_hardware(std::uint32_t crc,
                                                                        const void* data,
                                                                        std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  std::uint64_t c = ~crc;
  while (size >= 8) {
    std::uint64_t word;
    std::memcpy(&word, p, 8);  // unaligned load; x86 is little-endian
    c = _mm_crc32_u64(c, word);
    p += 8;
    size -= 8;
  }
  auto c32 = static_cast<std::uint32_t>(c);
  while (size-- > 0) c32 = _mm_crc32_u8(c32, *p++);
  return ~c32;
}

#else

bool crc32c_hardware_available() { return false; }

std::uint32_t crc32c_extend_hardware(std::uint32_t crc, const void* data, std::size_t size) {
  return crc32c_extend_portable(crc, data, size);
}

#endif

std::uint32_t crc32c_extend(std::uint32_t crc, const void* data, std::size_t size) {
  using Implementation = std::uint32_t (*)(std::uint32_t, const void*, std::size_t);
  static const Implementation implementation =
      crc32c_hardware_available() ? &crc32c_extend_hardware : &crc32c_extend_portable;
  return implementation(crc, data, size);
}

}  // namespace symcr::detail
