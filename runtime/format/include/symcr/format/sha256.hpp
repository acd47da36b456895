// SHA-256 (FIPS 180-4) and HMAC-SHA-256 (RFC 2104): the MAC of authenticated records
// (docs/format.md §1) and the digests that bind it. Written here so that symcr keeps no
// third-party dependency; checked against the published test vectors (tests/runtime/
// sha256_test.cpp).
#ifndef SYMCR_FORMAT_SHA256_HPP
#define SYMCR_FORMAT_SHA256_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace symcr {
namespace format {

constexpr std::size_t kSha256Size = 32;
constexpr std::size_t kSha256BlockSize = 64;

class Sha256 {
 public:
  Sha256()
      : state_{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
               0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19},
        buffer_{} {}

  void update(const void* data, std::size_t size) {
    const std::uint8_t* bytes = static_cast<const std::uint8_t*>(data);
    total_ += size;
    if (buffered_ != 0) {
      const std::size_t room = kSha256BlockSize - buffered_;
      const std::size_t take = size < room ? size : room;
      std::memcpy(buffer_ + buffered_, bytes, take);
      buffered_ += take;
      bytes += take;
      size -= take;
      if (buffered_ < kSha256BlockSize) return;
      compress(buffer_);
      buffered_ = 0;
    }
    for (; size >= kSha256BlockSize; bytes += kSha256BlockSize, size -= kSha256BlockSize) {
      compress(bytes);
    }
    if (size != 0) std::memcpy(buffer_, bytes, size);
    buffered_ = size;
  }

  void finish(std::uint8_t (&digest)[kSha256Size]) {
    const std::uint64_t bits = total_ * 8;
    const std::uint8_t one = 0x80;
    update(&one, 1);
    const std::uint8_t zero = 0;
    while (buffered_ != kSha256BlockSize - 8) update(&zero, 1);
    std::uint8_t length[8];
    for (int i = 0; i < 8; ++i) length[i] = static_cast<std::uint8_t>(bits >> (56 - 8 * i));
    update(length, sizeof length);
    for (std::size_t i = 0; i < 8; ++i) store_be32(digest + 4 * i, state_[i]);
  }

 private:
  static std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }
  static std::uint32_t load_be32(const std::uint8_t* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
           std::uint32_t{p[3]};
  }
  static void store_be32(std::uint8_t* p, std::uint32_t v) {
    p[0] = static_cast<std::uint8_t>(v >> 24);
    p[1] = static_cast<std::uint8_t>(v >> 16);
    p[2] = static_cast<std::uint8_t>(v >> 8);
    p[3] = static_cast<std::uint8_t>(v);
  }

  void compress(const std::uint8_t* block) {
    static const std::uint32_t kRound[64] = {
        0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4,
        0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe,
        0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f,
        0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7,
        0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc,
        0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
        0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116,
        0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
        0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
        0xc67178f2};
    std::uint32_t w[64];
    for (std::size_t i = 0; i < 16; ++i) w[i] = load_be32(block + 4 * i);
    for (int i = 16; i < 64; ++i) {
      const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
      const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
      w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    std::uint32_t a = state_[0], b = state_[1], c = state_[2], d = state_[3];
    std::uint32_t e = state_[4], f = state_[5], g = state_[6], h = state_[7];
    for (int i = 0; i < 64; ++i) {
      const std::uint32_t s1 = rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25);
      const std::uint32_t choice = (e & f) ^ (~e & g);
      const std::uint32_t t1 = h + s1 + choice + kRound[i] + w[i];
      const std::uint32_t s0 = rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22);
      const std::uint32_t majority = (a & b) ^ (a & c) ^ (b & c);
      const std::uint32_t t2 = s0 + majority;
      h = g;
      g = f;
      f = e;
      e = d + t1;
      d = c;
      c = b;
      b = a;
      a = t1 + t2;
    }
    state_[0] += a;
    state_[1] += b;
    state_[2] += c;
    state_[3] += d;
    state_[4] += e;
    state_[5] += f;
    state_[6] += g;
    state_[7] += h;
  }

  std::uint32_t state_[8];
  std::uint8_t buffer_[kSha256BlockSize];
  std::size_t buffered_ = 0;
  std::uint64_t total_ = 0;  // bytes
};

// HMAC-SHA-256 over the concatenation of its update() calls.
class HmacSha256 {
 public:
  HmacSha256(const std::uint8_t* key, std::size_t key_size) {
    // A key longer than a block is hashed first (RFC 2104); a shorter one is zero-padded.
    std::uint8_t block_key[kSha256BlockSize] = {};
    if (key_size > kSha256BlockSize) {
      Sha256 hashed;
      hashed.update(key, key_size);
      std::uint8_t digest[kSha256Size];
      hashed.finish(digest);
      std::memcpy(block_key, digest, sizeof digest);
    } else if (key_size != 0) {
      std::memcpy(block_key, key, key_size);
    }
    std::uint8_t inner_key[kSha256BlockSize];
    for (std::size_t i = 0; i < kSha256BlockSize; ++i) {
      inner_key[i] = static_cast<std::uint8_t>(block_key[i] ^ 0x36);
      outer_key_[i] = static_cast<std::uint8_t>(block_key[i] ^ 0x5c);
    }
    inner_.update(inner_key, sizeof inner_key);
  }
  void update(const void* data, std::size_t size) { inner_.update(data, size); }
  void finish(std::uint8_t (&mac)[kSha256Size]) {
    std::uint8_t inner_digest[kSha256Size];
    inner_.finish(inner_digest);
    Sha256 outer;
    outer.update(outer_key_, sizeof outer_key_);
    outer.update(inner_digest, sizeof inner_digest);
    outer.finish(mac);
  }

 private:
  Sha256 inner_;
  std::uint8_t outer_key_[kSha256BlockSize];
};

// Compares two MACs in time independent of where they differ.
inline bool equal_macs(const std::uint8_t* a, const std::uint8_t* b, std::size_t size) {
  std::uint8_t difference = 0;
  for (std::size_t i = 0; i < size; ++i) difference |= static_cast<std::uint8_t>(a[i] ^ b[i]);
  return difference == 0;
}

}  // namespace format
}  // namespace symcr

#endif  // SYMCR_FORMAT_SHA256_HPP
