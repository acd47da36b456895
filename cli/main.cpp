// symcr: the command-line tool (cli/README.md). Parses the command line with LLVM's
// CommandLine library (one subcommand each, with its own --help) and runs the subcommand.
// Exit codes: 0 fine, 1 a finding, 2 usage or I/O error (exit_codes.hpp).
#include <llvm/Support/CommandLine.h>
#include <llvm/Support/raw_ostream.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "store_survey.hpp"

namespace cl = llvm::cl;

namespace {

cl::OptionCategory symcr_category("symcr options");

cl::SubCommand inspect_command(
    "inspect",
    "Show a checkpoint's header and its values by source names. For a store: every "
    "slot, and the values of the one the program's next start would restore (or "
    "--slot N).");
cl::SubCommand verify_command(
    "verify",
    "Check a checkpoint or store: checksum, structure, full payload decode; for a "
    "store, the slot the program's next start would restore. Exit 1 if invalid.");
cl::SubCommand diff_command(
    "diff",
    "List the values that differ between two checkpoints, by path (added and removed "
    "paths too). Exit 1 if any differ.");
cl::SubCommand plan_command(
    "plan",
    "Show the report restoring a checkpoint into a build would produce, from the "
    "build's schema file, without running it; for several checkpoints (or directories "
    "of them) a line each, then the reports of those that would not restore cleanly. "
    "Exit 1 if a restore would fail or a field would be rejected (with --strict: if "
    "any decision is lossy), 2 if a checkpoint cannot be read.");
cl::SubCommand convert_command(
    "convert",
    "Restore a checkpoint into another build, known by its schema file, by the rules "
    "of that build's own restore, and write the result as that build's checkpoint "
    "(for a device, which restores only its own build's). Exit 1, writing nothing, "
    "if the restore would fail.");

cl::opt<std::string> inspect_path(cl::Positional, cl::Required,
                                  cl::desc("<checkpoint | store | schema file>"),
                                  cl::sub(inspect_command), cl::cat(symcr_category));
cl::opt<std::string> verify_path(cl::Positional, cl::Required,
                                 cl::desc("<checkpoint | store | schema file>"),
                                 cl::sub(verify_command), cl::cat(symcr_category));
cl::list<std::string> key_files(
    "key-file",
    cl::desc("A key the program authenticates checkpoints with: its bytes, as the program gives "
             "them to symcr::set_checkpoint_keys. Repeat for each key the program holds (a key "
             "rotation); a checkpoint without a MAC, or whose MAC verifies with none of them, "
             "is one the program refuses"),
    cl::value_desc("file"), cl::sub(inspect_command), cl::sub(verify_command),
    cl::sub(plan_command), cl::sub(convert_command), cl::cat(symcr_category));
cl::list<unsigned> key_ids(
    "key-id",
    cl::desc("The id of a --key-file key: the first --key-id is the first --key-file's, and so "
             "on (default 0 for a single key)"),
    cl::value_desc("N"), cl::sub(inspect_command), cl::sub(verify_command), cl::sub(plan_command),
    cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<std::string> key_ring(
    "key-ring",
    cl::desc("A file naming the program's keys, one a line: \"<id> <key file>\" (relative key "
             "files are taken from the ring's directory); with --key-file, both count"),
    cl::value_desc("file"), cl::sub(inspect_command), cl::sub(verify_command),
    cl::sub(plan_command), cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<std::string> counter_file(
    "counter",
    cl::desc("With keys: the store's freshness counter file (default: the store's path with "
             ".fresh appended, when it exists); a store older than it is reported rolled back"),
    cl::value_desc("file"), cl::sub(inspect_command), cl::sub(verify_command),
    cl::sub(plan_command), cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<std::string> diff_a(cl::Positional, cl::Required, cl::desc("<checkpoint a>"),
                            cl::sub(diff_command), cl::cat(symcr_category));
cl::opt<std::string> diff_b(cl::Positional, cl::Required, cl::desc("<checkpoint b>"),
                            cl::sub(diff_command), cl::cat(symcr_category));
cl::list<std::string> plan_checkpoints(cl::Positional, cl::OneOrMore,
                                       cl::desc("<checkpoint | store | directory>..."),
                                       cl::sub(plan_command), cl::cat(symcr_category));
cl::opt<std::string> convert_checkpoint(cl::Positional, cl::Required,
                                        cl::desc("<checkpoint | store>"), cl::sub(convert_command),
                                        cl::cat(symcr_category));
cl::opt<std::string> convert_output("o", cl::Required, cl::desc("The converted checkpoint"),
                                    cl::value_desc("file"), cl::sub(convert_command),
                                    cl::cat(symcr_category));
cl::opt<std::string> convert_initial(
    "initial",
    cl::desc("A checkpoint of the build's initial state (saved by the build where it would "
             "restore): the values its restore keeps. Without it, a conversion that keeps any "
             "of the build's own values is refused"),
    cl::value_desc("file"), cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<std::string> writer_schema(
    "writer-schema",
    cl::desc("Schema file of the build that wrote the checkpoint, for a record that names its "
             "schema by hash only (a device's)"),
    cl::value_desc("file"), cl::sub(inspect_command), cl::sub(plan_command),
    cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<bool> convert_inline_schema(
    "inline-schema",
    cl::desc("Carry the build's schema in the checkpoint (default: named by its hash, as a "
             "device's records are)"),
    cl::sub(convert_command), cl::cat(symcr_category));

cl::opt<bool> json_output("json", cl::desc("Write JSON instead of text"), cl::sub(inspect_command),
                          cl::sub(verify_command), cl::sub(diff_command), cl::sub(plan_command),
                          cl::cat(symcr_category));
cl::opt<unsigned> slot("slot",
                       cl::desc("Use this slot of a store instead of the one the program's next "
                                "start would restore"),
                       cl::value_desc("N"), cl::sub(inspect_command), cl::sub(plan_command),
                       cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<unsigned> slot_a("slot-a",
                         cl::desc("Slot of store <a> (default: the one its next start restores)"),
                         cl::value_desc("N"), cl::sub(diff_command), cl::cat(symcr_category));
cl::opt<unsigned> slot_b("slot-b",
                         cl::desc("Slot of store <b> (default: the one its next start restores)"),
                         cl::value_desc("N"), cl::sub(diff_command), cl::cat(symcr_category));
cl::opt<std::string> plan_schema("schema", cl::Required,
                                 cl::desc("Schema file of the build to restore into"),
                                 cl::value_desc("file"), cl::sub(plan_command),
                                 cl::sub(convert_command), cl::cat(symcr_category));
cl::opt<bool> plan_strict("strict",
                          cl::desc("Refuse any lossy decision, as RestoreOptions::strict does "
                                   "(exit 1)"),
                          cl::sub(plan_command), cl::sub(convert_command), cl::cat(symcr_category));

cl::opt<bool> plan_accept_other_program(
    "accept-other-program",
    cl::desc("Plan a checkpoint written by another program (another program name) instead of "
             "refusing it, as RestoreOptions::accept_other_program does"),
    cl::sub(plan_command), cl::sub(convert_command), cl::cat(symcr_category));

std::optional<std::uint32_t> given(const cl::opt<unsigned>& option) {
  if (option.getNumOccurrences() == 0) return std::nullopt;
  return static_cast<std::uint32_t>(option);
}

// Pairs the --key-file and --key-id options in order; false (after saying why) when they do not
// pair up.
bool given_keys(std::vector<symcr::cli::KeyFile>& keys) {
  if (key_ids.size() != key_files.size() && !(key_ids.empty() && key_files.size() == 1)) {
    llvm::errs() << "symcr: error: " << key_files.size() << " --key-file and " << key_ids.size()
                 << " --key-id: give each key file its id (the first --key-id is the first "
                    "--key-file's), or one --key-file alone (id 0)\n";
    return false;
  }
  for (std::size_t i = 0; i < key_files.size(); ++i) {
    keys.push_back({key_ids.empty() ? 0u : static_cast<std::uint32_t>(key_ids[i]), key_files[i]});
  }
  if (!key_ring.empty()) {
    const symcr::Status ring = symcr::cli::read_key_ring(key_ring, keys);
    if (!ring.ok()) {
      llvm::errs() << "symcr: error: " << ring.message() << "\n";
      return false;
    }
  }
  symcr::cli::use_counter_file(counter_file);
  return true;
}

void print_version(llvm::raw_ostream& out) { out << "symcr " SYMCR_VERSION "\n"; }

int run_subcommand() {
  std::vector<symcr::cli::KeyFile> keys;
  if (!given_keys(keys)) return symcr::cli::kExitError;
  if (inspect_command) {
    return symcr::cli::run_inspect({inspect_path, given(slot), json_output, writer_schema, keys});
  }
  if (verify_command) return symcr::cli::run_verify({verify_path, json_output, keys});
  if (diff_command) {
    return symcr::cli::run_diff({diff_a, diff_b, given(slot_a), given(slot_b), json_output});
  }
  if (plan_command) {
    return symcr::cli::run_plan({{plan_checkpoints.begin(), plan_checkpoints.end()},
                                 given(slot),
                                 plan_schema,
                                 plan_strict,
                                 json_output,
                                 plan_accept_other_program,
                                 writer_schema,
                                 keys});
  }
  if (convert_command) {
    return symcr::cli::run_convert({convert_checkpoint, given(slot), plan_schema, convert_output,
                                    convert_initial, plan_strict, plan_accept_other_program,
                                    convert_inline_schema, writer_schema, keys});
  }
  llvm::errs() << "symcr: a subcommand is needed: inspect, verify, diff, plan or convert (see "
                  "'symcr --help')\n";
  return symcr::cli::kExitError;
}

}  // namespace

int main(int argc, char** argv) {
  // LLVM's own options (from the shared library) are of no use here: show only ours.
  for (cl::SubCommand* command : {&*cl::TopLevelSubCommand, &inspect_command, &verify_command,
                                  &diff_command, &plan_command, &convert_command}) {
    cl::HideUnrelatedOptions(symcr_category, *command);
  }
  cl::SetVersionPrinter(print_version);
  if (!cl::ParseCommandLineOptions(
          argc, argv,
          "symcr: inspect, verify, diff, plan and convert symcr checkpoints\n\n"
          "  Run 'symcr <subcommand> --help' for a subcommand's options.\n"
          "  Exit codes: 0 fine, 1 a finding (invalid, different, rejected), 2 usage or I/O "
          "error.\n",
          &llvm::errs())) {
    return symcr::cli::kExitError;
  }
  const int code = run_subcommand();
  // Output that could not be written (a full disk, a closed stdout) is a failure, whatever the
  // subcommand found.
  llvm::outs().flush();
  std::string failure;
  if (llvm::outs().has_error()) {
    failure = llvm::outs().error().message();
    llvm::outs().clear_error();  // else LLVM aborts at exit
  }
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) failure = std::strerror(errno);
  if (!failure.empty()) {
    std::fprintf(stderr, "symcr: error: cannot write the output: %s\n", failure.c_str());
    return symcr::cli::kExitError;
  }
  return code;
}
