// MAVLink-v1-style binary frames: the only thing that crosses between the world (physics,
// sensors, ground station) and the autopilot. Both the sensor/actuator link and the
// ground-control link use it.
//
//   0     1    2    3      4       5      6 .. 6+len-1   6+len  7+len
//   0xFE  len  seq  sysid  compid  msgid  payload        crc_lo crc_hi
//
// The checksum is CRC-16/MCRF4XX (MAVLink's X.25) over bytes 1 .. 5+len, as in MAVLink.
#ifndef SPECIMEN_LINK_FRAME_HPP
#define SPECIMEN_LINK_FRAME_HPP

#include <cstddef>
#include <cstdint>

namespace mav {

constexpr std::uint8_t kFrameStart = 0xFE;
constexpr std::size_t kHeaderSize = 6;
constexpr std::size_t kChecksumSize = 2;
constexpr std::size_t kMaxPayload = 255;
constexpr std::size_t kMaxFrame = kHeaderSize + kMaxPayload + kChecksumSize;

struct Frame {
  std::uint8_t seq = 0;
  std::uint8_t sysid = 1;
  std::uint8_t compid = 1;
  std::uint8_t msgid = 0;
  std::uint8_t len = 0;
  std::uint8_t payload[kMaxPayload] = {};
};

std::uint16_t crc_x25(const std::uint8_t* data, std::size_t size);

// Writes the frame into `out` (at least kMaxFrame bytes); returns the encoded size.
std::size_t encode(const Frame& frame, std::uint8_t* out);

// Incremental decoder: feed bytes as they arrive; a complete frame with a valid checksum is
// returned once. Garbage and frames with a bad checksum are skipped (counted in `errors`).
class Parser {
 public:
  // Returns true when `byte` completed a valid frame, now in `out`.
  bool push(std::uint8_t byte, Frame& out);
  std::uint32_t errors() const { return errors_; }

 private:
  std::uint8_t buffer_[kMaxFrame] = {};
  std::size_t have_ = 0;
  std::uint32_t errors_ = 0;
};

}  // namespace mav

#endif  // SPECIMEN_LINK_FRAME_HPP
