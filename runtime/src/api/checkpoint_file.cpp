// Single-file and in-memory checkpoints: one self-contained record (schema inline).
#include <cstdint>
#include <vector>

#include "file_io.hpp"
#include "program_schema.hpp"
#include "record.hpp"
#include "report_access.hpp"
#include "symcr/symcr.hpp"

namespace symcr {
namespace {

// Reused across checkpoints of a thread: a steady state allocates nothing.
std::vector<std::uint8_t>& thread_buffer() {
  thread_local std::vector<std::uint8_t> buffer;
  return buffer;
}

Status with_path(const char* path, const Status& status) {
  return Status(status.error(), "%s: %s", path, status.message());
}

}  // namespace

Status checkpoint_to_buffer(const Schema& schema, std::vector<std::uint8_t>& out,
                            std::uint64_t sequence) {
  return detail::encode_record(schema, /*inline_schema=*/true, sequence, out);
}

Report restore_from_buffer(const Schema& schema, const std::uint8_t* data, std::size_t size,
                           const RestoreOptions& options) {
  return detail::restore_standalone_record(data, size, schema, options);
}

Status checkpoint(const Schema& schema, const char* path, const CheckpointOptions& options) {
  std::vector<std::uint8_t>& buffer = thread_buffer();
  Status status = detail::encode_record(schema, /*inline_schema=*/true, 0, buffer);
  if (!status.ok()) return status;
  return detail::write_file_atomically(path, buffer.data(), buffer.size(), options.durability);
}

Report restore(const Schema& schema, const char* path, const RestoreOptions& options) {
  // A buffer of its own, not the checkpoint one: a restore may run while another thread
  // checkpoints, and restored bytes are not needed afterwards.
  std::vector<std::uint8_t> bytes;
  std::uint64_t trailing = 0;
  Status status = detail::read_record_file(path, bytes, trailing);
  if (!status.ok()) {
    Report report;
    detail::ReportAccess::set_status(report, status);
    return report;
  }
  Report report = detail::restore_standalone_record(bytes.data(), bytes.size(), schema, options);
  if (!report.ok() && report.status().error() != Error::Io) {
    detail::ReportAccess::set_status(report, with_path(path, report.status()));
  }
  return report;
}

Status checkpoint(const char* path, const CheckpointOptions& options) {
  const Schema* schema = nullptr;
  Status status = detail::program_schema(schema);
  if (!status.ok()) return status;
  return checkpoint(*schema, path, options);
}

Report restore(const char* path, const RestoreOptions& options) {
  const Schema* schema = nullptr;
  Status status = detail::program_schema(schema);
  if (!status.ok()) {
    Report report;
    detail::ReportAccess::set_status(report, status);
    return report;
  }
  return restore(*schema, path, options);
}

}  // namespace symcr
