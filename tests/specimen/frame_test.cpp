#include <gtest/gtest.h>

#include "frame.hpp"
#include "messages.hpp"

namespace {

std::size_t encode_heartbeat(std::uint8_t* bytes, std::uint32_t mode) {
  mav::Heartbeat hb{};
  hb.custom_mode = mode;
  return mav::encode(mav::make_frame(mav::HEARTBEAT, hb), bytes);
}

TEST(Frame, RoundTripsThroughTheParser) {
  std::uint8_t bytes[mav::kMaxFrame];
  const std::size_t size = encode_heartbeat(bytes, 3);
  ASSERT_EQ(size, mav::kHeaderSize + sizeof(mav::Heartbeat) + mav::kChecksumSize);
  mav::Parser parser;
  mav::Frame out;
  for (std::size_t i = 0; i + 1 < size; ++i) EXPECT_FALSE(parser.push(bytes[i], out));
  ASSERT_TRUE(parser.push(bytes[size - 1], out));
  EXPECT_EQ(out.msgid, mav::HEARTBEAT);
  EXPECT_EQ(mav::read_payload<mav::Heartbeat>(out).custom_mode, 3u);
}

TEST(Frame, RejectsACorruptedFrameAndResynchronises) {
  std::uint8_t bytes[2 * mav::kMaxFrame];
  const std::size_t first = encode_heartbeat(bytes, 5);
  bytes[mav::kHeaderSize] ^= 0x01;  // flip a payload bit: checksum must fail
  const std::size_t second = encode_heartbeat(bytes + first, 6);
  mav::Parser parser;
  mav::Frame out;
  int frames = 0;
  std::uint32_t mode = 0;
  for (std::size_t i = 0; i < first + second; ++i) {
    if (parser.push(bytes[i], out)) {
      ++frames;
      mode = mav::read_payload<mav::Heartbeat>(out).custom_mode;
    }
  }
  EXPECT_EQ(frames, 1);
  EXPECT_EQ(mode, 6u);
  EXPECT_GE(parser.errors(), 1u);
}

TEST(Frame, ChecksumIsMavlinksX25) {
  // CRC-16/MCRF4XX check value for "123456789".
  const std::uint8_t digits[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(mav::crc_x25(digits, sizeof(digits)), 0x6F91);
}

TEST(Frame, ShortPayloadIsZeroExtended) {
  mav::Frame frame;
  frame.len = 2;
  frame.payload[0] = 7;
  frame.payload[1] = 0;
  frame.payload[2] = 0xFF;  // beyond len: must not be read
  const auto count = mav::read_payload<mav::MissionCount>(frame);
  EXPECT_EQ(count.count, 7);
  EXPECT_EQ(count.target_system, 0);
}

}  // namespace
