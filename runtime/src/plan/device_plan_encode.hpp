// Device plan images (runtime/device/src/device_plan.hpp): the host's plan of a previous build's
// checkpoints compiled into the ops the device profile executes. symcr-gen embeds one per
// PREVIOUS_SCHEMA of a PROFILE device build; the tests and the fuzzer make their own.
#ifndef SYMCR_SRC_DEVICE_PLAN_ENCODE_HPP
#define SYMCR_SRC_DEVICE_PLAN_ENCODE_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "symcr/generated.hpp"

namespace symcr::detail {

// Plans `writer` (hashing to writer_hash) against `reader` as the host does, and encodes the
// plan for the device into `image`. False when the device cannot carry it out: then `error`
// names the member path (from the writer's root) and the change that fixes it.
bool device_plan_image_for(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                           std::uint64_t reader_hash, std::vector<std::uint8_t>& image,
                           std::string& error);

struct Plan;
// The same for a plan already made (a restore's cached plan, planned or decoded).
bool device_plan_image_of(const Plan& plan, std::uint64_t writer_hash, std::uint64_t reader_hash,
                          std::vector<std::uint8_t>& image, std::string& error);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_DEVICE_PLAN_ENCODE_HPP
