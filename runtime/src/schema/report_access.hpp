// How the runtime and symcr's tools fill a Report: its mutators are private to keep the public
// API read-only for programs. Internal to the runtime; the CLI and tests may include it too.
#ifndef SYMCR_SRC_REPORT_ACCESS_HPP
#define SYMCR_SRC_REPORT_ACCESS_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "symcr/symcr.hpp"

namespace symcr::detail {

// Entries a report shares instead of copying (a cached plan's schema-level entries), written
// by the source when first asked for.
struct ReportSource {
  virtual const std::vector<ReportEntry>& entries() const = 0;

 protected:
  ~ReportSource() = default;
};

struct ReportAccess {
  static void set_status(Report& report, const Status& status) { report.status_ = status; }
  static void set_sequence(Report& report, std::uint64_t sequence) { report.sequence_ = sequence; }
  // Adds an entry (copying shared entries first).
  static void add(Report& report, std::string path, Decision decision, std::string detail,
                  bool lossy);
  // Removes every entry of `decision` (copying shared entries first).
  static void remove(Report& report, Decision decision);
  static std::vector<SkippedCheckpoint>& skipped(Report& report) { return report.skipped_; }
  static void warn(Report& report, std::string warning) {
    report.warnings_.push_back(std::move(warning));
  }
  // Starts an empty report with the entries of `source` (shared, not copied); a later add()
  // copies them first.
  static void set_source(Report& report, std::shared_ptr<const ReportSource> source);
};

}  // namespace symcr::detail

#endif  // SYMCR_SRC_REPORT_ACCESS_HPP
