// `symcr plan`: the restore report that restoring a checkpoint into a given build would
// produce, computed from the build's schema file without running the build — a gate before
// deploying a patch. Exit 1 when the restore would fail or reject a field, and with --strict
// when any decision is lossy.
#include <string>
#include <vector>

#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "dry_run.hpp"
#include "exit_codes.hpp"
#include "header_fields.hpp"
#include "json_writer.hpp"
#include "record.hpp"
#include "report_table.hpp"
#include "schema_file.hpp"
#include "terminal.hpp"
#include "report_access.hpp"

namespace symcr::cli {

int run_plan(const PlanArgs& args) {
  LoadedCheckpoint checkpoint;
  Status status = load_checkpoint(args.checkpoint, args.slot, checkpoint, args.writer_schema);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  detail::ParsedSchema build;
  std::uint32_t build_program_id = 0;
  status = detail::read_schema_file(resolve_links(args.schema).c_str(), build, &build_program_id);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  Report report;
  const Status program =
      detail::check_program(checkpoint.record.header.program_id, build_program_id,
                            "the build of the schema file", args.accept_other_program);
  if (program.ok()) {
    report = dry_run_restore(checkpoint, build.schema(), args.strict);
  } else {
    symcr::detail::ReportAccess::set_status(report, program);
    symcr::detail::ReportAccess::set_sequence(report, checkpoint.record.header.sequence);
  }
  const std::size_t rejected = report.count(Decision::Rejected);
  const std::size_t lossy = lossy_count(report);
  const bool would_restore = report.ok();
  const int exit_code = would_restore && rejected == 0 ? kExitOk : kExitFinding;

  const std::string build_text = args.schema + " (schema " + hex64(build.hash()) + ", " +
                                 std::to_string(build.schema().type_count) + " types, " +
                                 std::to_string(build.schema().root_count) + " roots)";
  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("checkpoint", args.checkpoint);
    if (checkpoint.from_store) json.field("slot", checkpoint.slot);
    json.field("checkpoint_schema", hex64(checkpoint.writer_hash));
    json.field("build_schema_file", args.schema);
    json.field("build_schema", hex64(build.hash()));
    json.field("strict", args.strict);
    json.field("would_restore", would_restore);
    json.field("rejected", static_cast<std::uint64_t>(rejected));
    json.field("lossy", static_cast<std::uint64_t>(lossy));
    // The runtime's report (Report::to_json's fields), so scripts read plans and restores alike.
    json.key_begin("report");
    json.object_begin();
    json.field("ok", report.ok());
    json.field("error", error_name(report.status().error()));
    json.field("message", report.status().message());
    json.field("sequence", report.sequence());
    json.key_begin("entries");
    json.array_begin();
    for (const ReportEntry& entry : report.entries()) {
      json.object_begin();
      json.field("path", entry.path);
      json.field("decision", decision_name(entry.decision));
      json.field("detail", entry.detail);
      json.field("lossy", entry.lossy);
      json.object_end();
    }
    json.array_end();
    json.key_end();
    json.object_end();
    json.key_end();
    json.object_end();
    return exit_code;
  }

  const Terminal terminal = Terminal::for_stdout();
  print("checkpoint  " + describe_checkpoint(checkpoint) + "\nbuild       " + build_text +
        "\nmode        " + (args.strict ? "strict" : "default") + "\n\n");
  print_report_table(report);
  if (would_restore) {
    print(terminal.paint(rejected ? Colour::Yellow : Colour::Green,
                         rejected ? "restore would proceed with " + std::to_string(rejected) +
                                        " rejected (each keeps the build's own value)"
                                  : "restore would succeed") +
          "\n");
  } else {
    print(terminal.paint(Colour::Red, std::string("restore would fail: ") +
                                          error_name(report.status().error()) + ": " +
                                          report.status().message()) +
          "\n");
  }
  return exit_code;
}

}  // namespace symcr::cli
