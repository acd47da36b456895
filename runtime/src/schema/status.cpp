// Status: a fixed-size error value (no allocation, usable on the checkpoint path), and the
// names of errors and decisions used in messages, reports and the CLI.
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "payload_error.hpp"
#include "symcr/symcr.hpp"

namespace symcr {

__attribute__((cold)) Status::Status(Error error, const char* format, ...) : error_(error) {
  va_list args;
  va_start(args, format);
  // vsnprintf always NUL-terminates within the buffer and reports, but never writes, the
  // untruncated length: a long message is cut, never overflows, and says that it was cut.
  int written = std::vsnprintf(message_, sizeof message_, format, args);
  va_end(args);
  if (written < 0) message_[0] = '\0';
  if (written >= static_cast<int>(sizeof message_)) {
    std::memcpy(message_ + sizeof message_ - 4, "...", 4);
  }
}

namespace detail {

const Status& set_corrupt_payload(Status& error, const char* format, va_list args) {
  char buffer[200];
  std::vsnprintf(buffer, sizeof buffer, format, args);
  if (error.ok()) error = Status(Error::Corrupt, "invalid payload: %s", buffer);
  return error;
}

}  // namespace detail

const char* error_name(Error error) {
  switch (error) {
    case Error::None:
      return "None";
    case Error::NoSchema:
      return "NoSchema";
    case Error::Io:
      return "Io";
    case Error::NotACheckpoint:
      return "NotACheckpoint";
    case Error::FutureVersion:
      return "FutureVersion";
    case Error::Truncated:
      return "Truncated";
    case Error::Checksum:
      return "Checksum";
    case Error::Corrupt:
      return "Corrupt";
    case Error::SchemaUnknown:
      return "SchemaUnknown";
    case Error::Incompatible:
      return "Incompatible";
    case Error::Strict:
      return "Strict";
    case Error::Unsupported:
      return "Unsupported";
    case Error::NoValidSlot:
      return "NoValidSlot";
    case Error::TooLarge:
      return "TooLarge";
    case Error::Unauthenticated:
      return "Unauthenticated";
    case Error::StoreFull:
      return "StoreFull";
    case Error::RolledBack:
      return "RolledBack";
  }
  return "Unknown";
}

const char* decision_name(Decision decision) {
  switch (decision) {
    case Decision::Restored:
      return "restored";
    case Decision::Kept:
      return "kept";
    case Decision::Dropped:
      return "dropped";
    case Decision::Converted:
      return "converted";
    case Decision::Rejected:
      return "rejected";
    case Decision::Rebased:
      return "rebased";
  }
  return "unknown";
}

}  // namespace symcr
