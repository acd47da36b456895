// Saving: a schema's roots as a payload (docs/format.md §3). Internal to the runtime; tools and
// tests may include it too.
#ifndef SYMCR_SRC_ENCODE_HPP
#define SYMCR_SRC_ENCODE_HPP

#include <cstdint>
#include <vector>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// Saves every root of `schema` as a payload, replacing `out`'s contents.
// Reuses the capacity of `out` and of internal per-thread scratch: a steady state allocates
// nothing after the first call.
Status encode_payload(const Schema& schema, std::vector<std::uint8_t>& out);

// The payload's CRC-32C, when saving computed it while copying (large flat values).
struct PayloadCrc {
  bool known = false;
  std::uint32_t value = 0;
};
// Same, written at offset `at` of `out` (at most out.size(): a header may come first); `out`
// then ends with the payload. The bytes `out` held past `at` are overwritten, not kept: a
// buffer reused for periodic checkpoints has its large values copied over them in one pass
// with their checksum, not appended behind a zero-fill. Sets `payload_crc` if given.
// `clock_readings`, if given, ends the payload instead of this process's epoch and its clocks'
// readings now (one per schema_clocks(schema), by index).
struct ClockReadings;
Status encode_payload_at(const Schema& schema, std::vector<std::uint8_t>& out, std::size_t at,
                         PayloadCrc* payload_crc = nullptr,
                         const ClockReadings* clock_readings = nullptr);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_ENCODE_HPP
