// Printing decoded values: `path = value` lines aligned on `=`, or a JSON array of
// {"path", "type", "value"} objects in payload order. Both render one value at a time.
#ifndef SYMCR_CLI_VALUE_LISTING_HPP
#define SYMCR_CLI_VALUE_LISTING_HPP

#include "json_writer.hpp"
#include "values.hpp"

namespace symcr::cli {

void print_values(const ValueListing& values);
void write_values_json(JsonWriter& json, const ValueListing& values);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_VALUE_LISTING_HPP
