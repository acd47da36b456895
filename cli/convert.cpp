// `symcr convert`: restores a checkpoint into another build, known by its schema file, by the
// same rules, report and strict mode as that build's own restore, and writes the result as a
// checkpoint of that build. For a device, which restores only its own build's checkpoints: the
// host converts across a firmware update, the device restores the result on its same-build
// path. Nothing is written unless the whole conversion succeeds.
#include <map>
#include <string>
#include <vector>

#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "file_io.hpp"
#include "header_fields.hpp"
#include "host_layout.hpp"
#include "parsed_schema.hpp"
#include "payload_grammar.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/payload.hpp"
#include "record.hpp"
#include "report_access.hpp"
#include "report_table.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "schema_file.hpp"
#include "terminal.hpp"

namespace symcr::cli {
namespace {

// What ends a payload of a schema with clocks (docs/format.md §3), read from a payload that
// restored (so it validated): the writing process's epoch and each clock's reading, by name.
struct ClockTimebase {
  std::uint64_t epoch = 0;
  std::map<std::string, std::int64_t> readings;
};
ClockTimebase clock_timebase(const Schema& writer, const std::uint8_t* payload, std::size_t size) {
  ClockTimebase timebase;
  const std::vector<const ClockInfo*> clocks = detail::schema_clocks(writer);
  const auto count = static_cast<std::uint32_t>(clocks.size());
  const std::size_t trailer_size = format::clock_readings_size(count);
  if (count == 0 || size < trailer_size) return timebase;
  const std::uint8_t* trailer = payload + size - trailer_size;
  timebase.epoch = format::load64(trailer);
  for (std::uint32_t c = 0; c < count; ++c) {
    if (clocks[c] != nullptr)
      timebase.readings[clocks[c]->name] = format::clock_reading(trailer, c);
  }
  return timebase;
}

// The readings that end the converted payload: the timebase its times are in, so that the
// build's restore in any other process moves them by its clocks' advance since (by name; a
// clock the timebase lacks reads 0, which no time needs: a time of a clock neither the
// checkpoint nor --initial has a reading of keeps the value it has).
std::vector<std::uint8_t> converted_readings(const Schema& build, const ClockTimebase& timebase,
                                             detail::ClockReadings& out) {
  const std::vector<const ClockInfo*> clocks = detail::schema_clocks(build);
  const auto count = static_cast<std::uint32_t>(clocks.size());
  std::vector<std::uint8_t> bytes(format::clock_readings_size(count));
  if (count != 0) format::store64(bytes.data(), timebase.epoch);
  for (std::uint32_t c = 0; c < count; ++c) {
    std::int64_t reading = 0;
    if (clocks[c] != nullptr) {
      const auto found = timebase.readings.find(clocks[c]->name);
      if (found != timebase.readings.end()) reading = found->second;
    }
    format::store64(bytes.data() + format::clock_reading_offset(c),
                    static_cast<std::uint64_t>(reading));
  }
  out.epoch = timebase.epoch;
  out.bytes = bytes.data();
  out.count = count;
  return bytes;
}

// The build's own values, into which the checkpoint is restored: what its restore keeps.
Status restore_initial_state(const std::string& path, const std::string& build_schema_file,
                             const detail::ParsedSchema& build, const HostLayout& layout,
                             ClockTimebase& timebase) {
  LoadedCheckpoint initial;
  // A device's record names its schema by hash: it is the build's own.
  Status status = load_checkpoint(path, std::nullopt, initial, build_schema_file);
  if (!status.ok()) return status;
  if (initial.writer_hash != build.hash()) {
    return Status(Error::Incompatible,
                  "%s was written by schema %s, not by the build of the schema file (%s): the "
                  "initial state must be that build's",
                  path.c_str(), hex64(initial.writer_hash).c_str(), hex64(build.hash()).c_str());
  }
  const Report restored =
      detail::restore_payload(*initial.writer, initial.writer_hash, initial.record.payload,
                              initial.record.payload_size, layout.schema(), RestoreOptions());
  if (restored.ok()) {
    timebase = clock_timebase(*initial.writer, initial.record.payload, initial.record.payload_size);
  }
  return restored.status();
}

// A build's symcr_migrate hooks are code: a conversion without them would not be its restore.
Status refuse_migrations(const Schema& build) {
  for (std::uint32_t t = 0; t < build.type_count; ++t) {
    if (build.types[t].flags & kTypeMigrated) {
      return Status(Error::Unsupported,
                    "the build migrates '%s' with symcr_migrate, code a conversion cannot run: "
                    "restore the checkpoint in a host build of the new source instead",
                    build.types[t].name);
    }
  }
  return Status();
}

}  // namespace

int run_convert(const ConvertArgs& args) {
  const Status keys = use_key_files(args.keys);
  if (!keys.ok()) {
    print_error(keys.message());
    return kExitError;
  }
  LoadedCheckpoint checkpoint;
  Status status = load_checkpoint(args.checkpoint, args.slot, checkpoint, args.writer_schema);
  if (!status.ok() && checkpoint.restores_nothing) {
    // The program's next start would restore nothing (its journal or keys exclude every
    // checkpoint, or the store is rolled back): a restore that fails, not an unreadable file.
    print_error(status.message() + std::string("; nothing written"));
    return kExitFinding;
  }
  // With keys, only a checkpoint the old build's restore would accept as authentic converts:
  // the converted record carries no MAC (the device profile verifies none), so this is where
  // its authenticity is checked.
  if (status.ok()) {
    const Status refused = check_authentic(checkpoint);
    if (!refused.ok()) {
      print_error(refused.message() + std::string("; nothing written"));
      return kExitFinding;
    }
  }
  detail::ParsedSchema build;
  std::uint32_t build_program_id = 0;
  if (status.ok()) {
    status = detail::read_schema_file(resolve_links(args.schema).c_str(), build, &build_program_id);
  }
  HostLayout layout;
  ClockTimebase initial_timebase;
  if (status.ok()) status = refuse_migrations(build.schema());
  if (status.ok()) {
    // What justifies the build's memory: the checkpoint's record and the build's schema.
    const std::uint64_t input_size = checkpoint.record.record_size + build.bytes().size();
    status = layout.lay_out(build.schema(), input_size);
  }
  // The result is in the checkpoint's timebase: its times are written as saved, so that the
  // build's restore moves them exactly as it moves the checkpoint's own (ranges see them as
  // saved, as there). The times kept from --initial are moved into that timebase as they are
  // restored (a restore whose clocks read the checkpoint's readings), so they move by their
  // clock's advance since --initial was saved; a clock the checkpoint has no reading of keeps
  // --initial's reading, and its times their values.
  ClockTimebase timebase;
  if (status.ok()) {
    timebase = clock_timebase(*checkpoint.writer, checkpoint.record.payload,
                              checkpoint.record.payload_size);
  }
  if (status.ok() && !args.initial.empty()) {
    status = layout.read_clocks_as(timebase.readings);
    if (status.ok()) {
      status = restore_initial_state(args.initial, args.schema, build, layout, initial_timebase);
    }
    if (status.ok()) status = layout.read_clocks_as({});  // the checkpoint's times stay as saved
    for (const auto& reading : initial_timebase.readings) timebase.readings.insert(reading);
  }
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  const Status program =
      detail::check_program(checkpoint.record.header.program_id, build_program_id,
                            "the build of the schema file", args.accept_other_program);
  if (!program.ok()) {
    print_error(program.message());
    return kExitFinding;
  }

  RestoreOptions options;
  options.strict = args.strict;
  options.accept_other_program = args.accept_other_program;
  Report report =
      detail::restore_payload(*checkpoint.writer, checkpoint.writer_hash, checkpoint.record.payload,
                              checkpoint.record.payload_size, layout.schema(), options);
  detail::ReportAccess::set_sequence(report, checkpoint.record.header.sequence);
  print("checkpoint  " + describe_checkpoint(checkpoint) + "\nbuild       " + args.schema +
        " (schema " + hex64(build.hash()) + ")\nmode        " +
        (args.strict ? "strict" : "default") + "\n\n");
  print_report_table(report);
  const Terminal terminal = Terminal::for_stdout();
  if (!report.ok()) {
    print(terminal.paint(Colour::Red, std::string("conversion failed, nothing written: ") +
                                          error_name(report.status().error()) + ": " +
                                          report.status().message()) +
          "\n");
    return kExitFinding;
  }
  // A value the restore keeps is the build's own, which only --initial supplies.
  if (args.initial.empty()) {
    std::string kept;
    for (const ReportEntry& entry : report.entries()) {
      if (entry.decision == Decision::Kept || entry.decision == Decision::Rejected) {
        kept += (kept.empty() ? "" : ", ") + entry.path;
      }
    }
    if (!kept.empty()) {
      print_error("the build keeps its own value for " + kept +
                  ", which only the build knows: give --initial <a checkpoint of the build's "
                  "initial state>; nothing written");
      return kExitFinding;
    }
  }

  detail::SchemaBlob identity;
  identity.data = build.bytes().data();
  identity.size = build.bytes().size();
  identity.hash = build.hash();
  identity.program_id = build_program_id;
  detail::ClockReadings readings;
  const std::vector<std::uint8_t> reading_bytes =
      converted_readings(build.schema(), timebase, readings);
  std::vector<std::uint8_t> record;
  status = detail::encode_record_as(layout.schema(), identity, args.inline_schema,
                                    checkpoint.record.header.sequence, record, nullptr, &readings);
  if (status.ok()) {
    status = detail::write_file_atomically(args.output.c_str(), record.data(), record.size(),
                                           Durability::Fdatasync);
  }
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  print(terminal.paint(Colour::Green, "converted: " + args.output + " (" +
                                          std::to_string(record.size()) + " bytes, schema " +
                                          hex64(build.hash()) + ")") +
        "\n");
  return kExitOk;
}

}  // namespace symcr::cli
