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
// restores it to the same state.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "compact_schema.hpp"
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
