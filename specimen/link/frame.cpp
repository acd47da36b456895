#include "frame.hpp"

#include <cstring>

namespace mav {

std::uint16_t crc_x25(const std::uint8_t* data, std::size_t size) {
  std::uint16_t crc = 0xFFFF;
  for (std::size_t i = 0; i < size; ++i) {
    std::uint8_t tmp = data[i] ^ static_cast<std::uint8_t>(crc & 0xFF);
    tmp = static_cast<std::uint8_t>(tmp ^ (tmp << 4));
    crc = static_cast<std::uint16_t>((crc >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4));
  }
  return crc;
}

std::size_t encode(const Frame& frame, std::uint8_t* out) {
  out[0] = kFrameStart;
  out[1] = frame.len;
  out[2] = frame.seq;
  out[3] = frame.sysid;
  out[4] = frame.compid;
  out[5] = frame.msgid;
  std::memcpy(out + kHeaderSize, frame.payload, frame.len);
  const std::uint16_t crc = crc_x25(out + 1, kHeaderSize - 1 + frame.len);
  out[kHeaderSize + frame.len] = static_cast<std::uint8_t>(crc & 0xFF);
  out[kHeaderSize + frame.len + 1] = static_cast<std::uint8_t>(crc >> 8);
  return kHeaderSize + frame.len + kChecksumSize;
}

bool Parser::push(std::uint8_t byte, Frame& out) {
  if (have_ == 0 && byte != kFrameStart) {
    ++errors_;
    return false;
  }
  buffer_[have_++] = byte;
  if (have_ < kHeaderSize) return false;
  const std::size_t total = kHeaderSize + buffer_[1] + kChecksumSize;
  if (have_ < total) return false;
  have_ = 0;
  const std::size_t len = buffer_[1];
  const std::uint16_t expected = crc_x25(buffer_ + 1, kHeaderSize - 1 + len);
  const std::uint16_t got = static_cast<std::uint16_t>(buffer_[kHeaderSize + len] |
                                                       (buffer_[kHeaderSize + len + 1] << 8));
  if (expected != got) {
    ++errors_;
    return false;
  }
  out.len = static_cast<std::uint8_t>(len);
  out.seq = buffer_[2];
  out.sysid = buffer_[3];
  out.compid = buffer_[4];
  out.msgid = buffer_[5];
  std::memcpy(out.payload, buffer_ + kHeaderSize, len);
  return true;
}

}  // namespace mav
