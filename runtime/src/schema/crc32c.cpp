// CRC-32C: SSE4.2 `crc32` instruction when the CPU has it (chosen at run time, so the rest of
// the build needs no -msse4.2), else slicing-by-8 tables.
#include "crc32c.hpp"

#include <cstring>

#if defined(__x86_64__)
#include <cpuid.h>
#include <nmmintrin.h>
#include <wmmintrin.h>
#if __has_include(<sys/platform/x86.h>)  // glibc 2.33+: the features ld.so already read
#if defined(__clang__)
// NOLINTNEXTLINE(readability-identifier-naming): C's keyword, which the C header spells
#define _Bool bool  // the header is C: clang's C++ mode has no _Bool, unlike GCC's
#include <sys/platform/x86.h>
#undef _Bool
#else
#include <sys/platform/x86.h>
#endif
#endif
#endif

#include "symcr/format/hashes.hpp"

namespace symcr::detail {
namespace {

constexpr std::uint32_t kPolynomial = format::kCrc32cPolynomial;

// Appending zero bits to a CRC register is linear: a 32x32 GF(2) matrix, one column per
// register bit.
constexpr std::uint32_t gf2_times(const std::uint32_t* matrix, std::uint32_t vector) {
  std::uint32_t sum = 0;
  for (; vector; vector >>= 1, ++matrix) {
    if (vector & 1u) sum ^= *matrix;
  }
  return sum;
}

constexpr void gf2_square(std::uint32_t* square, const std::uint32_t* matrix) {
  for (int n = 0; n < 32; ++n) square[n] = gf2_times(matrix, matrix[n]);
}

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

// Asked of glibc where it can tell: a CPUID instruction traps to the hypervisor in a virtual
// machine, which cost a fresh process tens of microseconds on its first checksum. Else CPUID
// leaf 1, ECX bit 20, read directly: __builtin_cpu_supports would link libgcc's CPU model
// detection (__cpu_indicator_init, about 4.5 KB of .text) into every program.
bool crc32c_hardware_available() {
  static const bool kAvailable = [] {
#if defined(CPU_FEATURE_ACTIVE)
    return CPU_FEATURE_ACTIVE(SSE4_2);
#else
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    return __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_SSE4_2) != 0;
#endif
  }();
  return kAvailable;
}

namespace {

// Carry-less multiplication (PCLMULQDQ), for the folding path below. Asked as above.
bool carryless_multiply_available() {
  static const bool kAvailable = [] {
#if defined(CPU_FEATURE_ACTIVE)
    return CPU_FEATURE_ACTIVE(PCLMULQDQ);
#else
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    return __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_PCLMUL) != 0;
#endif
  }();
  return kAvailable;
}

// Three interleaved crc32 chains (the instruction's latency is 3 cycles, its throughput 1 per
// cycle), combined by shifting one chain's CRC over the bytes the next chain covered: the
// technique of Mark Adler's crc32c.c. Shifting a CRC register over n zero bytes is linear, so
// it is a 32x32 GF(2) matrix, applied here through four 256-entry tables per block length.
constexpr std::size_t kHugeBlock = 65536;  // bytes per chain; powers of two
constexpr std::size_t kLongBlock = 8192;
constexpr std::size_t kShortBlock = 256;

struct ShiftTable {
  std::uint32_t table[4][256];
};

// The operator appending `length` zero bytes (a power of two, at least 1) to a CRC register.
// Computed at compile time: at run time it cost a fresh process tens of microseconds on its
// first checksum.
constexpr ShiftTable make_shift_table(std::size_t length) {
  std::uint32_t odd[32] = {}, even[32] = {};
  odd[0] = kPolynomial;  // one zero bit
  std::uint32_t row = 1;
  for (int n = 1; n < 32; ++n, row <<= 1) odd[n] = row;
  gf2_square(even, odd);  // two zero bits
  gf2_square(odd, even);  // four zero bits
  const std::uint32_t* op = odd;
  // Each squaring doubles the shift: 8 bits after the first, then length bytes.
  for (std::size_t bits = 4;;) {
    gf2_square(even, odd);
    bits *= 2;
    op = even;
    if (bits == length * 8) break;
    gf2_square(odd, even);
    bits *= 2;
    op = odd;
    if (bits == length * 8) break;
  }
  ShiftTable t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    t.table[0][n] = gf2_times(op, n);
    t.table[1][n] = gf2_times(op, n << 8);
    t.table[2][n] = gf2_times(op, n << 16);
    t.table[3][n] = gf2_times(op, n << 24);
  }
  return t;
}

constexpr ShiftTable kHugeBlockShift = make_shift_table(kHugeBlock);
constexpr ShiftTable kLongBlockShift = make_shift_table(kLongBlock);
constexpr ShiftTable kShortBlockShift = make_shift_table(kShortBlock);

inline std::uint32_t shift(const ShiftTable& t, std::uint32_t crc) {
  return t.table[0][crc & 0xFF] ^ t.table[1][(crc >> 8) & 0xFF] ^ t.table[2][(crc >> 16) & 0xFF] ^
         t.table[3][crc >> 24];
}

__attribute__((target("sse4.2"))) inline std::uint64_t load_word(const std::uint8_t* p) {
  std::uint64_t word;
  std::memcpy(&word, p, 8);  // unaligned load; x86 is little-endian
  return word;
}

// `c` is the raw register (not inverted); processes 3 * block bytes of `p`, copying them to `d`
// when kCopy (each word stored as it was loaded and checksummed; with kStream by non-temporal
// stores). No __restrict: with it GCC splits the loop back into a copy followed by a checksum of
// the copy.
template <bool kCopy, bool kStream = false>
__attribute__((target("sse4.2"))) std::uint32_t three_chains(std::uint32_t c, std::uint8_t* d,
                                                             const std::uint8_t* p,
                                                             std::size_t block,
                                                             const ShiftTable& t) {
  std::uint64_t c0 = c, c1 = 0, c2 = 0;
  const std::uint8_t* const end = p + block;
  // Unrolled: the loop's own increment, compare and branch were a third of its instructions.
#pragma GCC unroll 4
  for (; p < end; p += 8, d += kCopy ? 8 : 0) {
    const std::uint64_t w0 = load_word(p), w1 = load_word(p + block), w2 = load_word(p + 2 * block);
    if (kCopy && kStream) {
      _mm_stream_si64(reinterpret_cast<long long*>(d), static_cast<long long>(w0));
      _mm_stream_si64(reinterpret_cast<long long*>(d + block), static_cast<long long>(w1));
      _mm_stream_si64(reinterpret_cast<long long*>(d + 2 * block), static_cast<long long>(w2));
    } else if (kCopy) {
      std::memcpy(d, &w0, 8);
      std::memcpy(d + block, &w1, 8);
      std::memcpy(d + 2 * block, &w2, 8);
    }
    c0 = _mm_crc32_u64(c0, w0);
    c1 = _mm_crc32_u64(c1, w1);
    c2 = _mm_crc32_u64(c2, w2);
  }
  std::uint32_t crc = shift(t, static_cast<std::uint32_t>(c0)) ^ static_cast<std::uint32_t>(c1);
  return shift(t, crc) ^ static_cast<std::uint32_t>(c2);
}

// Folding (Intel's "Fast CRC Computation for Generic Polynomials Using PCLMULQDQ"): four
// 128-bit lanes hold the message read so far, reduced: each step multiplies every lane,
// carry-less, by x^575 and x^511 mod P (its two halves move 512 bits on) and adds the next 64
// bytes, so the lanes stay congruent, modulo P, to the message. At the end the lanes fold into
// one, whose 16 bytes the crc32 instruction reduces. It reads memory as fast as it comes, where
// the crc32 chains are bound by the instruction (a third of memcpy's speed on AMD cores).
//
// The constants, in the bit-reflected order of the crc32 instruction: x^n mod P (P the
// CRC-32C polynomial with its x^32 term), coefficient e at bit 63 - e. A carry-less product of
// two reflected 64-bit values comes out one bit short of the 128-bit lane's order, hence the
// exponents one below the distance: the low half, 64 bits further from the end, by x^(D+63);
// the high half by x^(D-1).
constexpr std::uint64_t x_power_mod_p(unsigned n) {
  std::uint64_t r = 1;
  for (unsigned i = 0; i < n; ++i) {
    r <<= 1;
    if ((r >> 32) != 0) r ^= 0x11EDC6F41u;
  }
  return r;
}
constexpr std::uint64_t reflected(std::uint64_t polynomial) {
  std::uint64_t out = 0;
  for (int e = 0; e < 32; ++e) {
    if (((polynomial >> e) & 1u) != 0) out |= std::uint64_t{1} << (63 - e);
  }
  return out;
}
constexpr std::uint64_t kFold512Low = reflected(x_power_mod_p(512 + 63));
constexpr std::uint64_t kFold512High = reflected(x_power_mod_p(512 - 1));
constexpr std::uint64_t kFold128Low = reflected(x_power_mod_p(128 + 63));
constexpr std::uint64_t kFold128High = reflected(x_power_mod_p(128 - 1));
// Below this many bytes the crc32 chains are as fast.
constexpr std::size_t kFoldingMinimum = 512;

__attribute__((target("sse4.2,pclmul"))) inline __m128i fold(__m128i lane, __m128i constants,
                                                             __m128i next) {
  const __m128i low = _mm_clmulepi64_si128(lane, constants, 0x00);
  const __m128i high = _mm_clmulepi64_si128(lane, constants, 0x11);
  return _mm_xor_si128(_mm_xor_si128(low, high), next);
}

// From this many bytes a copy bypasses the caches (non-temporal stores): a destination that
// large does not stay cached anyway, and writing around the caches saves reading each of its
// lines first, a third of the memory traffic. glibc's memcpy switches near this size too.
constexpr std::size_t kStreamingMinimum = std::size_t{16} << 20;
// Loads and stores whose addresses agree in their low 12 bits look alike to the core at first
// (4K aliasing); a destination up to kAliasingReach bytes past the source, modulo the period,
// makes each load meet the words just stored.
constexpr std::size_t kAliasingPeriod = 4096;
constexpr std::size_t kAliasingReach = 512;

// Folds whole 64-byte blocks of `p` (at least two), copying them to `d` when kCopy (kStream:
// with non-temporal stores, `d` 16-byte aligned), and advances both past them; `state` is the
// raw register (not inverted), as is the result.
template <bool kCopy, bool kStream>
__attribute__((target("sse4.2,pclmul"))) std::uint32_t fold_blocks(std::uint32_t state,
                                                                   std::uint8_t*& d,
                                                                   const std::uint8_t*& p,
                                                                   std::size_t& size) {
  const auto load = [&p](int lane) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p) + lane);
  };
  const auto store = [&d](int lane, __m128i value) {
    if (kCopy && kStream) _mm_stream_si128(reinterpret_cast<__m128i*>(d) + lane, value);
    if (kCopy && !kStream) _mm_storeu_si128(reinterpret_cast<__m128i*>(d) + lane, value);
  };
  __m128i a0 = load(0), a1 = load(1), a2 = load(2), a3 = load(3);
  store(0, a0), store(1, a1), store(2, a2), store(3, a3);
  // The register so far enters as the message's first 32 bits.
  a0 = _mm_xor_si128(a0, _mm_cvtsi32_si128(static_cast<int>(state)));
  p += 64, d += kCopy ? 64 : 0, size -= 64;
  const __m128i by512 =
      _mm_set_epi64x(static_cast<long long>(kFold512High), static_cast<long long>(kFold512Low));
  while (size >= 64) {
    const __m128i b0 = load(0), b1 = load(1), b2 = load(2), b3 = load(3);
    store(0, b0), store(1, b1), store(2, b2), store(3, b3);
    a0 = fold(a0, by512, b0);
    a1 = fold(a1, by512, b1);
    a2 = fold(a2, by512, b2);
    a3 = fold(a3, by512, b3);
    p += 64, d += kCopy ? 64 : 0, size -= 64;
  }
  const __m128i by128 =
      _mm_set_epi64x(static_cast<long long>(kFold128High), static_cast<long long>(kFold128Low));
  a3 = fold(fold(fold(a0, by128, a1), by128, a2), by128, a3);
  std::uint64_t c = _mm_crc32_u64(0, static_cast<std::uint64_t>(_mm_cvtsi128_si64(a3)));
  c = _mm_crc32_u64(c, static_cast<std::uint64_t>(_mm_extract_epi64(a3, 1)));
  return static_cast<std::uint32_t>(c);
}

// Copies the bytes of `p` to `d` one by one, checksumming them into the raw register `c`, until
// `d` is a multiple of `alignment` (a power of two, as streamed stores want); advances all three.
__attribute__((target("sse4.2"))) inline std::uint32_t copy_until_aligned(
    std::uint32_t c, std::uint8_t*& d, const std::uint8_t*& p, std::size_t& size,
    std::uintptr_t alignment) {
  while ((reinterpret_cast<std::uintptr_t>(d) & (alignment - 1)) != 0) {
    *d++ = *p;
    c = _mm_crc32_u8(c, *p++);
    --size;
  }
  return c;
}

// crc32c_extend_hardware, and with kCopy crc32c_copy_hardware: the bytes of `p` copied to `d`.
template <bool kCopy>
__attribute__((target("sse4.2"))) std::uint32_t extend_hardware(std::uint32_t crc, std::uint8_t* d,
                                                                const std::uint8_t* p,
                                                                std::size_t size) {
  std::uint32_t c = ~crc;
  // Measured on an AMD EPYC (Zen 3), 256 MiB: memcpy 19-24 ms (up to 80 ms when the destination
  // lies a little past the source modulo 4 KiB). Copying a destination this large, chains of
  // 64 KiB storing words around the caches: 19-24 ms, but over 1 s in that same position, where
  // each load seems to flush the pending streamed stores it partly matches; folding with 16-byte
  // streamed stores: 31-37 ms in every position. Copying a smaller destination, folding: faster
  // than the chains' three interleaved store streams. Reading only, chains: 16 ms over 64 KiB
  // blocks, 21 ms over 8 KiB ones (folding: 29 ms).
  if (kCopy && size >= kStreamingMinimum) {
    const std::size_t lead =
        (reinterpret_cast<std::uintptr_t>(d) - reinterpret_cast<std::uintptr_t>(p)) &
        (kAliasingPeriod - 1);
    if (lead == 0 || lead >= kAliasingReach || !carryless_multiply_available()) {
      // A streamed store that straddles two cache lines is many times slower: `d` word-aligned.
      c = copy_until_aligned(c, d, p, size, 8);
      while (size >= 3 * kHugeBlock) {
        c = three_chains<kCopy, true>(c, d, p, kHugeBlock, kHugeBlockShift);
        p += 3 * kHugeBlock;
        d += 3 * kHugeBlock;
        size -= 3 * kHugeBlock;
      }
    } else {
      c = copy_until_aligned(c, d, p, size, 16);
      c = fold_blocks<kCopy, true>(c, d, p, size);
    }
    _mm_sfence();  // the streamed stores are ordered before any later store
  } else if (kCopy && size >= kFoldingMinimum && carryless_multiply_available()) {
    c = fold_blocks<kCopy, false>(c, d, p, size);
  }
  if (size >= 3 * kShortBlock) {
    while (!kCopy && size >= 3 * kHugeBlock) {
      c = three_chains<kCopy>(c, d, p, kHugeBlock, kHugeBlockShift);
      p += 3 * kHugeBlock;
      size -= 3 * kHugeBlock;
    }
    while (!kCopy && size >= 3 * kLongBlock) {
      c = three_chains<kCopy>(c, d, p, kLongBlock, kLongBlockShift);
      p += 3 * kLongBlock;
      d += kCopy ? 3 * kLongBlock : 0;
      size -= 3 * kLongBlock;
    }
    while (size >= 3 * kShortBlock) {
      c = three_chains<kCopy>(c, d, p, kShortBlock, kShortBlockShift);
      p += 3 * kShortBlock;
      d += kCopy ? 3 * kShortBlock : 0;
      size -= 3 * kShortBlock;
    }
  }
  std::uint64_t c64 = c;
#pragma GCC unroll 4
  while (size >= 8) {
    const std::uint64_t word = load_word(p);
    if (kCopy) {
      std::memcpy(d, &word, 8);
      d += 8;
    }
    c64 = _mm_crc32_u64(c64, word);
    p += 8;
    size -= 8;
  }
  auto c32 = static_cast<std::uint32_t>(c64);
  while (size-- > 0) {
    if (kCopy) *d++ = *p;
    c32 = _mm_crc32_u8(c32, *p++);
  }
  return ~c32;
}

}  // namespace

std::uint32_t crc32c_extend_hardware(std::uint32_t crc, const void* data, std::size_t size) {
  return extend_hardware<false>(crc, nullptr, static_cast<const std::uint8_t*>(data), size);
}

std::uint32_t crc32c_copy_hardware(std::uint32_t crc, void* destination, const void* source,
                                   std::size_t size) {
  return extend_hardware<true>(crc, static_cast<std::uint8_t*>(destination),
                               static_cast<const std::uint8_t*>(source), size);
}

#else

bool crc32c_hardware_available() { return false; }

std::uint32_t crc32c_extend_hardware(std::uint32_t crc, const void* data, std::size_t size) {
  return crc32c_extend_portable(crc, data, size);
}

std::uint32_t crc32c_copy_hardware(std::uint32_t crc, void* destination, const void* source,
                                   std::size_t size) {
  std::memcpy(destination, source, size);
  return crc32c_extend_portable(crc, destination, size);
}

#endif

// zlib's crc32_combine: the operator for one zero byte, squared once per bit of the length,
// applied to crc_a where the length has a one bit.
std::uint32_t crc32c_combine(std::uint32_t crc_a, std::uint32_t crc_b, std::uint64_t length_b) {
  if (length_b == 0) return crc_a;
  std::uint32_t odd[32], even[32];
  odd[0] = kPolynomial;  // one zero bit
  std::uint32_t row = 1;
  for (int n = 1; n < 32; ++n, row <<= 1) odd[n] = row;
  gf2_square(even, odd);  // two zero bits
  gf2_square(odd, even);  // four zero bits
  do {
    gf2_square(even, odd);  // first: one zero byte
    if (length_b & 1) crc_a = gf2_times(even, crc_a);
    length_b >>= 1;
    if (length_b == 0) break;
    gf2_square(odd, even);
    if (length_b & 1) crc_a = gf2_times(odd, crc_a);
    length_b >>= 1;
  } while (length_b != 0);
  return crc_a ^ crc_b;
}

namespace {

// Polynomials modulo the CRC's, bit-reflected as the register is (bit 31 is x^0): zlib's
// multmodp and x2nmodp. A CRC moves over n bytes by a product with x^(8 n).
constexpr std::uint32_t multiply_modulo(std::uint32_t a, std::uint32_t b) {
  std::uint32_t product = 0;
  for (std::uint32_t m = 1u << 31; m != 0; m >>= 1) {
    if (a & m) product ^= b;
    b = (b & 1u) ? (b >> 1) ^ kPolynomial : b >> 1;
  }
  return product;
}

// x^(2^k) for every k that x^(8 n) of a 64-bit n needs (8 n = 2^3 n).
struct PowerTable {
  std::uint32_t x_to_2_to[3 + 64];
};

constexpr PowerTable make_power_table() {
  PowerTable t{};
  std::uint32_t p = 1u << 30;  // x^1
  t.x_to_2_to[0] = p;
  for (int k = 1; k < 3 + 64; ++k) t.x_to_2_to[k] = p = multiply_modulo(p, p);
  return t;
}

constexpr PowerTable kPowers = make_power_table();

std::uint32_t x_to_8n(std::uint64_t n) {
  std::uint32_t p = 1u << 31;  // x^0
  for (unsigned k = 3; n != 0; n >>= 1, ++k) {
    if (n & 1u) p = multiply_modulo(kPowers.x_to_2_to[k], p);
  }
  return p;
}

}  // namespace

Crc32cSpan crc32c_span(const void* data, std::size_t size) {
  Crc32cSpan span;
  span.crc = crc32c(data, size);
  // The operator's column for register bit i (x^(31 - i)) is x^(8 n) times that power.
  std::uint32_t column[32];
  column[31] = x_to_8n(size);
  for (int i = 30; i >= 0; --i) {
    const std::uint32_t next = column[i + 1];
    column[i] = (next & 1u) ? (next >> 1) ^ kPolynomial : next >> 1;  // times x
  }
  for (int nibble = 0; nibble < 8; ++nibble) {
    for (unsigned value = 1; value < 16; ++value) {
      const unsigned low = static_cast<unsigned>(__builtin_ctz(value));
      span.shift[nibble][value] =
          span.shift[nibble][value & (value - 1)] ^ column[4 * nibble + low];
    }
  }
  return span;
}

// As crc32c_combine: the register moved over the span's bytes as if they were zeros, then
// their own CRC added.
std::uint32_t crc32c_extend_span(std::uint32_t crc, const Crc32cSpan& span) {
  std::uint32_t moved = span.crc;
  for (int nibble = 0; nibble < 8; ++nibble)
    moved ^= span.shift[nibble][(crc >> (4 * nibble)) & 15u];
  return moved;
}

std::uint32_t crc32c_extend(std::uint32_t crc, const void* data, std::size_t size) {
  using Implementation = std::uint32_t (*)(std::uint32_t, const void*, std::size_t);
  static const Implementation kImplementation =
      crc32c_hardware_available() ? &crc32c_extend_hardware : &crc32c_extend_portable;
  return kImplementation(crc, data, size);
}

std::uint32_t crc32c_copy(std::uint32_t crc, void* destination, const void* source,
                          std::size_t size) {
  if (crc32c_hardware_available()) return crc32c_copy_hardware(crc, destination, source, size);
  std::memcpy(destination, source, size);  // the table-driven checksum is far slower than memory
  return crc32c_extend_portable(crc, destination, size);
}

}  // namespace symcr::detail
