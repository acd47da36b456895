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
#include "payload_grammar.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::cli {

// One leaf, rendered.
struct Value {
  std::string path;
  std::string type;  // the writer type's canonical name
  std::string text;  // 42.28, true, AUTO, "text", -> copter.home, null
  JsonScalar json;
};

// The leaves of one payload, kept without copying what the file can make large: a leaf is its
// wire bytes in the payload and its place in a tree of path frames whose names are the
// schema's, so a path or a value is rendered only when asked for. The schema and the payload
// must outlive the listing.
class ValueListing {
 public:
  // Decodes the whole payload. The payload is checked in full before the first leaf is kept,
  // so on failure (Corrupt, with the engine's message; TooLarge beyond listing_budget) the
  // listing is empty.
  Status decode(const Schema& writer, const std::uint8_t* payload, std::size_t size);

  std::size_t size() const { return leaves_.size(); }
  std::string path(std::size_t leaf) const;
  std::string text(std::size_t leaf) const;
  Value value(std::size_t leaf) const;

 private:
  friend class Recorder;
  static constexpr std::uint32_t kNoNode = 0xFFFFFFFFu;
  static constexpr std::uint32_t kNoTarget = 0xFFFFFFFFu;
  struct Node {
    detail::PathFrame frame;
    std::uint32_t parent;
  };
  struct Leaf {
    const TypeInfo* type;
    const std::uint8_t* bytes;
    std::size_t size;
    std::uint32_t node;    // its own path frame
    std::uint32_t target;  // pointers: index into targets_; others kNoTarget
  };
  void append_path(std::uint32_t node, std::string& out) const;
  const char* target_text(const Leaf& leaf) const {
    return leaf.target == kNoTarget ? nullptr : targets_[leaf.target].c_str();
  }

  const Schema* writer_ = nullptr;
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  std::vector<std::string> targets_;  // pointer texts, each once ("null", "-> copter.home")
};

// The most memory a listing of a `payload_size`-byte payload may take: 64 MiB, or 128 bytes
// per payload byte when that is more (an ordinary payload takes well under 64 per byte).
std::size_t listing_budget(std::size_t payload_size);

// Full structural check of a payload against its schema, without keeping the values;
// `leaf_count`, when given, receives the number of leaves.
Status check_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     std::size_t* leaf_count = nullptr);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_VALUES_HPP
