// `symcr plan`: the restore report that restoring a checkpoint into a given build would
// produce, computed from the build's schema file without running the build — a gate before
// deploying a patch. Several checkpoints (or a directory of them) give a matrix, one line per
// checkpoint, then the report of each one that would not restore cleanly. Exit 1 when a restore
// would fail or reject a field, and with --strict when any decision is lossy; 2 when a
// checkpoint cannot be read.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "authentication.hpp"
#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "dry_run.hpp"
#include "exit_codes.hpp"
#include "header_fields.hpp"
#include "json_writer.hpp"
#include "parsed_schema.hpp"
#include "record.hpp"
#include "report_access.hpp"
#include "report_table.hpp"
#include "schema_file.hpp"
#include "terminal.hpp"

namespace symcr::cli {
namespace {

struct Build {
  detail::ParsedSchema schema;
  std::uint32_t program_id = 0;
};

// One checkpoint planned into the build.
struct PlannedCheckpoint {
  std::string path;
  Status loaded;  // !ok: the checkpoint could not be read (nothing else is set)
  LoadedCheckpoint checkpoint;
  Report report;
  // A store whose journal or keys exclude every checkpoint: loaded, but no checkpoint is set;
  // the report says why nothing would be restored.
  bool restores_nothing = false;
  std::size_t rejected = 0;
  std::size_t lossy = 0;
  bool would_restore = false;
  // What the gate decides: a failed restore or a rejected field; with --strict, lossiness.
  bool finding(bool strict) const { return !would_restore || rejected != 0 || (strict && lossy); }
};

void plan_one(const PlanArgs& args, const Build& build, PlannedCheckpoint& out) {
  out.loaded = load_checkpoint(out.path, args.slot, out.checkpoint, args.writer_schema);
  if (!out.loaded.ok() && out.checkpoint.restores_nothing) {
    // The program's next start would restore nothing: a restore that fails, not a file that
    // cannot be read.
    detail::ReportAccess::set_status(out.report, out.loaded);
    detail::ReportAccess::skipped(out.report) = out.checkpoint.skipped;
    out.loaded = Status();
    out.restores_nothing = true;
    return;
  }
  if (!out.loaded.ok()) return;
  const detail::RecordHeader& header = out.checkpoint.record.header;
  // With keys, a restore refuses a checkpoint whose MAC does not verify, before anything else.
  Status refused = check_authentic(out.checkpoint);
  if (refused.ok()) {
    refused = detail::check_program(header.program_id, build.program_id,
                                    "the build of the schema file", args.accept_other_program);
  }
  if (refused.ok()) {
    out.report = dry_run_restore(out.checkpoint, build.schema.schema(), args.strict);
  } else {
    detail::ReportAccess::set_status(out.report, refused);
    detail::ReportAccess::set_sequence(out.report, header.sequence);
  }
  detail::ReportAccess::skipped(out.report) = out.checkpoint.skipped;
  out.rejected = out.report.count(Decision::Rejected);
  out.lossy = lossy_count(out.report);
  out.would_restore = out.report.ok();
}

// The heading naming what is planned.
std::string planned_text(const PlannedCheckpoint& plan) {
  return plan.restores_nothing ? plan.path +
                                     " (no checkpoint: the program's next start would "
                                     "restore none)"
                               : describe_checkpoint(plan.checkpoint);
}

// The slots the program's next start passes over (as its restore report lists them), then the
// report's table (none when nothing would be restored).
void print_plan_body(const PlannedCheckpoint& plan) {
  for (const SkippedCheckpoint& skipped : plan.report.skipped()) {
    print("passed over slot " + std::to_string(skipped.slot) +
          (skipped.sequence != 0 ? " (sequence " + std::to_string(skipped.sequence) + ")" : "") +
          ": " + skipped.reason + "\n");
  }
  if (!plan.report.skipped().empty()) print("\n");
  if (!plan.restores_nothing) print_report_table(plan.report);
}

// The arguments, a directory standing for the files in it (by name; its subdirectories are
// not entered).
std::vector<std::string> checkpoint_paths(const std::vector<std::string>& arguments,
                                          bool& any_directory) {
  std::vector<std::string> paths;
  any_directory = false;
  for (const std::string& argument : arguments) {
    std::error_code error;
    if (!std::filesystem::is_directory(argument, error)) {
      paths.push_back(argument);
      continue;
    }
    any_directory = true;
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(argument, error)) {
      if (entry.is_regular_file(error)) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) paths.push_back(argument);  // reported as unreadable: no checkpoint in it
    paths.insert(paths.end(), files.begin(), files.end());
  }
  return paths;
}

void write_report_json(JsonWriter& json, const Report& report) {
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
  json.key_begin("skipped");
  json.array_begin();
  for (const SkippedCheckpoint& skipped : report.skipped()) {
    json.object_begin();
    json.field("slot", skipped.slot);
    json.field("sequence", skipped.sequence);
    json.field("reason", skipped.reason);
    json.object_end();
  }
  json.array_end();
  json.key_end();
  json.object_end();
}

// One checkpoint's plan as a JSON object; `with_build`: also the build's fields (a single plan).
void write_plan_json(JsonWriter& json, const PlanArgs& args, const Build& build,
                     const PlannedCheckpoint& plan, bool with_build) {
  json.object_begin();
  json.field("checkpoint", plan.path);
  if (!plan.loaded.ok()) {
    json.field("error", plan.loaded.message());
    json.object_end();
    return;
  }
  if (plan.restores_nothing) {
    json.field("slot", JsonScalar::null());
  } else {
    if (plan.checkpoint.from_store) json.field("slot", plan.checkpoint.slot);
    json.field("checkpoint_schema", hex64(plan.checkpoint.writer_hash));
  }
  if (with_build) {
    json.field("build_schema_file", args.schema);
    json.field("build_schema", hex64(build.schema.hash()));
    json.field("strict", args.strict);
  }
  json.field("would_restore", plan.would_restore);
  json.field("rejected", static_cast<std::uint64_t>(plan.rejected));
  json.field("lossy", static_cast<std::uint64_t>(plan.lossy));
  // The runtime's report (Report::to_json's fields), so scripts read plans and restores alike.
  json.key_begin("report");
  write_report_json(json, plan.report);
  json.key_end();
  json.object_end();
}

std::string verdict(const PlannedCheckpoint& plan) {
  if (!plan.would_restore) {
    return std::string("restore would fail: ") + error_name(plan.report.status().error()) + ": " +
           plan.report.status().message();
  }
  return plan.rejected ? "restore would proceed with " + std::to_string(plan.rejected) +
                             " rejected (each keeps the build's own value)"
                       : "restore would succeed";
}

void print_verdict(const Terminal& terminal, const PlannedCheckpoint& plan) {
  const Colour colour = !plan.would_restore ? Colour::Red
                        : plan.rejected     ? Colour::Yellow
                                            : Colour::Green;
  print(terminal.paint(colour, verdict(plan)) + "\n");
}

// The matrix's outcome cell of one checkpoint.
std::string outcome(const PlannedCheckpoint& plan, bool strict) {
  if (!plan.loaded.ok()) return std::string("unreadable: ") + plan.loaded.message();
  if (!plan.would_restore) {
    return std::string("fails: ") + error_name(plan.report.status().error());
  }
  std::string text = plan.rejected ? "rejects " + std::to_string(plan.rejected) : "restores";
  if (plan.lossy) text += (strict ? ", refused: " : ", ") + std::to_string(plan.lossy) + " lossy";
  return text;
}

int print_matrix(const PlanArgs& args, const std::string& build_text,
                 const std::vector<std::unique_ptr<PlannedCheckpoint>>& plans) {
  const Terminal terminal = Terminal::for_stdout();
  print("build       " + build_text + "\nmode        " + (args.strict ? "strict" : "default") +
        "\n\n");
  std::size_t width = std::string("checkpoint").size();
  for (const auto& plan : plans) width = std::max(width, plan->path.size());
  const auto cell = [](std::string text, std::size_t size) {
    text.resize(std::max(text.size(), size), ' ');
    return text;
  };
  print(cell("checkpoint", width) + "  slot  schema            outcome\n");
  unsigned clean = 0, findings = 0, unreadable = 0;
  for (const auto& plan : plans) {
    const bool loaded = plan->loaded.ok();
    const bool chosen = loaded && !plan->restores_nothing;
    const std::string slot =
        chosen && plan->checkpoint.from_store ? std::to_string(plan->checkpoint.slot) : "-";
    const std::string schema = chosen ? hex64(plan->checkpoint.writer_hash) : "-";
    const bool finding = loaded && plan->finding(args.strict);
    const Colour colour = !loaded || finding ? Colour::Red : Colour::Green;
    print(cell(plan->path, width) + "  " + cell(slot, 4) + "  " + cell(schema, 16) + "  " +
          terminal.paint(colour, outcome(*plan, args.strict)) + "\n");
    unreadable += !loaded;
    findings += finding;
    clean += loaded && !finding;
  }
  print("\n" + std::to_string(clean) + " of " + std::to_string(plans.size()) + " would restore" +
        (args.strict ? " without a lossy decision" : "") + "; " + std::to_string(findings) +
        " would not, " + std::to_string(unreadable) + " unreadable\n");
  for (const auto& plan : plans) {
    if (!plan->loaded.ok() || !plan->finding(args.strict)) continue;
    print("\ncheckpoint  " + planned_text(*plan) + "\n\n");
    print_plan_body(*plan);
    print_verdict(terminal, *plan);
  }
  return unreadable ? kExitError : findings ? kExitFinding : kExitOk;
}

}  // namespace

int run_plan(const PlanArgs& args) {
  const Status keys = use_key_files(args.keys);
  if (!keys.ok()) {
    print_error(keys.message());
    return kExitError;
  }
  bool any_directory = false;
  const std::vector<std::string> paths = checkpoint_paths(args.checkpoints, any_directory);
  Build build;
  Status status =
      detail::read_schema_file(resolve_links(args.schema).c_str(), build.schema, &build.program_id);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  std::vector<std::unique_ptr<PlannedCheckpoint>> plans;
  for (const std::string& path : paths) {
    plans.push_back(std::make_unique<PlannedCheckpoint>());
    plans.back()->path = path;
    plan_one(args, build, *plans.back());
  }
  const std::string build_text = args.schema + " (schema " + hex64(build.schema.hash()) + ", " +
                                 std::to_string(build.schema.schema().type_count) + " types, " +
                                 std::to_string(build.schema.schema().root_count) + " roots)";
  const bool matrix = plans.size() > 1 || any_directory;

  if (!matrix) {
    const PlannedCheckpoint& plan = *plans.front();
    if (!plan.loaded.ok()) {
      print_error(plan.loaded.message());
      return kExitError;
    }
    const int exit_code = plan.finding(args.strict) ? kExitFinding : kExitOk;
    if (args.json) {
      JsonWriter json;
      write_plan_json(json, args, build, plan, /*with_build=*/true);
      return exit_code;
    }
    print("checkpoint  " + planned_text(plan) + "\nbuild       " + build_text + "\nmode        " +
          (args.strict ? "strict" : "default") + "\n\n");
    print_plan_body(plan);
    print_verdict(Terminal::for_stdout(), plan);
    return exit_code;
  }

  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("build_schema_file", args.schema);
    json.field("build_schema", hex64(build.schema.hash()));
    json.field("strict", args.strict);
    json.key_begin("checkpoints");
    json.array_begin();
    bool unreadable = false, findings = false;
    for (const auto& plan : plans) {
      write_plan_json(json, args, build, *plan, /*with_build=*/false);
      unreadable |= !plan->loaded.ok();
      findings |= plan->loaded.ok() && plan->finding(args.strict);
    }
    json.array_end();
    json.key_end();
    json.object_end();
    return unreadable ? kExitError : findings ? kExitFinding : kExitOk;
  }
  return print_matrix(args, build_text, plans);
}

}  // namespace symcr::cli
