// `symcr diff`: the values that differ between two checkpoints, by path. Paths only one side
// has are listed as removed (only in a) or added (only in b), so checkpoints of different
// builds compare meaningfully; values compare by their rendering, so an int32 42 equals an
// int64 42 and floats compare exactly.
#include <string>
#include <unordered_map>
#include <vector>

#include "checkpoint_source.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "header_fields.hpp"
#include "json_writer.hpp"
#include "terminal.hpp"
#include "values.hpp"

namespace symcr::cli {
namespace {

enum class Change { Changed, Removed, Added };

struct Difference {
  Change change;
  const Value* a;  // null when added
  const Value* b;  // null when removed
};

const char* change_name(Change change) {
  switch (change) {
    case Change::Changed: return "changed";
    case Change::Removed: return "removed";
    case Change::Added: return "added";
  }
  return "?";
}

std::vector<Difference> compare(const std::vector<Value>& a, const std::vector<Value>& b) {
  std::unordered_map<std::string, const Value*> in_b;
  for (const Value& value : b) in_b.emplace(value.path, &value);
  std::unordered_map<std::string, const Value*> in_a;
  std::vector<Difference> differences;
  for (const Value& value : a) {
    in_a.emplace(value.path, &value);
    const auto found = in_b.find(value.path);
    if (found == in_b.end()) {
      differences.push_back({Change::Removed, &value, nullptr});
    } else if (found->second->text != value.text) {
      differences.push_back({Change::Changed, &value, found->second});
    }
  }
  for (const Value& value : b) {
    if (in_a.find(value.path) == in_a.end()) differences.push_back({Change::Added, nullptr, &value});
  }
  return differences;
}

std::string describe(const LoadedCheckpoint& c) {
  std::string text = c.path;
  if (c.from_store) text += " slot " + std::to_string(c.slot);
  text += " (sequence " + std::to_string(c.record.header.sequence) + ", " +
          utc_iso8601(c.record.header.timestamp_ns) + ")";
  return text;
}

bool load(const std::string& path, std::optional<std::uint32_t> slot, LoadedCheckpoint& out,
          std::vector<Value>& values) {
  Status status = load_checkpoint(path, slot, out);
  if (status.ok()) {
    status = decode_values(*out.writer, out.record.payload, out.record.payload_size, values);
  }
  if (!status.ok()) print_error(status.message());
  return status.ok();
}

}  // namespace

int run_diff(const DiffArgs& args) {
  LoadedCheckpoint a, b;
  std::vector<Value> values_a, values_b;
  if (!load(args.a, args.slot_a, a, values_a) || !load(args.b, args.slot_b, b, values_b)) {
    return kExitError;
  }
  const std::vector<Difference> differences = compare(values_a, values_b);
  std::size_t counts[3] = {};
  for (const Difference& d : differences) ++counts[static_cast<int>(d.change)];

  if (args.json) {
    JsonWriter json;
    json.object_begin();
    json.field("a", describe(a));
    json.field("b", describe(b));
    json.field("changed", static_cast<std::uint64_t>(counts[0]));
    json.field("removed", static_cast<std::uint64_t>(counts[1]));
    json.field("added", static_cast<std::uint64_t>(counts[2]));
    json.key_begin("differences");
    json.array_begin();
    for (const Difference& d : differences) {
      const Value& any = d.a ? *d.a : *d.b;
      json.object_begin();
      json.field("path", any.path);
      json.field("change", change_name(d.change));
      if (d.a) {
        json.field("a", d.a->json);
        json.field("type_a", d.a->type);
      }
      if (d.b) {
        json.field("b", d.b->json);
        json.field("type_b", d.b->type);
      }
      json.object_end();
    }
    json.array_end();
    json.key_end();
    json.object_end();
    return differences.empty() ? kExitOk : kExitFinding;
  }

  const Terminal terminal = Terminal::for_stdout();
  print("a  " + describe(a) + "\nb  " + describe(b) + "\n\n");
  Table table;
  table.cap_column(1, 60);
  table.cap_column(2, 30);
  table.cap_column(3, 30);
  if (!differences.empty()) {
    table.add({{" "}, {"path", Colour::Bold}, {"a", Colour::Bold}, {"b", Colour::Bold}});
  }
  for (const Difference& d : differences) {
    switch (d.change) {
      case Change::Changed: {
        std::string note;
        if (d.a->type != d.b->type) note = "(" + d.a->type + " -> " + d.b->type + ")";
        table.add({{"~", Colour::Yellow}, {d.a->path}, {d.a->text}, {d.b->text}, {note}});
        break;
      }
      case Change::Removed:
        table.add({{"-", Colour::Red}, {d.a->path}, {d.a->text}, {"(absent)", Colour::Dim}});
        break;
      case Change::Added:
        table.add({{"+", Colour::Green}, {d.b->path}, {"(absent)", Colour::Dim}, {d.b->text}});
        break;
    }
  }
  print(table.render(terminal));
  if (differences.empty()) {
    print("no differences (" + std::to_string(values_a.size()) + " values)\n");
    return kExitOk;
  }
  print("\n" + std::to_string(differences.size()) + " difference(s): " +
        std::to_string(counts[0]) + " changed, " + std::to_string(counts[1]) + " removed, " +
        std::to_string(counts[2]) + " added\n");
  return kExitFinding;
}

}  // namespace symcr::cli
