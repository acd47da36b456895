// A checkpoint's values as a flat, ordered list of leaves by source path
// ("copter.mission.items[3].lat"), rendered for people (text) and for JSON. Decoding runs the
// engine's writer-schema walker (visit_payload), so no build of the program is needed.
#ifndef SYMCR_CLI_VALUES_HPP
#define SYMCR_CLI_VALUES_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "json_writer.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::cli {

struct Value {
  std::string path;
  std::string type;  // the writer type's canonical name
  std::string text;  // 42.28, true, AUTO, "text", -> copter.home, null
  JsonScalar json;
};

// Decodes the whole payload. The payload is checked in full before the first value is
// reported, so on failure (Corrupt, with the engine's message) `out` is empty.
Status decode_values(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     std::vector<Value>& out);

// Full structural check of a payload against its schema, without keeping the values.
Status check_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_VALUES_HPP
