// dry_run_restore: the engine's restore check pass over the whole payload (plan_payload), so
// value-level decisions (a value that does not fit, an unknown enumerator) are reported too.
#include "dry_run.hpp"

#include "report_access.hpp"
#include "restore_payload.hpp"

namespace symcr::cli {

Report dry_run_restore(const LoadedCheckpoint& checkpoint, const Schema& reader, bool strict) {
  RestoreOptions options;
  options.strict = strict;
  Report report =
      detail::plan_payload(*checkpoint.writer, checkpoint.writer_hash, checkpoint.record.payload,
                           checkpoint.record.payload_size, reader, options);
  symcr::detail::ReportAccess::set_sequence(report, checkpoint.record.header.sequence);
  return report;
}

}  // namespace symcr::cli
