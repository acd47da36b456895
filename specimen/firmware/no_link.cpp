// The board's links: this firmware flies without a ground station or a simulator, so frames the
// autopilot sends are dropped and none arrive (a flight controller would drive a UART here).
#include "channel.hpp"

namespace mav {

bool Channel::send(Frame frame) {
  (void)frame;
  ++tx_seq_;
  return true;
}

bool Channel::receive(Frame& out, int timeout_ms) {
  (void)out;
  (void)timeout_ms;
  return false;
}

bool Channel::take_buffered(Frame& out) {
  (void)out;
  return false;
}

}  // namespace mav
