// Decoding a payload without a reader schema, leaf by leaf (the CLI's inspect/diff). Internal
// to the runtime; tools and tests may include it too.
#ifndef SYMCR_SRC_VISIT_HPP
#define SYMCR_SRC_VISIT_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

struct PathFrame;  // payload_grammar.hpp

// Called for each scalar leaf of a payload with its symbolic path.
struct ValueVisitor {
  virtual ~ValueVisitor() = default;
  // Around every nested value, in the pass that reports leaves: the path as a stack of frames
  // (whose names are the schema's), for a visitor that keeps paths without copying them.
  virtual void enter(const PathFrame& /*frame*/) {}
  virtual void leave() {}
  // `path` like "copter.mission.items[3].lat"; `type` is the writer type of the leaf; `bytes`
  // the little-endian wire bytes (String: the characters; Pointer: textual target in `text`).
  virtual void leaf(const char* path, const TypeInfo& type, const std::uint8_t* bytes,
                    std::size_t size, const char* text) = 0;
};
// Decodes a payload against its writer schema, calling `visitor`. Returns the decode status.
Status visit_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     ValueVisitor& visitor);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_VISIT_HPP
