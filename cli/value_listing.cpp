// print_values and write_values_json.
#include "value_listing.hpp"

#include <algorithm>

#include "terminal.hpp"

namespace symcr::cli {

void print_values(const ValueListing& values) {
  constexpr std::size_t kPathCap = 60;
  // The path column's width first, then a row at a time: the listing is never held rendered.
  std::size_t path_width = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    path_width = std::max(path_width, Table::cell_width(values.path(i), kPathCap));
  }
  const Terminal terminal = Terminal::for_stdout();
  for (std::size_t i = 0; i < values.size(); ++i) {
    Table row;
    row.cap_column(0, kPathCap);
    row.pad_column(0, path_width);
    row.add({{values.path(i)}, {"="}, {values.text(i), Colour::Cyan}});
    print(row.render(terminal, " "));
  }
}

void write_values_json(JsonWriter& json, const ValueListing& values) {
  json.array_begin();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const Value value = values.value(i);
    json.object_begin();
    json.field("path", value.path);
    json.field("type", value.type);
    json.field("value", value.json);
    json.object_end();
  }
  json.array_end();
}

}  // namespace symcr::cli
