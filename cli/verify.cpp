// `symcr verify`: checks a checkpoint, schema file or store as restore would — checksum,
// structure, schema, and a full decode of the payload — and says which slot of a store
// restore_latest() would take. Exit 1 when anything written fails a check.
#include <string>
#include <vector>

#include "authentication.hpp"
#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "file_io.hpp"
#include "header_fields.hpp"
#include "json_writer.hpp"
#include "parsed_schema.hpp"
#include "store_survey.hpp"
#include "terminal.hpp"
#include "values.hpp"

namespace symcr::cli {
namespace {

struct Check {
  std::string name;
  bool ok;
  std::string detail;
};

// Runs the checks of a single record file in order, stopping at the first failure.
std::vector<Check> check_record_file(const std::vector<std::uint8_t>& bytes, std::string& kind) {
  std::vector<Check> checks;
  kind = "checkpoint";
  detail::RecordView record;
  Status status = detail::parse_record(bytes.data(), bytes.size(), record);
  if (!status.ok()) {
    checks.push_back(
        {"record", false, std::string(error_name(status.error())) + ": " + status.message()});
    return checks;
  }
  const detail::RecordHeader& h = record.header;
  checks.push_back({"record", true,
                    "format " + std::to_string(h.format_version) + ", " +
                        std::to_string(record.record_size) + " bytes, checksum ok (crc32c " +
                        hex32(h.checksum) + ")"});
  // With --key-file the MAC must verify; without, an authenticated record is only described.
  const detail::KeySnapshot keys = detail::current_keys();
  if (keys) {
    status = detail::check_standalone_authentication(keys.get(), bytes.data(), record);
    if (!status.ok()) {
      checks.push_back({"authentication", false, status.message()});
      return checks;
    }
    checks.push_back(
        {"authentication", true, "MAC verifies with key id " + std::to_string(h.key_id)});
  } else if ((h.flags & symcr::format::kRecordAuthenticated) != 0) {
    checks.push_back(
        {"authentication", true,
         "MAC with key id " + std::to_string(h.key_id) + ", not verified (no --key-file)"});
  }
  if (record.schema == nullptr) {
    checks.push_back({"schema", false,
                      "no inline schema (a store slot's record, schema " + hex64(h.schema_hash) +
                          " referenced by hash)"});
    return checks;
  }
  detail::ParsedSchema schema;
  status = detail::parse_schema(record.schema, h.schema_size, schema);
  if (!status.ok()) {
    checks.push_back({"schema", false, status.message()});
    return checks;
  }
  checks.push_back({"schema", true,
                    "inline, hash " + hex64(h.schema_hash) + ", " +
                        std::to_string(schema.schema().type_count) + " types, " +
                        std::to_string(schema.schema().root_count) + " roots"});
  if (record.payload_size == 0) {
    kind = "schema";
    checks.push_back({"payload", true, "none (a schema file)"});
    return checks;
  }
  std::size_t leaf_count = 0;
  status = check_payload(schema.schema(), record.payload, record.payload_size, &leaf_count);
  if (!status.ok()) {
    checks.push_back({"payload", false, status.message()});
    return checks;
  }
  checks.push_back({"payload", true,
                    std::to_string(record.payload_size) + " bytes, " + std::to_string(leaf_count) +
                        " values decoded"});
  return checks;
}

int verify_record(const VerifyArgs& args) {
  std::vector<std::uint8_t> bytes;
  std::uint64_t trailing = 0;
  const Status status = detail::read_record_file(args.path.c_str(), bytes, trailing);
  if (!status.ok() && trailing == 0) {
    print_error(status.message());
    return kExitError;
  }
  std::string kind = "checkpoint";
  // Bytes after the record are refused before the record is read: its layout is what fails.
  const std::vector<Check> checks = trailing != 0
                                        ? std::vector<Check>{{"layout", false, status.message()}}
                                        : check_record_file(bytes, kind);
  const bool valid = !checks.empty() && checks.back().ok;
  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("file", args.path);
    json.field("kind", kind);
    json.field("valid", valid);
    json.key_begin("checks");
    json.array_begin();
    for (const Check& check : checks) {
      json.object_begin();
      json.field("check", check.name);
      json.field("ok", check.ok);
      json.field("detail", check.detail);
      json.object_end();
    }
    json.array_end();
    json.key_end();
    json.object_end();
  } else {
    const Terminal terminal = Terminal::for_stdout();
    print(kind + " " + args.path + "\n");
    Table table;
    for (const Check& check : checks) {
      table.add({{check.name},
                 {check.ok ? "ok" : "FAILED", check.ok ? Colour::Green : Colour::Red},
                 {check.detail}});
    }
    print(table.render(terminal));
    print(terminal.paint(valid ? Colour::Green : Colour::Red, valid ? "valid" : "invalid") + "\n");
  }
  return valid ? kExitOk : kExitFinding;
}

int verify_store(const VerifyArgs& args) {
  detail::StoreReader store;
  const Status status = store.open(args.path.c_str(), counter_file_of(args.path).c_str());
  if (!status.ok()) {
    if (status.error() == Error::Io) {
      print_error(status.message());
      return kExitError;
    }
    if (args.json) {
      JsonWriter json;
      json.object_begin();
      json.field("file", args.path);
      json.field("kind", "store");
      json.field("valid", false);
      json.field("error", std::string(error_name(status.error())) + ": " + status.message());
      json.object_end();
    } else {
      const Terminal terminal = Terminal::for_stdout();
      print("store " + args.path + "\n");
      print(terminal.paint(Colour::Red, "invalid") + ": " + error_name(status.error()) + ": " +
            status.message() + "\n");
    }
    return kExitFinding;
  }
  const StoreSurvey survey = survey_store(store);
  std::size_t damaged = 0;
  for (const SlotSurvey& slot : survey.slots) damaged += slot.damaged;
  const bool valid = survey.restore_latest_slot.has_value() && damaged == 0;
  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("file", args.path);
    json.field("kind", "store");
    json.field("valid", valid);
    json.field("damaged_slots", static_cast<std::uint64_t>(damaged));
    write_store_json(json, store, survey);
    json.object_end();
  } else {
    const Terminal terminal = Terminal::for_stdout();
    print_store_overview(args.path, store, survey, std::nullopt);
    std::string verdict =
        terminal.paint(valid ? Colour::Green : Colour::Red, valid ? "valid" : "invalid");
    if (damaged) verdict += ": " + std::to_string(damaged) + " damaged slot(s)";
    if (!survey.restore_latest_slot) verdict += (damaged ? "; " : ": ") + survey.nothing_restored;
    print("\n" + verdict + "\n");
  }
  return valid ? kExitOk : kExitFinding;
}

}  // namespace

int run_verify(const VerifyArgs& args) {
  const Status keys = use_key_files(args.keys);
  if (!keys.ok()) {
    print_error(keys.message());
    return kExitError;
  }
  FileKind kind = FileKind::Record;  // set on success; g++ -O3 cannot tell it is
  const Status status = detect_file_kind(args.path, kind);
  if (!status.ok()) {
    if (status.error() == Error::Io) {
      print_error(status.message());
      return kExitError;
    }
    if (args.json) {
      JsonWriter json;
      json.object_begin();
      json.field("file", args.path);
      json.field("valid", false);
      json.field("error", status.message());
      json.object_end();
    } else {
      print(args.path + ": " + Terminal::for_stdout().paint(Colour::Red, "invalid") + ": " +
            status.message() + "\n");
    }
    return kExitFinding;
  }
  return kind == FileKind::Store ? verify_store(args) : verify_record(args);
}

}  // namespace symcr::cli
