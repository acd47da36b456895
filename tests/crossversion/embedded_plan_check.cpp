// The check of the plans symcr-gen embeds (PREVIOUS_SCHEMA): linked into every v1, which calls
// it before restoring v0's checkpoint. The embedded image must be, byte for byte, the image of
// the plan this build's runtime makes for the checkpoint's schema, and decoding it must lose
// nothing (re-encoding the decoded plan gives the same bytes). Restore then follows the decoded
// plan, so a pair's value checks hold for the embedded path exactly as for the planned one.
// It also restores through the device profile's plan image (xv_restore_through_device_plan).
// C++17 with the runtime's internal headers, apart from the programs (some are C++11).
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "device_plan_encode.hpp"
#include "parsed_schema.hpp"
#include "plan.hpp"
#include "plan_image.hpp"
#include "record.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"

extern "C" int xv_check_embedded_plan(const char* checkpoint) {
  using namespace symcr::detail;
  std::ifstream in(checkpoint, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                        std::istreambuf_iterator<char>()};
  RecordView record;
  ParsedSchema writer;
  if (!parse_record(bytes.data(), bytes.size(), record).ok() || record.schema == nullptr ||
      !parse_schema(record.schema, record.header.schema_size, writer).ok()) {
    std::fprintf(stderr, "embedded plan: %s is not a checkpoint with its schema\n", checkpoint);
    return 1;
  }
  const symcr::Schema& reader = *symcr_program_schema();
  const std::uint64_t reader_hash = schema_blob(reader).hash;
  if (writer.hash() == reader_hash) return 0;  // the same schema: restored without a plan
  std::uint32_t count = 0;
  const symcr::PlannedSchema* plans = symcr_program_plans ? symcr_program_plans(&count) : nullptr;
  const symcr::PlannedSchema* embedded = nullptr;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (plans[i].writer_hash == writer.hash()) embedded = &plans[i];
  }
  if (embedded == nullptr) {
    std::fprintf(stderr, "embedded plan: none for the checkpoint's schema (PREVIOUS_SCHEMA)\n");
    return 1;
  }
  const std::vector<std::uint8_t> image(embedded->image, embedded->image + embedded->size);
  std::vector<std::uint8_t> planned;
  plan_image_for(writer.schema(), writer.hash(), reader, reader_hash, planned);
  int failures = 0;
  if (planned != image) {
    std::fprintf(stderr, "embedded plan: differs from this build's own plan (%zu vs %zu bytes)\n",
                 image.size(), planned.size());
    ++failures;
  }
  Plan decoded;
  decoded.writer = &writer.schema();
  decoded.reader = &reader;
  std::vector<std::uint8_t> again;
  if (!decode_plan_image(image.data(), image.size(), writer.hash(), reader_hash, decoded)) {
    std::fprintf(stderr, "embedded plan: does not decode\n");
    return failures + 1;
  }
  encode_plan_image(decoded, writer.hash(), reader_hash, again);
  if (again != image) {
    std::fprintf(stderr, "embedded plan: decoding it loses something\n");
    ++failures;
  }
  // An image is only ever used for the schemas it was made for.
  Plan other;
  other.writer = &writer.schema();
  other.reader = &reader;
  if (decode_plan_image(image.data(), image.size(), writer.hash() ^ 1, reader_hash, other) ||
      decode_plan_image(image.data(), image.size() - 1, writer.hash(), reader_hash, other)) {
    std::fprintf(stderr, "embedded plan: accepted for another schema, or truncated\n");
    ++failures;
  }
  return failures;
}

// The device profile's cross-version restore, for the pairs whose types it holds: the
// checkpoint (v0's, with its schema inline) restored by the device profile through the device
// plan image symcr-gen would embed for v0's schema (device_plan_encode.hpp). 0 when restored.
extern "C" int xv_restore_through_device_plan(const char* checkpoint) {
  using namespace symcr::detail;
  std::ifstream in(checkpoint, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                        std::istreambuf_iterator<char>()};
  RecordView record;
  ParsedSchema writer;
  if (!parse_record(bytes.data(), bytes.size(), record).ok() || record.schema == nullptr ||
      !parse_schema(record.schema, record.header.schema_size, writer).ok()) {
    std::fprintf(stderr, "device plan: %s is not a checkpoint with its schema\n", checkpoint);
    return 1;
  }
  const symcr::Schema& reader = *symcr_program_schema();
  const std::uint64_t reader_hash = schema_blob(reader).hash;
  std::vector<std::uint8_t> image;
  std::string error;
  if (!device_plan_image_for(writer.schema(), writer.hash(), reader, reader_hash, image, error)) {
    std::fprintf(stderr, "device plan: %s\n", error.c_str());
    return 1;
  }
  const symcr::PlannedSchema planned{writer.hash(), image.data(),
                                     static_cast<std::uint32_t>(image.size())};
  const symcr::device::Build build(&reader, reader_hash, &planned, 1);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(reader));
  const symcr::device::Result result = symcr::device::restore(
      build, bytes.data(), bytes.size(), scratch.data(), scratch.size());
  if (result != symcr::device::Result::Ok) {
    std::fprintf(stderr, "device plan restore: %s\n", symcr::device::result_text(result));
    return 1;
  }
  return 0;
}
