// SHA-256 and HMAC-SHA-256 against published test vectors: FIPS 180-2's examples and RFC 4231's
// HMAC-SHA-256 test cases (1-4, 6, 7; 5's truncated output is not used by symcr).
#include "symcr/format/sha256.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using symcr::format::HmacSha256;
using symcr::format::kSha256Size;
using symcr::format::Sha256;

std::string hex(const std::uint8_t (&digest)[symcr::format::kSha256Size]) {
  std::string out;
  char two[3];
  for (std::uint8_t byte : digest) {
    std::snprintf(two, sizeof two, "%02x", byte);
    out += two;
  }
  return out;
}

std::string sha256(const std::string& text) {
  symcr::format::Sha256 hash;
  hash.update(text.data(), text.size());
  std::uint8_t digest[symcr::format::kSha256Size];
  hash.finish(digest);
  return hex(digest);
}

std::string hmac(const std::vector<std::uint8_t>& key, const std::string& data) {
  symcr::format::HmacSha256 mac(key.data(), key.size());
  mac.update(data.data(), data.size());
  std::uint8_t out[symcr::format::kSha256Size];
  mac.finish(out);
  return hex(out);
}

std::vector<std::uint8_t> bytes(std::size_t count, std::uint8_t value) {
  return std::vector<std::uint8_t>(count, value);
}

TEST(Sha256Test, Fips180Examples) {
  EXPECT_EQ(sha256(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256Test, AMillionAsFedInPiecesOfEverySize) {
  symcr::format::Sha256 hash;
  const std::string piece(997, 'a');  // not a divisor of the block size
  std::size_t left = 1000000;
  for (std::size_t step = 1; left != 0; step = step % 997 + 1) {
    const std::size_t take = std::min(step, left);
    hash.update(piece.data(), take);
    left -= take;
  }
  std::uint8_t digest[symcr::format::kSha256Size];
  hash.finish(digest);
  EXPECT_EQ(hex(digest), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(HmacSha256Test, Rfc4231) {
  EXPECT_EQ(hmac(bytes(20, 0x0b), "Hi There"),
            "b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7");
  EXPECT_EQ(hmac({'J', 'e', 'f', 'e'}, "what do ya want for nothing?"),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
  EXPECT_EQ(hmac(bytes(20, 0xaa), std::string(50, '\xdd')),
            "773ea91e36800e46854db8ebd09181a72959098b3ef8c122d9635514ced565fe");
  std::vector<std::uint8_t> counting;
  for (std::uint8_t i = 1; i <= 25; ++i) counting.push_back(i);
  EXPECT_EQ(hmac(counting, std::string(50, '\xcd')),
            "82558a389a443c0ea4cc819899f2083a85f0faa3e578f8077a2e3ff46729665b");
  // Keys longer than a block are hashed first.
  EXPECT_EQ(hmac(bytes(131, 0xaa), "Test Using Larger Than Block-Size Key - Hash Key First"),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54");
  EXPECT_EQ(hmac(bytes(131, 0xaa),
                 "This is a test using a larger than block-size key and a larger than "
                 "block-size data. The key needs to be hashed before being used by the HMAC "
                 "algorithm."),
            "9b09ffa71b942fcb27635fbcd5b0e944bfdc63644f0713938a7f51535c3a35e2");
}

TEST(HmacSha256Test, MacsCompareEqualOnlyWhenEveryByteIs) {
  std::uint8_t a[symcr::format::kSha256Size] = {}, b[symcr::format::kSha256Size] = {};
  EXPECT_TRUE(symcr::format::equal_macs(a, b, symcr::format::kSha256Size));
  b[31] = 1;
  EXPECT_FALSE(symcr::format::equal_macs(a, b, symcr::format::kSha256Size));
}

}  // namespace
