// Little-endian wire primitives shared by the schema and payload code (docs/format.md).
// The runtime targets little-endian hosts (x86-64, AArch64): wire bytes are host bytes.
#ifndef SYMCR_SRC_WIRE_HPP
#define SYMCR_SRC_WIRE_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "symcr's wire format is little-endian");

namespace symcr::detail {

// Appends fixed-width values to a byte vector.
inline void put_u8(std::vector<std::uint8_t>& out, std::uint8_t value) { out.push_back(value); }
template <typename T>
inline void put_le(std::vector<std::uint8_t>& out, T value) {
  std::uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}
inline void put_u16(std::vector<std::uint8_t>& out, std::uint16_t v) { put_le(out, v); }
inline void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) { put_le(out, v); }
inline void put_u64(std::vector<std::uint8_t>& out, std::uint64_t v) { put_le(out, v); }

// Bounds-checked reading of untrusted bytes: every read either succeeds or returns false and
// leaves the cursor where it was.
class WireReader {
 public:
  WireReader() = default;
  WireReader(const std::uint8_t* data, std::size_t size) : cur_(data), end_(data + size) {}

  std::size_t remaining() const { return static_cast<std::size_t>(end_ - cur_); }
  const std::uint8_t* position() const { return cur_; }
  void seek(const std::uint8_t* position) { cur_ = position; }
  bool at_end() const { return cur_ == end_; }

  template <typename T>
  bool read(T& value) {
    if (remaining() < sizeof(T)) return false;
    std::memcpy(&value, cur_, sizeof(T));
    cur_ += sizeof(T);
    return true;
  }
  bool bytes(std::size_t n, const std::uint8_t*& out) {
    if (remaining() < n) return false;
    out = cur_;
    cur_ += n;
    return true;
  }
  bool skip(std::size_t n) {
    if (remaining() < n) return false;
    cur_ += n;
    return true;
  }

 private:
  const std::uint8_t* cur_ = nullptr;
  const std::uint8_t* end_ = nullptr;
};

}  // namespace symcr::detail

#endif  // SYMCR_SRC_WIRE_HPP
