// The payload's grammar (docs/format.md §3), written once. Internal to the runtime.
//
// Every reader of a payload reads it through PayloadReader: restore's check and write passes
// (whose recursion follows the plan), and, through walk_value, the CLI's visitor, a migration
// hook's OldValues and the fuzzers. Each rule of the grammar (a bool is 0 or 1, a count is
// bounded by the bytes left, a presence flag is 0 or 1, a variant index names an alternative,
// a reference's steps stay inside its types, one nesting limit) is checked here and nowhere
// else, with one error text per fault.
#ifndef SYMCR_SRC_PAYLOAD_GRAMMAR_HPP
#define SYMCR_SRC_PAYLOAD_GRAMMAR_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "symcr/format/payload.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"
#include "schema_sizes.hpp"
#include "wire.hpp"

namespace symcr::detail {

// What ends a payload of a schema with clocks.
struct ClockReadings {
  std::uint64_t epoch = 0;              // the writing process (0: unknown, e.g. a device)
  const std::uint8_t* bytes = nullptr;  // the epoch, then `count` readings (format core)
  std::uint32_t count = 0;
  const std::uint8_t* reading_bytes(std::uint32_t clock) const {
    return bytes + format::clock_reading_offset(clock);
  }
  std::int64_t reading(std::uint32_t clock) const { return format::clock_reading(bytes, clock); }
};

// The payload's codes are the format core's (symcr/format/payload.hpp): a Pointer's or
// SharedPtr's reference code, and what a reference starts from.
using format::kBaseElement;
using format::kBaseObject;
using format::kFirstReference;
using format::kNullCode;
using format::kOutsideCode;
using format::ReferenceBase;

// The member a reference's step at a struct names: its fields first, then its reference
// members (format.md §2); nullptr when there is no such member.
inline const FieldInfo* step_member(const TypeInfo& type, std::uint32_t step) {
  if (step < type.field_count) return &type.fields[step];
  step -= type.field_count;
  return step < type.reference_member_count ? &type.reference_members[step] : nullptr;
}

// One step of a value's symbolic path: "copter", ".mission", "[3]", "heap#2(ModeAuto)".
// Decoders keep a stack of frames and render the path only when they report it.
struct PathFrame {
  enum class Kind : std::uint8_t { Name, Index, Heap, Alternative } kind;
  const char* name;     // Name, Heap (the type), Alternative (the type)
  std::uint64_t index;  // Index, Heap (the object's ordinal)
};
void append_path(std::string& path, const PathFrame& frame);
std::string render_path(const PathFrame* frames, std::size_t count);

// A reference of the payload's reference table: an object (kBaseObject: root or heap object
// `a`) or a container element (kBaseElement: element `b` of the `a`th container in stream order),
// then `step_count` steps into it, ending at writer type `target`.
struct Reference {
  std::uint8_t base = 0;
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint16_t step_count = 0;
  std::uint32_t target = 0;
};

// The bounds-checked reading of one payload by the grammar. Every read either succeeds or sets
// the caller's status to Corrupt "invalid payload: ..." and returns false. The hot reads are
// inline; their failures are out of line and cold.
class PayloadReader {
 public:
  PayloadReader(const Schema& writer, const WireSizes& sizes, Status& error)
      : writer_(writer), sizes_(sizes), error_(error) {}

  void start(const std::uint8_t* data, std::size_t size) {
    in_ = WireReader(data, size);
    size_ = size;
  }
  const std::uint8_t* position() const { return in_.position(); }
  void seek(const std::uint8_t* position) { in_.seek(position); }
  std::size_t remaining() const { return in_.remaining(); }
  std::size_t size() const { return size_; }
  const Schema& writer() const { return writer_; }
  const WireSizes& sizes() const { return sizes_; }

  // A Bool/Int/UInt/Float/Enum or a Union: its bytes.
  bool scalar(const TypeInfo& type, const std::uint8_t*& bytes) {
    if (!in_.bytes(type.size, bytes)) return truncated("scalar");
    if (type.kind == Kind::Bool && bytes[0] > 1) return invalid_bool(bytes[0]);
    return true;
  }
  // `count` consecutive values of a fixed-width non-bool scalar type, all checked at once.
  bool scalar_run(const TypeInfo& element, std::uint64_t count, const std::uint8_t*& bytes) {
    if (count > in_.remaining() / element.size || !in_.bytes(count * element.size, bytes)) {
      return truncated("scalar run");
    }
    return true;
  }
  // A String: its length and characters (length * the character type's size bytes).
  bool string(const TypeInfo& type, const std::uint8_t*& chars, std::uint32_t& length) {
    if (!in_.read(length)) return truncated("string length");
    const std::uint32_t width = writer_.types[type.element].size;
    if (length > in_.remaining() / width || !in_.bytes(std::size_t{length} * width, chars)) {
      return truncated("string");
    }
    return true;
  }
  // A fixed array's element count is the schema's; refused when its elements encode to nothing
  // and there are too many of them to walk.
  bool array(const TypeInfo& type) {
    if (sizes_.least[type.element] == 0 && type.count > kMaxEmptyElements) return empty_array(type);
    return true;
  }
  // A Container's element count, bounded by the bytes left.
  bool container(const TypeInfo& type, std::uint32_t& count) {
    if (!in_.read(count)) return truncated("container count");
    const std::uint64_t least = sizes_.least[type.element];
    if (least == 0 ? count > kMaxEmptyElements : count > in_.remaining() / least) {
      return container_too_long(count);
    }
    return true;
  }
  // An Optional's or UniquePtr's presence flag.
  bool presence(const TypeInfo& type, bool& present) {
    std::uint8_t flag = 0;
    if (!in_.read(flag)) return truncated(type.kind == Kind::Optional ? "optional" : "unique_ptr");
    if (flag > 1) return invalid_flag(type, flag);
    present = flag != 0;
    return true;
  }
  // A Variant's alternative index; kNoType when it was saved valueless.
  bool variant(const TypeInfo& type, std::uint32_t& index) {
    if (!in_.read(index)) return truncated("variant");
    if (index != kNoType && index >= type.alternative_count) return invalid_alternative(index);
    return true;
  }
  // A Pointer's or SharedPtr's reference code (kNullCode, kOutsideCode, or a reference index
  // from kFirstReference on, checked once the table is read).
  bool pointer(const TypeInfo& type, std::uint32_t& code) {
    if (!in_.read(code)) return truncated("pointer");
    if (code == kOutsideCode && type.kind == Kind::SharedPtr) return shared_outside();
    return true;
  }
  // Values of a fixed encoded size, not looked into.
  bool skip(std::uint64_t bytes) {
    if (bytes > in_.remaining()) return truncated("value");
    in_.seek(in_.position() + bytes);
    return true;
  }
  // The nesting charged to a root's or heap object's value of `type`, and to a container's
  // element or a unique_ptr's pointee of `type` inside a value charged `depth`.
  int object_depth(std::uint32_t type) const { return static_cast<int>(sizes_.levels[type]); }
  int element_depth(int depth, std::uint32_t type) const {
    return depth + 1 + static_cast<int>(sizes_.levels[type]);
  }
  // Whether a value charged `depth` is within the nesting limit.
  bool nest(int depth) { return depth <= kMaxValueNesting || too_deep(); }

  // The heap section's header and each heap object's (its writer type and ownership flag).
  bool heap_count(std::uint32_t& count);
  bool heap_object(std::uint32_t ordinal, std::uint32_t& type, std::uint8_t& owner);

  // The reference table. `object_type(a, type)` gives the writer type of object `a` (false when
  // there is none); `element_type(a, b, type)` that of element `b` of container `a`. Each step
  // is checked against the type it steps into and passed to `on_step(step)`.
  bool reference_count(std::uint32_t& count);
  // After the references: the clock readings (none when the writer schema has no clocks).
  bool clock_readings(ClockReadings& out);
  template <typename ObjectType, typename ElementType, typename OnStep>
  bool reference(std::uint32_t i, Reference& ref, ObjectType object_type, ElementType element_type,
                 OnStep on_step) {
    if (!in_.read(ref.base) || !in_.read(ref.a)) return truncated("reference");
    if (ref.base > kBaseElement) return invalid_reference(i, "has base kind", ref.base);
    if ((ref.base == kBaseElement && !in_.read(ref.b)) || !in_.read(ref.step_count)) {
      return truncated("reference");
    }
    std::uint32_t type = 0;
    if (ref.base == kBaseObject ? !object_type(ref.a, type) : !element_type(ref.a, ref.b, type)) {
      return missing_base(i, ref);
    }
    for (std::uint16_t s = 0; s < ref.step_count; ++s) {
      std::uint32_t step = 0;
      if (!in_.read(step)) return truncated("reference steps");
      if (!step_into(i, type, step)) return false;
      on_step(step);
    }
    if (!in_.read(ref.target)) return truncated("reference target");
    if (ref.target != type) return wrong_target(i, type, ref.target);
    return true;
  }
  // After the reference table: nothing may follow.
  bool finish();

 private:
  bool step_into(std::uint32_t i, std::uint32_t& type, std::uint32_t step);

  __attribute__((noinline, cold)) bool truncated(const char* what);
  __attribute__((noinline, cold)) bool invalid_bool(std::uint8_t value);
  __attribute__((noinline, cold)) bool empty_array(const TypeInfo& type);
  __attribute__((noinline, cold)) bool container_too_long(std::uint32_t count);
  __attribute__((noinline, cold)) bool invalid_flag(const TypeInfo& type, std::uint8_t flag);
  __attribute__((noinline, cold)) bool invalid_alternative(std::uint32_t index);
  __attribute__((noinline, cold)) bool shared_outside();
  __attribute__((noinline, cold)) bool too_deep();
  __attribute__((noinline, cold)) bool invalid_reference(std::uint32_t i, const char* what,
                                                         std::uint32_t value);
  __attribute__((noinline, cold)) bool missing_base(std::uint32_t i, const Reference& ref);
  __attribute__((noinline, cold)) bool wrong_target(std::uint32_t i, std::uint32_t type,
                                                    std::uint32_t target);
  __attribute__((format(printf, 2, 3), noinline, cold)) bool fail(const char* format, ...);

  const Schema& writer_;
  const WireSizes& sizes_;
  Status& error_;
  WireReader in_;
  std::size_t size_ = 0;
};

// Walks one value of writer type `type` along the grammar, for decoders that need no reader
// schema. The sink sees the structure and the leaves:
//   static constexpr bool kEveryValue;  // false: runs of fixed-size values are skipped whole
//   void push(const PathFrame&); void pop();            // path, around every nested value
//   void leaf(const TypeInfo&, const std::uint8_t* bytes, std::size_t size);  // scalar, union,
//                                                       // string (its characters)
//   void pointer(const TypeInfo&, const std::uint8_t* code_bytes, std::uint32_t code);
//   void container(const TypeInfo&, std::uint32_t count);  // before its elements
// `depth` is the nesting charged to the value (object_depth for a root or heap object).
template <typename Sink>
bool walk_value(PayloadReader& in, std::uint32_t type_index, int depth, Sink& sink) {
  const Schema& writer = in.writer();
  const TypeInfo& type = writer.types[type_index];
  const std::uint8_t* bytes = nullptr;
  if (!Sink::kEveryValue && in.sizes().fixed[type_index] != WireSizes::kVariable) {
    return in.skip(in.sizes().fixed[type_index]);  // its bools are not looked at
  }
  switch (type.kind) {
    case Kind::Bool:
    case Kind::Int:
    case Kind::UInt:
    case Kind::Float:
    case Kind::Enum:
    case Kind::Union:
      if (!in.scalar(type, bytes)) return false;
      sink.leaf(type, bytes, type.size);
      return true;
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        sink.push(PathFrame{PathFrame::Kind::Name, type.fields[f].name, 0});
        if (!walk_value(in, type.fields[f].type, depth, sink)) return false;
        sink.pop();
      }
      return true;
    case Kind::Array:
      if (!in.array(type)) return false;
      for (std::uint64_t i = 0; i < type.count; ++i) {
        sink.push(PathFrame{PathFrame::Kind::Index, nullptr, i});
        if (!walk_value(in, type.element, depth, sink)) return false;
        sink.pop();
      }
      return true;
    case Kind::String: {
      std::uint32_t length = 0;
      if (!in.string(type, bytes, length)) return false;
      sink.leaf(type, bytes, std::size_t{length} * writer.types[type.element].size);
      return true;
    }
    case Kind::Container: {
      std::uint32_t count = 0;
      const int element_depth = in.element_depth(depth, type.element);
      if (!in.container(type, count) || (count > 0 && !in.nest(element_depth))) return false;
      sink.container(type, count);
      for (std::uint32_t i = 0; i < count; ++i) {
        sink.push(PathFrame{PathFrame::Kind::Index, nullptr, i});
        if (!walk_value(in, type.element, element_depth, sink)) return false;
        sink.pop();
      }
      return true;
    }
    case Kind::Optional: {  // holds its value by value: charged with the object
      bool present = false;
      if (!in.presence(type, present)) return false;
      return !present || walk_value(in, type.element, depth, sink);
    }
    case Kind::UniquePtr: {
      bool present = false;
      if (!in.presence(type, present)) return false;
      const int pointee_depth = in.element_depth(depth, type.element);
      return !present ||
             (in.nest(pointee_depth) && walk_value(in, type.element, pointee_depth, sink));
    }
    case Kind::Variant: {
      std::uint32_t index = 0;
      if (!in.variant(type, index)) return false;
      if (index == kNoType) return true;
      const std::uint32_t alternative = type.alternatives[index];
      sink.push(PathFrame{PathFrame::Kind::Alternative, writer.types[alternative].name, 0});
      if (!walk_value(in, alternative, depth, sink)) return false;
      sink.pop();
      return true;
    }
    case Kind::Pointer:
    case Kind::SharedPtr: {
      const std::uint8_t* code_bytes = in.position();
      std::uint32_t code = 0;
      if (!in.pointer(type, code)) return false;
      sink.pointer(type, code_bytes, code);
      return true;
    }
  }
  return false;
}

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PAYLOAD_GRAMMAR_HPP
