// The payload decoders' one error: Corrupt "invalid payload: ...". Internal to the runtime.
#ifndef SYMCR_SRC_PAYLOAD_ERROR_HPP
#define SYMCR_SRC_PAYLOAD_ERROR_HPP

#include <cstdarg>

#include "symcr/symcr.hpp"

namespace symcr::detail {

// Sets `error`, unless it already holds one, to Corrupt "invalid payload: <format...>", and
// returns it. Out of line and cold, so that its message buffer is not in the frames of the
// recursive decoders (their depth is bounded, their frames not).
__attribute__((format(printf, 2, 0), noinline, cold)) const Status& set_corrupt_payload(
    Status& error, const char* format, va_list args);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PAYLOAD_ERROR_HPP
