#include "channel.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace mav {

bool Channel::send(Frame frame) {
  frame.seq = tx_seq_++;
  std::uint8_t bytes[kMaxFrame];
  const std::size_t size = encode(frame, bytes);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      closed_ = true;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

bool Channel::take_buffered(Frame& out) {
  while (rx_pos_ < rx_len_) {
    if (parser_.push(rx_[rx_pos_++], out)) return true;
  }
  return false;
}

bool Channel::receive(Frame& out, int timeout_ms) {
  for (;;) {
    if (take_buffered(out)) return true;
    if (closed_) return false;
    pollfd pfd{fd_, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, timeout_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return false;
    const ssize_t n = ::read(fd_, rx_, sizeof(rx_));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      closed_ = true;
      return false;
    }
    rx_len_ = static_cast<std::size_t>(n);
    rx_pos_ = 0;
  }
}

}  // namespace mav
