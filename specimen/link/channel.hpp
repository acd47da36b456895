// A frame channel over a stream file descriptor (one end of a socketpair).
#ifndef SPECIMEN_LINK_CHANNEL_HPP
#define SPECIMEN_LINK_CHANNEL_HPP

#include "frame.hpp"

namespace mav {

class Channel {
 public:
  Channel() = default;
  explicit Channel(int fd) : fd_(fd) {}
  int fd() const { return fd_; }

  // Sends one frame, stamping the sequence number. False when the peer is gone.
  bool send(Frame frame);
  // Blocks until a frame arrives (or `timeout_ms` passes; -1 = forever). False on timeout or
  // when the peer closed the link.
  bool receive(Frame& out, int timeout_ms);
  // Returns a frame if one is already buffered or readable now, without blocking.
  bool poll(Frame& out) { return receive(out, 0); }
  bool closed() const { return closed_; }

 private:
  bool take_buffered(Frame& out);

  int fd_ = -1;
  std::uint8_t tx_seq_ = 0;
  Parser parser_;
  std::uint8_t rx_[4096] = {};
  std::size_t rx_len_ = 0;
  std::size_t rx_pos_ = 0;
  bool closed_ = false;
};

}  // namespace mav

#endif  // SPECIMEN_LINK_CHANNEL_HPP
