// The check of the plans symcr-gen embeds (PREVIOUS_SCHEMA): linked into every v1, which calls
// it before restoring v0's checkpoint. The embedded image must be, byte for byte, the image of
// the plan this build's runtime makes for the checkpoint's schema, and decoding it must lose
// nothing (re-encoding the decoded plan gives the same bytes). Restore then follows the decoded
// plan, so a pair's value checks hold for the embedded path exactly as for the planned one.
// C++17 with the runtime's internal headers, apart from the programs (some are C++11).
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "engine.hpp"
#include "plan.hpp"
#include "plan_image.hpp"
#include "record.hpp"

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
