// print_values and write_values_json.
#include "value_listing.hpp"

#include "terminal.hpp"

namespace symcr::cli {

void print_values(const std::vector<Value>& values) {
  Table table;
  table.cap_column(0, 60);
  for (const Value& value : values) {
    table.add({{value.path}, {"="}, {value.text, Colour::Cyan}});
  }
  print(table.render(Terminal::for_stdout(), " "));
}

void write_values_json(JsonWriter& json, const std::vector<Value>& values) {
  json.array_begin();
  for (const Value& value : values) {
    json.object_begin();
    json.field("path", value.path);
    json.field("type", value.type);
    json.field("value", value.json);
    json.object_end();
  }
  json.array_end();
}

}  // namespace symcr::cli
