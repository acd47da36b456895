// libFuzzer target (a): a single-file / in-memory checkpoint (a record with its schema inline,
// docs/format.md §1-§3) restored into a test program's live state.
//
// Input: one control byte, then the record bytes.
//   control bits 0-3  reader world (fuzz_worlds.hpp; seeds use the writer's own world for an
//                     unchanged reader and its patched partner for a different one)
//   control bit 4     recompute the inline schema hash and the CRC-32C after mutation
//   control bit 5     strict mode
//   control bit 6     the reader already holds live heap objects (restore fills them)
//   control bit 7     the reader authenticates checkpoints (fuzz_worlds.hpp's key); with bit 4
//                     an authenticated record is signed again after mutation
//
// Checked beyond the sanitizers: a refused restore changes nothing (the reader re-encodes to
// the same bytes), and no live value breaks the reader's ranges or validators. The decoder the
// CLI uses (visit_payload) runs over the same record.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_worlds.hpp"
#include "parsed_schema.hpp"
#include "visit.hpp"

namespace {

struct NullVisitor : symcr::detail::ValueVisitor {
  std::size_t leaves = 0;
  void leaf(const char*, const symcr::TypeInfo&, const std::uint8_t*, std::size_t,
            const char*) override {
    ++leaves;
  }
};

[[noreturn]] void fail(const char* what, unsigned world, const symcr::Report& report) {
  std::fprintf(stderr, "symcr fuzz: %s (reader %s)\n%s\n", what, fuzz::world_name(world),
               report.to_text().c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t control = data[0];
  const unsigned world = (control & 0x0f) % fuzz::kWorldCount;
  std::vector<std::uint8_t> record(data + 1, data + size);
  fuzz::use_fuzz_key((control & 0x80) != 0);
  if (control & 0x10) fuzz::fix_record_integrity(record.data(), record.size());

  fuzz::reset_world(world);
  if (control & 0x40) fuzz::preset_live_objects(world);
  const std::vector<std::uint8_t> before = fuzz::world_snapshot(world);

  symcr::RestoreOptions options;
  options.strict = (control & 0x20) != 0;
  const symcr::Report report =
      symcr::restore_from_buffer(fuzz::world_schema(world), record.data(), record.size(), options);
  (void)report.to_json();
  if (std::getenv("SYMCR_FUZZ_VERBOSE")) {
    std::fprintf(stderr, "reader %s:\n%s\n", fuzz::world_name(world), report.to_text().c_str());
  }
  if (!report.ok() && fuzz::world_snapshot(world) != before) {
    fail("a refused restore modified the live state", world, report);
  }
  if (!fuzz::world_rules_hold(world)) fail("a restored value breaks the reader's rules", world, report);
  if (report.ok() && options.strict) {
    for (const symcr::ReportEntry& entry : report.entries()) {
      if (entry.lossy) fail("strict mode applied a lossy restore", world, report);
    }
  }
  fuzz::reset_world(world);

  // The reader-less decoder (symcr inspect/diff) over the same bytes.
  symcr::detail::RecordView view;
  if (symcr::detail::parse_record(record.data(), record.size(), view).ok() && view.schema) {
    symcr::detail::ParsedSchema writer;
    if (symcr::detail::parse_schema(view.schema, view.header.schema_size, writer).ok()) {
      NullVisitor visitor;
      (void)symcr::detail::visit_payload(writer.schema(), view.payload, view.payload_size,
                                         visitor);
    }
  }
  return 0;
}
