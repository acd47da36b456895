// Internal: SHA-256 (FIPS 180-4) and HMAC-SHA-256 (RFC 2104), for authenticated checkpoints.
// Written here so that the runtime keeps no third-party dependency; checked against the
// published test vectors (tests/runtime/sha256_test.cpp).
#ifndef SYMCR_SRC_SHA256_HPP
#define SYMCR_SRC_SHA256_HPP

#include <cstddef>
#include <cstdint>

namespace symcr::detail {

inline constexpr std::size_t kSha256Size = 32;
inline constexpr std::size_t kSha256BlockSize = 64;

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  void finish(std::uint8_t (&digest)[kSha256Size]);

 private:
  void compress(const std::uint8_t* block);

  std::uint32_t state_[8];
  std::uint8_t buffer_[kSha256BlockSize];
  std::size_t buffered_ = 0;
  std::uint64_t total_ = 0;  // bytes
};

// HMAC-SHA-256 over the concatenation of its update() calls.
class HmacSha256 {
 public:
  HmacSha256(const std::uint8_t* key, std::size_t key_size);
  void update(const void* data, std::size_t size) { inner_.update(data, size); }
  void finish(std::uint8_t (&mac)[kSha256Size]);

 private:
  Sha256 inner_;
  std::uint8_t outer_key_[kSha256BlockSize];
};

// Compares two MACs in time independent of where they differ.
bool equal_macs(const std::uint8_t* a, const std::uint8_t* b, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SHA256_HPP
