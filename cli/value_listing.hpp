// Printing decoded values: `path = value` lines aligned on `=`, or a JSON array of
// {"path", "type", "value"} objects in payload order.
#ifndef SYMCR_CLI_VALUE_LISTING_HPP
#define SYMCR_CLI_VALUE_LISTING_HPP

#include <vector>

#include "json_writer.hpp"
#include "values.hpp"

namespace symcr::cli {

void print_values(const std::vector<Value>& values);
void write_values_json(JsonWriter& json, const std::vector<Value>& values);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_VALUE_LISTING_HPP
