// `symcr diff`: the values that differ between two checkpoints, by path. Paths only one side
// has are listed as removed (only in a) or added (only in b), so checkpoints of different
// builds compare meaningfully; values compare by their rendering, so an int32 42 equals an
// int64 42 and floats compare exactly.
#include <algorithm>
#include <functional>
#include <string>
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

constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

struct Difference {
  Change change;
  std::size_t a;  // leaf of a; kAbsent when added
  std::size_t b;  // leaf of b; kAbsent when removed
};

const char* change_name(Change change) {
  switch (change) {
    case Change::Changed:
      return "changed";
    case Change::Removed:
      return "removed";
    case Change::Added:
      return "added";
  }
  return "?";
}

// A listing's leaves by path without holding the paths: their hashes, sorted, each match
// confirmed by rendering the path. Of several leaves with one path the first counts.
class PathIndex {
 public:
  explicit PathIndex(const ValueListing& listing) : listing_(listing) {
    entries_.reserve(listing.size());
    for (std::size_t leaf = 0; leaf < listing.size(); ++leaf) {
      entries_.push_back({hash(listing.path(leaf)), leaf});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  std::size_t find(const std::string& path) const {
    const std::uint64_t h = hash(path);
    for (auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{h, 0});
         it != entries_.end() && it->hash == h; ++it) {
      if (listing_.path(it->leaf) == path) return it->leaf;
    }
    return kAbsent;
  }

 private:
  struct Entry {
    std::uint64_t hash;
    std::size_t leaf;
    bool operator<(const Entry& other) const {
      return hash != other.hash ? hash < other.hash : leaf < other.leaf;
    }
  };
  static std::uint64_t hash(const std::string& path) { return std::hash<std::string>()(path); }

  const ValueListing& listing_;
  std::vector<Entry> entries_;
};

std::vector<Difference> compare(const ValueListing& a, const ValueListing& b) {
  const PathIndex in_a(a), in_b(b);
  std::vector<Difference> differences;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = in_b.find(a.path(i));
    if (j == kAbsent) {
      differences.push_back({Change::Removed, i, kAbsent});
    } else if (a.text(i) != b.text(j)) {
      differences.push_back({Change::Changed, i, j});
    }
  }
  for (std::size_t j = 0; j < b.size(); ++j) {
    if (in_a.find(b.path(j)) == kAbsent) differences.push_back({Change::Added, kAbsent, j});
  }
  return differences;
}

// The table's columns: change mark, path, a, b, and for a changed type a note.
constexpr std::size_t kDiffColumnCaps[] = {0, 60, 30, 30};

std::vector<Table::Cell> difference_row(const Difference& d, const ValueListing& a,
                                        const ValueListing& b) {
  switch (d.change) {
    case Change::Changed: {
      const Value va = a.value(d.a), vb = b.value(d.b);
      std::string note;
      if (va.type != vb.type) note = "(" + va.type + " -> " + vb.type + ")";
      return {{"~", Colour::Yellow}, {va.path}, {va.text}, {vb.text}, {note}};
    }
    case Change::Removed:
      return {{"-", Colour::Red}, {a.path(d.a)}, {a.text(d.a)}, {"(absent)", Colour::Dim}};
    case Change::Added:
      return {{"+", Colour::Green}, {b.path(d.b)}, {"(absent)", Colour::Dim}, {b.text(d.b)}};
  }
  return {};
}

std::string describe(const LoadedCheckpoint& c) {
  std::string text = c.path;
  if (c.from_store) text += " slot " + std::to_string(c.slot);
  text += " (sequence " + std::to_string(c.record.header.sequence) + ", " +
          utc_iso8601(c.record.header.timestamp_ns) + ")";
  return text;
}

bool load(const std::string& path, std::optional<std::uint32_t> slot, LoadedCheckpoint& out,
          ValueListing& values) {
  Status status = load_checkpoint(path, slot, out);
  if (status.ok()) {
    status = values.decode(*out.writer, out.record.payload, out.record.payload_size);
    if (!status.ok()) status = Status(status.error(), "%s: %s", path.c_str(), status.message());
  }
  if (!status.ok()) print_error(status.message());
  return status.ok();
}

}  // namespace

int run_diff(const DiffArgs& args) {
  LoadedCheckpoint a, b;
  ValueListing values_a, values_b;
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
      json.object_begin();
      json.field("path", d.a != kAbsent ? values_a.path(d.a) : values_b.path(d.b));
      json.field("change", change_name(d.change));
      if (d.a != kAbsent) {
        const Value value = values_a.value(d.a);
        json.field("a", value.json);
        json.field("type_a", value.type);
      }
      if (d.b != kAbsent) {
        const Value value = values_b.value(d.b);
        json.field("b", value.json);
        json.field("type_b", value.type);
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
  // Widths first, then a row at a time: the differences are never held rendered.
  const std::vector<Table::Cell> heading = {
      {" "}, {"path", Colour::Bold}, {"a", Colour::Bold}, {"b", Colour::Bold}};
  std::size_t widths[4] = {};
  auto measure = [&widths](const std::vector<Table::Cell>& row) {
    for (std::size_t c = 0; c < 4 && c < row.size(); ++c) {
      widths[c] = std::max(widths[c], Table::cell_width(row[c].text, kDiffColumnCaps[c]));
    }
  };
  auto print_row = [&](const std::vector<Table::Cell>& row) {
    Table table;
    for (std::size_t c = 0; c < 4; ++c) {
      table.cap_column(c, kDiffColumnCaps[c]);
      table.pad_column(c, widths[c]);
    }
    table.add(row);
    print(table.render(terminal));
  };
  if (!differences.empty()) measure(heading);
  for (const Difference& d : differences) measure(difference_row(d, values_a, values_b));
  if (!differences.empty()) print_row(heading);
  for (const Difference& d : differences) print_row(difference_row(d, values_a, values_b));
  if (differences.empty()) {
    print("no differences (" + std::to_string(values_a.size()) + " values)\n");
    return kExitOk;
  }
  print("\n" + std::to_string(differences.size()) + " difference(s): " + std::to_string(counts[0]) +
        " changed, " + std::to_string(counts[1]) + " removed, " + std::to_string(counts[2]) +
        " added\n");
  return kExitFinding;
}

}  // namespace symcr::cli
