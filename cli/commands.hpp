// The subcommands, each in its own file, called by main.cpp once the command line is parsed.
// Each returns an exit code (exit_codes.hpp).
#ifndef SYMCR_CLI_COMMANDS_HPP
#define SYMCR_CLI_COMMANDS_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace symcr::cli {

// A key the program authenticates checkpoints with: its id and the file holding its bytes.
struct KeyFile {
  std::uint32_t id = 0;
  std::string path;
};

struct InspectArgs {
  std::string path;                   // a checkpoint, a store or a schema file
  std::optional<std::uint32_t> slot;  // store: this slot instead of the one a start restores
  bool json = false;
  std::string writer_schema;  // for a record that names its schema by hash only
  std::vector<KeyFile> keys;  // the program's keys (none: MACs are not checked)
};
int run_inspect(const InspectArgs& args);

struct VerifyArgs {
  std::string path;
  bool json = false;
  std::vector<KeyFile> keys;  // the program's keys (none: MACs are not checked)
};
int run_verify(const VerifyArgs& args);

struct DiffArgs {
  std::string a, b;
  std::optional<std::uint32_t> slot_a, slot_b;
  bool json = false;
};
int run_diff(const DiffArgs& args);

struct PlanArgs {
  std::vector<std::string> checkpoints;  // files, stores, or directories of them
  std::optional<std::uint32_t> slot;
  std::string schema;  // the target build's schema file
  bool strict = false;
  bool json = false;
  bool accept_other_program = false;  // plan a checkpoint of another program all the same
  std::string writer_schema;          // for a record that names its schema by hash only
  std::vector<KeyFile> keys;          // the program's keys (none: MACs are not checked)
};
int run_plan(const PlanArgs& args);

struct ConvertArgs {
  std::string checkpoint;
  std::optional<std::uint32_t> slot;
  std::string schema;  // the target build's schema file
  std::string output;
  std::string initial;  // a checkpoint of the target build's initial state
  bool strict = false;
  bool accept_other_program = false;
  bool inline_schema = false;  // else the record names its schema by hash only
  std::string writer_schema;   // for a record that names its schema by hash only
  std::vector<KeyFile> keys;   // the program's keys (none: MACs are not checked)
};
int run_convert(const ConvertArgs& args);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_COMMANDS_HPP
