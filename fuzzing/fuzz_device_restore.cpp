// libFuzzer target (d): a record restored by the device profile (runtime/device) into a test
// program's live state, for the worlds whose every type the device profile holds.
//
// Input: one control byte, then the record bytes.
//   control bits 0-3  the world (among those the device profile holds, fuzz_worlds.hpp)
//   control bit 4     recompute the CRC-32C (and an inline schema's hash) after mutation
//
// Each record is restored through both forms of the world's tables: its TypeInfo tables and the
// compact ones symcr-gen emits for PROFILE device (symcr::DeviceSchema, laid out by
// tests/device/compact_schema.hpp), whose reader is fuzzed as well.
//
// Checked beyond the sanitizers: a refused restore changes nothing; both forms give the same
// result and the same state; an accepted record is also accepted by the host runtime, which
// restores it to the same state; the host's steps of the walk (held_steps()) decode any payload
// as the walk does.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <vector>

#include "compact_schema.hpp"
#include "device_format.hpp"
#include "fuzz_worlds.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"

namespace {

// The worlds whose every type the device profile holds.
const std::vector<unsigned>& device_worlds() {
  static const std::vector<unsigned> kWorlds = [] {
    std::vector<unsigned> held;
    for (unsigned world = 0; world < fuzz::kWorldCount; ++world) {
      if (symcr::device::check_schema(fuzz::world_schema(world)) == symcr::device::Result::Ok) {
        held.push_back(world);
      }
    }
    return held;
  }();
  return kWorlds;
}

// The compact tables of world `world` (one of device_worlds()), made once.
const symcr::Schema& compact_schema(unsigned world) {
  static std::vector<std::unique_ptr<device_tests::CompactSchema>> compact(fuzz::kWorldCount);
  if (!compact[world])
    compact[world].reset(new device_tests::CompactSchema(fuzz::world_schema(world)));
  return compact[world]->schema();
}

[[noreturn]] void fail(const char* what, unsigned world, const char* why = "") {
  std::fprintf(stderr, "symcr fuzz: %s (world %s) %s\n", what, fuzz::world_name(world), why);
  std::abort();
}

// The steps of world `world`'s walk (held_steps()), written once; empty when it has none.
const std::vector<symcr::device::detail::HeldStep>& world_steps(unsigned world) {
  static std::vector<std::vector<symcr::device::detail::HeldStep>> steps(fuzz::kWorldCount);
  static std::vector<bool> written(fuzz::kWorldCount);
  if (!written[world]) {
    const symcr::Schema& schema = fuzz::world_schema(world);
    constexpr std::size_t kLimit = 1 << 16;
    const std::size_t count = symcr::device::detail::held_steps(schema, nullptr, 0, kLimit);
    if (count <= kLimit) {
      steps[world].resize(count);
      symcr::device::detail::held_steps(schema, steps[world].data(), count, kLimit);
    }
    written[world] = true;
  }
  return steps[world];
}

// A host's first restore runs the walk as those steps: over the record's payload as it is
// (its checksum holding or not), the steps decide and stage exactly as the walk does.
void check_steps_against_walk(unsigned world, const std::vector<std::uint8_t>& record) {
  const std::vector<symcr::device::detail::HeldStep>& steps = world_steps(world);
  symcr::format::RecordHeader h;
  if (steps.empty() ||
      symcr::format::decode_record_header(record.data(), record.size(), &h) !=
          symcr::format::HeaderFault::None ||
      std::size_t{h.header_size} + h.schema_size > record.size()) {
    return;
  }
  const std::size_t at = std::size_t{h.header_size} + h.schema_size;
  const std::size_t size = std::min<std::size_t>(h.payload_size, record.size() - at);
  const symcr::Schema& schema = fuzz::world_schema(world);
  const symcr::device::detail::PayloadShape walked = symcr::device::detail::payload_shape(schema);
  symcr::device::detail::PayloadShape stepped = walked;
  stepped.steps = steps.data();
  stepped.step_count = steps.size();
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  symcr::device::Result results[2];
  std::vector<std::uint8_t> states[2];
  for (int form = 0; form < 2; ++form) {
    fuzz::reset_world(world);
    results[form] = symcr::device::detail::restore_held_payload(
        schema, record.data() + at, size, scratch.data(), scratch.size(),
        form == 0 ? &walked : &stepped);
    states[form] = fuzz::world_snapshot(world);
  }
  if (results[0] != results[1]) {
    fail("the walk's steps and the walk restored with different results", world,
         symcr::device::result_text(results[1]));
  }
  if (states[0] != states[1]) fail("the walk's steps and the walk restored different states", world);
  fuzz::reset_world(world);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || device_worlds().empty()) return 0;
  const std::uint8_t control = data[0];
  const unsigned world = device_worlds()[(control & 0x0f) % device_worlds().size()];
  std::vector<std::uint8_t> record(data + 1, data + size);
  if (control & 0x10) fuzz::fix_record_integrity(record.data(), record.size());

  const symcr::Schema& schema = fuzz::world_schema(world);
  const symcr::device::Build build{&schema, symcr::detail::schema_blob(schema).hash};
  fuzz::reset_world(world);
  const std::vector<std::uint8_t> before = fuzz::world_snapshot(world);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  const symcr::device::Result result =
      symcr::device::restore(build, record.data(), record.size(), scratch.data(), scratch.size());
  const std::vector<std::uint8_t> after = fuzz::world_snapshot(world);
  // The compact tables: the same result, the same state.
  fuzz::reset_world(world);
  const symcr::device::Build compact{&compact_schema(world), build.schema_hash};
  const symcr::device::Result compact_result =
      symcr::device::restore(compact, record.data(), record.size(), scratch.data(), scratch.size());
  if (compact_result != result) {
    fail("the compact tables and the TypeInfo tables restored with different results", world,
         symcr::device::result_text(compact_result));
  }
  if (fuzz::world_snapshot(world) != after) {
    fail("the compact tables and the TypeInfo tables restored different states", world);
  }
  check_steps_against_walk(world, record);
  if (result != symcr::device::Result::Ok) {
    if (after != before) fail("a refused device restore modified the live state", world);
    return 0;
  }
  // The host runtime must agree: the same record, the same state.
  fuzz::reset_world(world);
  symcr::detail::RecordView view;
  const symcr::Status parsed = symcr::detail::parse_record(record.data(), record.size(), view);
  if (!parsed.ok()) {
    fail("the device restored a record the host cannot parse", world, parsed.message());
  }
  const symcr::Report report =
      symcr::detail::restore_record(view, schema, build.schema_hash, schema, {});
  if (!report.ok()) {
    fail("the device restored a record the host refuses", world, report.status().message());
  }
  if (fuzz::world_snapshot(world) != after)
    fail("device and host restored different states", world);
  fuzz::reset_world(world);
  return 0;
}
