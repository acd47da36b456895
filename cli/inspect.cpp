// `symcr inspect`: a checkpoint's header and values by source names; for a store, every slot
// and the values of the one restore_latest() would take (or --slot N); for a schema file, the
// roots it declares.
#include <string>
#include <vector>

#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "header_fields.hpp"
#include "json_writer.hpp"
#include "store_survey.hpp"
#include "terminal.hpp"
#include "value_listing.hpp"
#include "values.hpp"

namespace symcr::cli {
namespace {

struct Root {
  std::string name;
  std::string type;
};

std::vector<Root> roots_of(const Schema& schema) {
  std::vector<Root> roots;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    const RootInfo& root = schema.roots[r];
    roots.push_back(
        {root.name, root.type < schema.type_count ? schema.types[root.type].name : "?"});
  }
  return roots;
}

int inspect_schema_file(const InspectArgs& args, const LoadedCheckpoint& file) {
  const std::vector<HeaderField> fields =
      describe_header(file.record.header, file.writer, "inline");
  const std::vector<Root> roots = roots_of(*file.writer);
  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("file", args.path);
    json.field("kind", "schema");
    json.key_begin("header");
    write_fields_json(json, fields);
    json.key_end();
    json.key_begin("roots");
    json.array_begin();
    for (const Root& root : roots) {
      json.object_begin();
      json.field("name", root.name);
      json.field("type", root.type);
      json.object_end();
    }
    json.array_end();
    json.key_end();
    json.object_end();
    return kExitOk;
  }
  print("schema file " + args.path + "\n");
  print_fields(fields);
  print("\n");
  Table table;
  for (const Root& root : roots) table.add({{root.name}, {root.type, Colour::Cyan}});
  print(table.render(Terminal::for_stdout()));
  return kExitOk;
}

int inspect_record(const InspectArgs& args) {
  if (args.slot) {
    print_error(args.path + " is a single-file checkpoint, which has no slots");
    return kExitError;
  }
  LoadedCheckpoint file;
  Status status = load_record_file(args.path, file, args.writer_schema);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  if (file.record.payload_size == 0) return inspect_schema_file(args, file);
  ValueListing values;
  status = values.decode(*file.writer, file.record.payload, file.record.payload_size);
  if (!status.ok()) {
    print_error(args.path + ": " + status.message());
    return kExitError;
  }
  const std::vector<HeaderField> fields =
      describe_header(file.record.header, file.writer, "inline");
  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("file", args.path);
    json.field("kind", "checkpoint");
    json.key_begin("header");
    write_fields_json(json, fields);
    json.key_end();
    json.key_begin("values");
    write_values_json(json, values);
    json.key_end();
    json.object_end();
    return kExitOk;
  }
  print("checkpoint " + args.path + "\n");
  print_fields(fields);
  print("\n");
  print_values(values);
  return kExitOk;
}

int inspect_store(const InspectArgs& args) {
  detail::StoreReader store;
  Status status = store.open(args.path.c_str(), counter_file_of(args.path).c_str());
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  const StoreSurvey survey = survey_store(store);
  std::optional<std::uint32_t> selected = args.slot ? args.slot : survey.restore_latest_slot;

  std::string failure;
  std::vector<std::uint8_t> bytes;  // the selected record, which `values` points into
  ValueListing values;
  std::vector<HeaderField> fields;
  if (!selected) {
    failure = args.path + ": " + survey.nothing_restored;
  } else if (*selected >= survey.slots.size()) {
    failure = args.path + " has " + std::to_string(survey.slots.size()) +
              " slots; there is no slot " + std::to_string(*selected);
    selected.reset();
  } else if (!survey.slots[*selected].restorable) {
    failure =
        args.path + ": slot " + std::to_string(*selected) + " is " + survey.slots[*selected].state +
        (survey.slots[*selected].problem.empty() ? "" : ": " + survey.slots[*selected].problem);
  } else {
    detail::RecordView view;
    int area = -1;
    status = store.read_record(*selected, bytes, view, area);
    const Schema* writer = area >= 0 ? &store.area(area).schema() : nullptr;
    if (status.ok()) status = values.decode(*writer, view.payload, view.payload_size);
    if (status.ok()) {
      fields = describe_header(view.header, writer, "store area " + std::to_string(area));
    } else {
      failure = args.path + ": slot " + std::to_string(*selected) + ": " + status.message();
    }
  }

  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("file", args.path);
    json.field("kind", "store");
    write_store_json(json, store, survey);
    json.field("selected_slot",
               selected && failure.empty() ? JsonScalar::of_uint(*selected) : JsonScalar::null());
    if (failure.empty()) {
      json.key_begin("header");
      write_fields_json(json, fields);
      json.key_end();
      json.key_begin("values");
      write_values_json(json, values);
      json.key_end();
    } else {
      json.field("error", failure);
    }
    json.object_end();
  } else {
    print_store_overview(args.path, store, survey, failure.empty() ? selected : std::nullopt);
    if (failure.empty()) {
      print("\nslot " + std::to_string(*selected) + "\n");
      print_fields(fields);
      print("\n");
      print_values(values);
    }
  }
  if (!failure.empty()) {
    print_error(failure);
    return kExitError;
  }
  return kExitOk;
}

}  // namespace

int run_inspect(const InspectArgs& args) {
  Status status = use_key_files(args.keys);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  FileKind kind = FileKind::Record;  // set on success; g++ -O3 cannot tell it is
  status = detect_file_kind(args.path, kind);
  if (!status.ok()) {
    print_error(status.message());
    return kExitError;
  }
  return kind == FileKind::Store ? inspect_store(args) : inspect_record(args);
}

}  // namespace symcr::cli
