// Finding the checkpoint a command works on: a single-file checkpoint, or one slot of a store
// (the one the program's next start would restore, or a chosen one), with its writer schema;
// and the keys the program authenticates checkpoints with.
#ifndef SYMCR_CLI_CHECKPOINT_SOURCE_HPP
#define SYMCR_CLI_CHECKPOINT_SOURCE_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "parsed_schema.hpp"
#include "record.hpp"
#include "store_reader.hpp"
#include "symcr/symcr.hpp"

namespace symcr::cli {

enum class FileKind : std::uint8_t {
  Record,  // "SYMCRCKP": a single-file checkpoint or a schema file
  Store,   // "SYMCRSTO"
};

// `path` with symbolic links resolved (or as given if it cannot be), for the CLI's own inputs
// (schema files, keys). A checkpoint or store behind a link is refused, as a program refuses
// it: what the CLI says of a file is what the program's restore would do with it.
std::string resolve_links(const std::string& path);

// Reads the magic only. Anything else is NotACheckpoint; a missing file is Io.
Status detect_file_kind(const std::string& path, FileKind& out);

struct LoadedCheckpoint {
  std::string path;
  bool from_store = false;
  std::uint32_t slot = 0;                      // from_store: which slot
  int area = -1;                               // from_store: the schema area of its record
  std::vector<std::uint8_t> bytes;             // the record
  detail::RecordView record;                   // views into `bytes`
  detail::ParsedSchema inline_schema;          // single file: its own schema
  std::unique_ptr<detail::StoreReader> store;  // from_store: owns the area's schema
  const Schema* writer = nullptr;
  std::uint64_t writer_hash = 0;
  // from_store, no slot chosen: the slots the next start passes over on the way to this one
  // (or to none), then the unusable ones, as restore_latest()'s Report::skipped().
  std::vector<SkippedCheckpoint> skipped;
  // from_store: nothing would be restored although the store holds sound checkpoints (the
  // crash-loop fallback or the keys exclude them all); load_checkpoint fails with NoValidSlot.
  bool restores_nothing = false;
};

// Reads each key file (its bytes are the key, as the program gives them to
// set_checkpoint_keys) and sets the keys: checkpoints are then authenticated as by a program
// that holds them. No keys: nothing is set.
Status use_key_files(const std::vector<KeyFile>& keys);
// Appends the keys of a key ring file to `keys`: one key a line, "<id> <key file>" (a relative
// key file is taken from the ring file's directory); blank lines and "#" comments are skipped.
Status read_key_ring(const std::string& path, std::vector<KeyFile>& keys);

// A single-file checkpoint, or from a store the chosen slot or else the one the program's next
// start would restore (store_survey.hpp: the journal applied, the keys set checked, corrupt
// payloads passed over). The record, its
// schema and (for a store slot) its payload are fully checked; a schema file is refused. A
// single-file record that names its schema by hash only (a device's) is read with the schema
// file `writer_schema`, whose hash must be the one it names.
Status load_checkpoint(const std::string& path, std::optional<std::uint32_t> slot,
                       LoadedCheckpoint& out, const std::string& writer_schema = "");

// With keys set (use_key_files), OK only for a checkpoint a restore would accept as
// authentic: it carries a MAC that verifies with one of them, bound to its store slot (or as a
// standalone checkpoint). A restore checks this before anything else. Without keys, OK.
Status check_authentic(const LoadedCheckpoint& checkpoint);
// "<path> [slot N] (sequence S, <time>, schema <hash>)", for a command's heading.
std::string describe_checkpoint(const LoadedCheckpoint& checkpoint);

// The parts of loading a single-file record, for verify's step-by-step account: parses and
// validates the record (no trailing bytes; schema inline, or `writer_schema`'s) and its schema.
Status load_record_file(const std::string& path, LoadedCheckpoint& out,
                        const std::string& writer_schema = "");

}  // namespace symcr::cli

#endif  // SYMCR_CLI_CHECKPOINT_SOURCE_HPP
