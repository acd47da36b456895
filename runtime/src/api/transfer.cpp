// In-process state transfer (symcr.hpp, "Live update"): the roots of one loaded build moved
// into the roots of another by the restore's rules, through the payload encoding alone (no
// record header, no file, no checksum: the bytes never leave this call).
#include <cstdint>
#include <vector>

#include "encode.hpp"
#include "record.hpp"
#include "report_access.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "symcr/symcr.hpp"

namespace symcr {
namespace {

// Kept between transfers: the payload needs no allocation once it has been as large.
std::vector<std::uint8_t>& transfer_buffer() {
  thread_local std::vector<std::uint8_t> buffer;
  return buffer;
}

Status check_two_builds(const Schema& from, const Schema& to) {
  if (&from != &to) return Status();
  return Status(Error::Incompatible, "a transfer needs two builds: `from` and `to` are one");
}

}  // namespace

Status prepare_transfer(const Schema& from, const Schema& to) {
  const Status status = check_two_builds(from, to);
  if (status.ok()) detail::prepare_restore(from, detail::schema_blob(from).hash, to, nullptr);
  return status;
}

// The plan is looked up (or built) once, by restore_payload: prepare_transfer is only ahead of it.
Report transfer(const Schema& from, const Schema& to, const RestoreOptions& options) {
  Report report;
  Status status = check_two_builds(from, to);
  if (status.ok()) {
    status = detail::check_program(detail::schema_blob(from).program_id,
                                   detail::schema_blob(to).program_id, to.program,
                                   options.accept_other_program);
  }
  std::vector<std::uint8_t>& payload = transfer_buffer();
  if (status.ok()) status = detail::encode_payload(from, payload);
  if (!status.ok()) {
    detail::ReportAccess::set_status(report, status);
    return report;
  }
  return detail::restore_payload(from, detail::schema_blob(from).hash, payload.data(),
                                 payload.size(), to, options);
}

}  // namespace symcr
