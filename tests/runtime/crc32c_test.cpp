// CRC-32C: published vectors (RFC 3720 B.4, and the "123456789" check value), and the
// hardware and portable implementations agreeing at every length and alignment.
#include "crc32c.hpp"

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace {

using symcr::detail::crc32c;
using symcr::detail::crc32c_combine;
using symcr::detail::crc32c_copy;
using symcr::detail::crc32c_copy_hardware;
using symcr::detail::crc32c_extend;
using symcr::detail::crc32c_extend_hardware;
using symcr::detail::crc32c_extend_portable;
using symcr::detail::crc32c_extend_span;
using symcr::detail::crc32c_hardware_available;
using symcr::detail::crc32c_span;

struct Vector {
  std::vector<std::uint8_t> bytes;
  std::uint32_t crc;
};

std::vector<Vector> known_vectors() {
  std::vector<Vector> vectors;
  vectors.push_back({{}, 0x00000000u});
  const char* check = "123456789";
  vectors.push_back({{check, check + 9}, 0xE3069283u});
  vectors.push_back({std::vector<std::uint8_t>(32, 0x00), 0x8A9136AAu});
  vectors.push_back({std::vector<std::uint8_t>(32, 0xFF), 0x62A8AB43u});
  std::vector<std::uint8_t> ascending(32), descending(32);
  for (int i = 0; i < 32; ++i) {
    ascending[i] = static_cast<std::uint8_t>(i);
    descending[i] = static_cast<std::uint8_t>(31 - i);
  }
  vectors.push_back({ascending, 0x46DD794Eu});
  vectors.push_back({descending, 0x113FDB5Cu});
  return vectors;
}

TEST(Crc32c, KnownVectors) {
  for (const Vector& v : known_vectors()) {
    EXPECT_EQ(crc32c(v.bytes.data(), v.bytes.size()), v.crc);
    EXPECT_EQ(crc32c_extend_portable(0, v.bytes.data(), v.bytes.size()), v.crc);
    if (crc32c_hardware_available()) {
      EXPECT_EQ(crc32c_extend_hardware(0, v.bytes.data(), v.bytes.size()), v.crc);
    }
  }
}

TEST(Crc32c, ExtendingEqualsOneCall) {
  const char* text = "The quick brown fox jumps over the lazy dog";
  const std::size_t n = std::strlen(text);
  const std::uint32_t whole = crc32c(text, n);
  for (std::size_t split = 0; split <= n; ++split) {
    EXPECT_EQ(crc32c_extend(crc32c(text, split), text + split, n - split), whole) << split;
  }
}

TEST(Crc32c, CombiningEqualsOneCall) {
  std::mt19937 random(7);
  std::vector<std::uint8_t> bytes(70000);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(random());
  const std::uint32_t whole = crc32c(bytes.data(), bytes.size());
  for (std::size_t split : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{4096},
                            std::size_t{65536}, bytes.size() - 1, bytes.size()}) {
    const std::uint32_t a = crc32c(bytes.data(), split);
    const std::uint32_t b = crc32c(bytes.data() + split, bytes.size() - split);
    EXPECT_EQ(crc32c_combine(a, b, bytes.size() - split), whole) << split;
  }
  EXPECT_EQ(crc32c_combine(0xE3069283u, 0, 0), 0xE3069283u);  // nothing appended
}

// A span's share, added to any CRC before it and extended after it, is the CRC of the whole.
TEST(Crc32c, ExtendingBySpanEqualsReadingTheSpan) {
  std::mt19937 random(11);
  std::vector<std::uint8_t> bytes(20000);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(random());
  for (std::size_t length : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{8},
                             std::size_t{255}, std::size_t{4321}, std::size_t{16384}}) {
    const std::size_t before = 57, after = 1000;
    const std::uint8_t* span_bytes = bytes.data() + before;
    const std::uint32_t whole = crc32c(bytes.data(), before + length + after);
    const std::uint32_t head = crc32c(bytes.data(), before);
    const std::uint32_t through = crc32c_extend_span(head, crc32c_span(span_bytes, length));
    EXPECT_EQ(through, crc32c_extend(head, span_bytes, length)) << length;
    EXPECT_EQ(crc32c_extend(through, span_bytes + length, after), whole) << length;
    EXPECT_EQ(crc32c_extend_span(0, crc32c_span(span_bytes, length)), crc32c(span_bytes, length));
  }
}

TEST(Crc32c, HardwareAndPortableAgreeAtEveryLengthAndAlignment) {
  if (!crc32c_hardware_available()) GTEST_SKIP() << "no SSE4.2 on this CPU";
  std::mt19937 random(20201);
  std::vector<std::uint8_t> data(1024 + 8);
  for (auto& byte : data) byte = static_cast<std::uint8_t>(random());
  for (std::size_t offset = 0; offset < 8; ++offset) {
    for (std::size_t size = 0; size <= 1024; size += (size < 64 ? 1 : 37)) {
      const std::uint32_t seed = static_cast<std::uint32_t>(random());
      ASSERT_EQ(crc32c_extend_hardware(seed, data.data() + offset, size),
                crc32c_extend_portable(seed, data.data() + offset, size))
          << "offset " << offset << " size " << size;
    }
  }
}

// The hardware path runs three interleaved chains over blocks of 3 x 256 and 3 x 8192 bytes
// and combines them: every length around those block boundaries, at every alignment, and as
// extensions of a previous CRC.
TEST(Crc32c, HardwareAndPortableAgreeAroundChainBlockBoundaries) {
  if (!crc32c_hardware_available()) GTEST_SKIP() << "no SSE4.2 on this CPU";
  std::mt19937 random(777);
  // Chains of 256 bytes, 8 KiB and 64 KiB, and their mixes.
  std::vector<std::uint8_t> data(2 * 3 * 65536 + 3 * 8192 + 3 * 256 + 64);
  for (auto& byte : data) byte = static_cast<std::uint8_t>(random());
  std::vector<std::size_t> sizes;
  for (std::size_t base :
       {std::size_t{3 * 256}, std::size_t{2 * 3 * 256}, std::size_t{3 * 8192},
        std::size_t{3 * 8192 + 3 * 256}, std::size_t{2 * 3 * 8192}, std::size_t{3 * 3 * 8192},
        std::size_t{3 * 65536}, std::size_t{3 * 65536 + 3 * 8192 + 3 * 256},
        std::size_t{2 * 3 * 65536}}) {
    for (std::size_t delta = 0; delta <= 17; ++delta) {
      sizes.push_back(base + delta);
      if (base >= delta) sizes.push_back(base - delta);
    }
  }
  for (std::size_t offset = 0; offset < 8; ++offset) {
    for (std::size_t size : sizes) {
      ASSERT_LE(offset + size, data.size());
      const std::uint32_t seed = static_cast<std::uint32_t>(random());
      ASSERT_EQ(crc32c_extend_hardware(seed, data.data() + offset, size),
                crc32c_extend_portable(seed, data.data() + offset, size))
          << "offset " << offset << " size " << size;
    }
  }
  // Split anywhere: extending equals one call across block boundaries.
  const std::size_t n = 2 * 3 * 8192 + 5;
  const std::uint32_t whole = crc32c_extend_portable(0, data.data(), n);
  for (std::size_t split :
       {std::size_t{0}, std::size_t{1}, std::size_t{767}, std::size_t{768}, std::size_t{769},
        std::size_t{24575}, std::size_t{24576}, std::size_t{24577}, n}) {
    EXPECT_EQ(crc32c_extend_hardware(crc32c_extend_hardware(0, data.data(), split),
                                     data.data() + split, n - split),
              whole)
        << split;
  }
}

TEST(Crc32c, DetectsEverySingleBitFlip) {
  std::vector<std::uint8_t> data(300);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7);
  const std::uint32_t clean = crc32c(data.data(), data.size());
  for (std::size_t bit = 0; bit < data.size() * 8; ++bit) {
    data[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    ASSERT_NE(crc32c(data.data(), data.size()), clean) << bit;
    data[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
  }
}

// Copying with the checksum: the destination holds exactly the source's bytes (nothing written
// around them) and the CRC is the one of those bytes, at lengths around the chains' blocks and
// at every alignment of source and destination, through crc32c_copy and its hardware path.
TEST(Crc32c, CopyingChecksumsExactlyTheBytesCopied) {
  std::mt19937 random(4242);
  std::vector<std::uint8_t> source(3 * 3 * 8192 + 3 * 256 + 64);
  for (auto& byte : source) byte = static_cast<std::uint8_t>(random());
  std::vector<std::size_t> sizes = {0, 1, 7, 8, 9, 100};
  for (std::size_t base :
       {std::size_t{3 * 256}, std::size_t{3 * 8192}, std::size_t{3 * 3 * 8192}}) {
    for (std::size_t delta : {std::size_t{0}, std::size_t{1}, std::size_t{8}, std::size_t{13}}) {
      sizes.push_back(base + delta);
      sizes.push_back(base - delta - 1);
    }
  }
  constexpr std::uint8_t kGuard = 0xA5;
  std::vector<std::uint8_t> destination(source.size() + 32);
  for (std::size_t from = 0; from < 8; from += 3) {
    for (std::size_t to = 0; to < 8; to += 5) {
      for (std::size_t size : sizes) {
        ASSERT_LE(from + size, source.size());
        const std::uint32_t seed = static_cast<std::uint32_t>(random());
        const std::uint32_t expected = crc32c_extend_portable(seed, source.data() + from, size);
        for (int hardware = 0; hardware < 2; ++hardware) {
          if (hardware && !crc32c_hardware_available()) continue;
          std::fill(destination.begin(), destination.end(), kGuard);
          const std::uint32_t crc =
              hardware ? crc32c_copy_hardware(seed, destination.data() + 8 + to,
                                              source.data() + from, size)
                       : crc32c_copy(seed, destination.data() + 8 + to, source.data() + from, size);
          ASSERT_EQ(crc, expected) << "size " << size << " from " << from << " to " << to;
          ASSERT_EQ(std::memcmp(destination.data() + 8 + to, source.data() + from, size), 0)
              << "size " << size;
          for (std::size_t i = 0; i < destination.size(); ++i) {
            if (i >= 8 + to && i < 8 + to + size) continue;
            ASSERT_EQ(destination[i], kGuard) << "byte " << i << " written, size " << size;
          }
        }
      }
    }
  }
}

// A copy of 16 MiB or more bypasses the caches, its destination first aligned to 16 bytes by
// single bytes: every misalignment of the destination, an odd length, and nothing written
// around it.
TEST(Crc32c, LargeCopiesBypassingTheCachesChecksumExactlyTheBytesCopied) {
  constexpr std::size_t kSize = (std::size_t{16} << 20) + 77;
  std::mt19937 random(77);
  std::vector<std::uint8_t> source(kSize + 16);
  for (auto& byte : source) byte = static_cast<std::uint8_t>(random());
  constexpr std::uint8_t kGuard = 0x5A;
  constexpr std::size_t kPeriod = 4096;  // the destination's place relative to the source, below
  std::vector<std::uint8_t> destination(kSize + 2 * kPeriod);
  const std::uint8_t* from = source.data() + 3;
  const auto from_address = reinterpret_cast<std::uintptr_t>(from);
  // Copies of this size take one of two streaming paths, chosen by where the destination lies
  // past the source modulo 4 KiB (kPeriod): at 0 or far, word chains; just past, folding. Both,
  // at several alignments of the destination.
  for (std::size_t lead :
       {std::size_t{0}, std::size_t{1}, std::size_t{9}, std::size_t{15}, std::size_t{100},
        std::size_t{511}, std::size_t{512}, std::size_t{2049}, kPeriod - 1}) {
    const auto base = reinterpret_cast<std::uintptr_t>(destination.data()) + kPeriod;
    const std::size_t at = kPeriod + ((from_address + lead - base) & (kPeriod - 1));
    std::uint8_t* into = destination.data() + at;
    ASSERT_EQ((reinterpret_cast<std::uintptr_t>(into) - from_address) & (kPeriod - 1), lead);
    const std::uint32_t seed = static_cast<std::uint32_t>(random());
    const std::uint32_t expected = crc32c_extend_portable(seed, from, kSize);
    std::fill(destination.begin(), destination.end(), kGuard);
    ASSERT_EQ(crc32c_copy(seed, into, from, kSize), expected) << "lead " << lead;
    ASSERT_EQ(std::memcmp(into, from, kSize), 0) << "lead " << lead;
    for (std::size_t i = 0; i < at; ++i) ASSERT_EQ(destination[i], kGuard) << i;
    for (std::size_t i = at + kSize; i < destination.size(); ++i) {
      ASSERT_EQ(destination[i], kGuard) << i;
    }
  }
}

}  // namespace
