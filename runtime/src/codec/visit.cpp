// Decoding a payload against its writer schema alone, for the CLI (inspect, diff): every
// scalar leaf is reported with its concrete path and wire bytes; pointers with a textual
// target. Two walks along the grammar (payload_grammar.hpp): the first finds the reference
// table (which follows the values) and the paths of containers, the second reports the leaves.
#include <algorithm>
#include <string>
#include <vector>

#include "payload_grammar.hpp"
#include "visit.hpp"

namespace symcr::detail {
namespace {

class Walker {
 public:
  static constexpr bool kEveryValue = true;

  Walker(const Schema& writer, const std::uint8_t* payload, std::size_t size, ValueVisitor& visitor)
      : writer_(writer),
        sizes_(wire_sizes(writer)),
        in_(writer, sizes_, error_),
        payload_(payload),
        size_(size),
        visitor_(visitor) {}

  Status run() {
    emit_ = false;
    ClockReadings readings;
    if (!walk_objects() || !error_.ok() || !read_references() || !in_.clock_readings(readings) ||
        !in_.finish()) {
      return error_;
    }
    emit_ = true;
    walk_objects();
    emit_clock_readings(readings);
    return error_;
  }

  // Each clock's reading at the checkpoint, as a value "(clock).NAME" after the objects.
  void emit_clock_readings(const ClockReadings& readings) {
    static const TypeInfo kReading = [] {
      TypeInfo type{};
      type.name = "int64";
      type.kind = Kind::Int;
      type.size = type.align = 8;
      type.element = kNoType;
      return type;
    }();
    const std::vector<const ClockInfo*> clocks = schema_clocks(writer_);
    // "(clock).millis": a visitor may keep the frames' names, which the schema owns.
    push(PathFrame{PathFrame::Kind::Name, "(clock)", 0});
    for (std::uint32_t c = 0; c < readings.count && c < clocks.size(); ++c) {
      push(PathFrame{PathFrame::Kind::Name, clocks[c] && clocks[c]->name ? clocks[c]->name : "?",
                     0});
      leaf(kReading, readings.reading_bytes(c), format::kClockReadingSize);
      pop();
    }
    pop();
  }

  // ---- the sink of walk_value --------------------------------------------------------------
  void push(const PathFrame& frame) {
    marks_.push_back(path_.size());
    if (!over_budget_) {
      append_path(path_, frame);
      kept(0);  // the path itself counts
    }
    if (emit_) visitor_.enter(frame);
  }
  void pop() {
    path_.resize(marks_.back());
    marks_.pop_back();
    if (emit_) visitor_.leave();
  }
  void leaf(const TypeInfo& type, const std::uint8_t* bytes, std::size_t size) {
    if (emit_) visitor_.leaf(path_.c_str(), type, bytes, size, nullptr);
  }
  void pointer(const TypeInfo& type, const std::uint8_t* code_bytes, std::uint32_t code) {
    if (!emit_) return;
    const char* text = "null";
    if (code == kOutsideCode) text = "outside";
    if (code >= kFirstReference) {
      const std::uint32_t index = code - kFirstReference;
      text = index < targets_.size() ? targets_[index].c_str() : "-> ?";
    }
    visitor_.leaf(path_.c_str(), type, code_bytes, 4, text);
  }
  void container(const TypeInfo& type, std::uint32_t count) {
    if (emit_ || !kept(path_.size())) return;
    containers_.push_back(Container{path_, count, type.element});
  }

 private:
  struct Container {
    std::string path;
    std::uint32_t count;
    std::uint32_t element_type;
  };

  // The paths kept for containers (references may name their elements), the references' texts
  // and the current path are text the file's names drive: bounded by the input (names of up to
  // 64 KiB over many containers would otherwise take gigabytes), refused past the bound.
  bool kept(std::size_t more) {
    kept_bytes_ += more;
    if (!over_budget_ && kept_bytes_ + path_.size() <= text_budget_) return true;
    if (!over_budget_ && error_.ok()) {
      error_ = Status(Error::TooLarge,
                      "the payload's paths would take more than %zu bytes of text (the bound for "
                      "a payload of %zu bytes)",
                      text_budget_, size_);
    }
    over_budget_ = true;
    return false;
  }

  bool walk_objects() {
    in_.start(payload_, size_);
    for (std::uint32_t r = 0; r < writer_.root_count; ++r) {
      path_.clear();
      push(PathFrame{PathFrame::Kind::Name, writer_.roots[r].name, 0});
      const std::uint32_t type = writer_.roots[r].type;
      if (!walk_value(in_, type, in_.object_depth(type), *this)) return false;
      pop();
    }
    std::uint32_t heap_count = 0;
    if (!in_.heap_count(heap_count)) return false;
    for (std::uint32_t h = 0; h < heap_count; ++h) {
      std::uint32_t type = 0;
      std::uint8_t owner = 0;
      if (!in_.heap_object(h, type, owner)) return false;
      if (!emit_) heap_types_.push_back(type);
      path_.clear();
      push(PathFrame{PathFrame::Kind::Heap, writer_.types[type].name, h});
      if (!walk_value(in_, type, in_.object_depth(type), *this)) return false;
      pop();
    }
    return true;
  }

  bool read_references() {
    std::uint32_t count = 0;
    if (!in_.reference_count(count)) return false;
    for (std::uint32_t i = 0; i < count; ++i) {
      std::string text;
      std::uint32_t type = 0;
      auto object_type = [&](std::uint32_t a, std::uint32_t& out) {
        if (a < writer_.root_count) {
          append_path(text, PathFrame{PathFrame::Kind::Name, writer_.roots[a].name, 0});
          type = out = writer_.roots[a].type;
          return true;
        }
        if (a - writer_.root_count >= heap_types_.size()) return false;
        type = out = heap_types_[a - writer_.root_count];
        append_path(text, PathFrame{PathFrame::Kind::Heap, writer_.types[out].name,
                                    a - writer_.root_count});
        return true;
      };
      auto element_type = [&](std::uint32_t a, std::uint32_t b, std::uint32_t& out) {
        if (a >= containers_.size() || b >= containers_[a].count) return false;
        text += containers_[a].path;
        append_path(text, PathFrame{PathFrame::Kind::Index, nullptr, b});
        type = out = containers_[a].element_type;
        return true;
      };
      auto on_step = [&](std::uint32_t step) {
        const TypeInfo& t = writer_.types[type];
        const FieldInfo* member = t.kind == Kind::Struct ? step_member(t, step) : nullptr;
        type = member ? member->type : t.kind == Kind::Variant ? t.alternatives[step] : t.element;
        if (member) {
          text += '.';
          text += member->name;
        } else if (t.kind == Kind::Array || t.kind == Kind::String) {  // an element or character
          append_path(text, PathFrame{PathFrame::Kind::Index, nullptr, step});
        } else if (t.kind == Kind::Variant) {
          append_path(text, PathFrame{PathFrame::Kind::Alternative, writer_.types[type].name, 0});
        }
      };
      Reference ref;
      if (!in_.reference(i, ref, object_type, element_type, on_step)) return false;
      if (!kept(text.size())) return false;
      targets_.push_back("-> " + text);
    }
    return true;
  }

  const Schema& writer_;
  const WireSizes sizes_;
  Status error_;
  PayloadReader in_;
  const std::uint8_t* payload_;
  std::size_t size_;
  ValueVisitor& visitor_;
  bool emit_ = false;
  const std::size_t text_budget_ = std::max<std::size_t>(std::size_t{64} << 20, 64 * size_);
  std::size_t kept_bytes_ = 0;
  bool over_budget_ = false;
  std::string path_;
  std::vector<std::size_t> marks_;
  std::vector<std::uint32_t> heap_types_;
  std::vector<Container> containers_;
  std::vector<std::string> targets_;
};

}  // namespace

Status visit_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     ValueVisitor& visitor) {
  if (!payload && size) return Status(Error::Corrupt, "invalid payload: no bytes");
  Walker walker(writer, payload, size, visitor);
  return walker.run();
}

}  // namespace symcr::detail
