// libFuzzer target (e): a previous build's record restored by the device profile through a
// device plan image (runtime/device/src/device_plan.hpp), for the world pairs (x0 saved, x1
// restores) whose every type the device profile holds and whose plan the device can carry out.
//
// Input: one control byte, a u16 (little-endian) image length and that many image bytes, then
// the record bytes.
//   control bits 0-3  the pair (among those the device holds)
//   control bit 4     recompute the record's CRC-32C (and an inline schema's hash) after mutation
//   control bit 5     restore through the pair's genuine image (symcr-gen's), ignoring the input's
//   control bit 6     (input image) put back the image's header (magic, version, hashes)
//
// Checked beyond the sanitizers: a refused restore changes nothing; with the genuine image, an
// accepted record is also restored by the host runtime to the same state, and no live value
// breaks the reader's rules.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "device_plan.hpp"
#include "device_plan_encode.hpp"
#include "fuzz_worlds.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"

namespace {

struct Pair {
  unsigned writer, reader;
  std::vector<std::uint8_t> image;
};

// The pairs whose worlds the device profile holds, each with the image symcr-gen would embed.
const std::vector<Pair>& device_pairs() {
  static const std::vector<Pair> kPairs = [] {
    std::vector<Pair> held;
    for (unsigned world = 0; world < fuzz::kP; world += 2) {  // x0, x1 pairs
      const symcr::Schema& writer = fuzz::world_schema(world);
      const symcr::Schema& reader = fuzz::world_schema(world + 1);
      if (symcr::device::check_schema(writer) != symcr::device::Result::Ok ||
          symcr::device::check_schema(reader) != symcr::device::Result::Ok) {
        continue;
      }
      Pair pair{world, world + 1, {}};
      std::string error;
      if (symcr::detail::device_plan_image_for(writer, symcr::detail::schema_blob(writer).hash,
                                               reader, symcr::detail::schema_blob(reader).hash,
                                               pair.image, error)) {
        held.push_back(pair);
      }
    }
    return held;
  }();
  return kPairs;
}

[[noreturn]] void fail(const char* what, unsigned world, const char* why = "") {
  std::fprintf(stderr, "symcr fuzz: %s (world %s) %s\n", what, fuzz::world_name(world), why);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3 || device_pairs().empty()) return 0;
  const std::uint8_t control = data[0];
  const Pair& pair = device_pairs()[(control & 0x0f) % device_pairs().size()];
  const std::size_t image_size = std::min<std::size_t>(data[1] | data[2] << 8, size - 3);
  const bool genuine = (control & 0x20) != 0;
  std::vector<std::uint8_t> image =
      genuine ? pair.image : std::vector<std::uint8_t>(data + 3, data + 3 + image_size);
  std::vector<std::uint8_t> record(data + 3 + image_size, data + size);
  if (control & 0x10) fuzz::fix_record_integrity(record.data(), record.size());

  const symcr::Schema& writer = fuzz::world_schema(pair.writer);
  const symcr::Schema& reader = fuzz::world_schema(pair.reader);
  const std::uint64_t writer_hash = symcr::detail::schema_blob(writer).hash;
  const std::uint64_t reader_hash = symcr::detail::schema_blob(reader).hash;
  if (!genuine && (control & 0x40) && image.size() >= symcr::device::plan::kPlanHeaderSize) {
    std::memcpy(image.data(), pair.image.data(), 8);  // magic, version
    std::memcpy(image.data() + 8, &writer_hash, 8);
    std::memcpy(image.data() + 16, &reader_hash, 8);
  }
  const symcr::PlannedSchema planned{writer_hash, image.data(),
                                     static_cast<std::uint32_t>(image.size())};
  const symcr::device::Build build(&reader, reader_hash, &planned, 1);
  fuzz::reset_world(pair.reader);
  const std::vector<std::uint8_t> before = fuzz::world_snapshot(pair.reader);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(reader));
  const symcr::device::Result result =
      symcr::device::restore(build, record.data(), record.size(), scratch.data(), scratch.size());
  const std::vector<std::uint8_t> after = fuzz::world_snapshot(pair.reader);
  if (result != symcr::device::Result::Ok) {
    if (after != before) fail("a refused device restore modified the live state", pair.reader);
    return 0;
  }
  if (!genuine) {  // an image is the build's own data: a damaged one must only stay memory-safe
    fuzz::reset_world(pair.reader);
    return 0;
  }
  if (!fuzz::world_rules_hold(pair.reader)) fail("a live value breaks its rule", pair.reader);
  // The host runtime must agree: the same record, the same state, nothing rejected.
  fuzz::reset_world(pair.reader);
  symcr::detail::RecordView view;
  const symcr::Status parsed = symcr::detail::parse_record(record.data(), record.size(), view);
  if (!parsed.ok()) fail("the device restored a record the host cannot parse", pair.reader);
  const symcr::Report report = symcr::detail::restore_record(view, writer, writer_hash, reader, {});
  if (!report.ok()) {
    fail("the device restored a record the host refuses", pair.reader, report.status().message());
  }
  // A value the host rejects keeps the reader's value there, while the device refuses the whole
  // checkpoint: an accepted record must leave both with the same state.
  if (fuzz::world_snapshot(pair.reader) != after) {
    fail("device and host restored different states", pair.reader);
  }
  fuzz::reset_world(pair.reader);
  return 0;
}
