// A restore report as the commands that plan or perform a restore print it: one row per
// decision (path, decision, * when lossy, detail), then the counts.
#ifndef SYMCR_CLI_REPORT_TABLE_HPP
#define SYMCR_CLI_REPORT_TABLE_HPP

#include <cstddef>

#include "symcr/symcr.hpp"

namespace symcr::cli {

// Decisions that lose information (ReportEntry::lossy).
std::size_t lossy_count(const Report& report);

// Prints the table and the line "N restored, N converted, ...; N lossy (*)" to stdout.
void print_report_table(const Report& report);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_REPORT_TABLE_HPP
