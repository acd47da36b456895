// The payload grammar's path text and fault reports (payload_grammar.hpp).
#include "payload_grammar.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <utility>

#include "payload_error.hpp"

namespace symcr::detail {

// Paths are rendered only for reports and errors: cold.
__attribute__((cold)) void append_path(std::string& path, const PathFrame& frame) {
  char buffer[48];
  switch (frame.kind) {
    case PathFrame::Kind::Name:
      if (!path.empty()) path += '.';
      path += frame.name;
      return;
    case PathFrame::Kind::Index:
      std::snprintf(buffer, sizeof buffer, "[%" PRIu64 "]", frame.index);
      path += buffer;
      return;
    case PathFrame::Kind::Heap:
      std::snprintf(buffer, sizeof buffer, "heap#%" PRIu64 "(", frame.index);
      path += buffer;
      path += frame.name;
      path += ')';
      return;
    case PathFrame::Kind::Alternative:
      path += '<';
      path += frame.name;
      path += '>';
      return;
  }
}

__attribute__((cold)) std::string render_path(const PathFrame* frames, std::size_t count) {
  std::string path;
  for (std::size_t i = 0; i < count; ++i) append_path(path, frames[i]);
  return path;
}

bool PayloadReader::heap_count(std::uint32_t& count) {
  if (!in_.read(count)) return truncated("heap count");
  // A heap object takes at least its 5-byte header.
  if (count > in_.remaining() / 5) return fail("heap count %u exceeds the payload", count);
  return true;
}

bool PayloadReader::heap_object(std::uint32_t ordinal, std::uint32_t& type, std::uint8_t& owner) {
  if (!in_.read(type) || !in_.read(owner)) return truncated("heap object");
  if (type >= writer_.type_count) return fail("heap object %u has type %u", ordinal, type);
  if (owner > format::kHeapOwnerShared) return fail("heap object %u has owner %u", ordinal, owner);
  return true;
}

bool PayloadReader::reference_count(std::uint32_t& count) {
  if (!in_.read(count)) return truncated("reference count");
  // A reference takes at least an object reference without steps: base, object, step count and
  // target.
  if (count > in_.remaining() / format::object_reference_size(0)) {
    return fail("reference count %u exceeds the payload", count);
  }
  return true;
}

bool PayloadReader::clock_readings(ClockReadings& out) {
  out = ClockReadings();
  if (sizes_.clock_count == 0) return true;
  if (!in_.bytes(format::clock_readings_size(sizes_.clock_count), out.bytes)) {
    return truncated("clock readings");
  }
  out.epoch = format::load64(out.bytes);
  out.count = sizes_.clock_count;
  return true;
}

bool PayloadReader::finish() {
  if (in_.at_end()) return true;
  return fail("%zu bytes after the payload's references", in_.remaining());
}

// A step into a struct is a field index (then a reference member's: format.md §2), into an array an
// element index, into an optional or unique_ptr 0 (its value), into a variant an alternative index,
// into a string a character index (bounded by the string's length once restored).
bool PayloadReader::step_into(std::uint32_t i, std::uint32_t& type, std::uint32_t step) {
  const TypeInfo& t = writer_.types[type];
  switch (t.kind) {
    case Kind::Struct: {
      const FieldInfo* member = step_member(t, step);
      if (!member) return fail("reference %u: no field %u in %s", i, step, t.name);
      type = member->type;
      return true;
    }
    case Kind::Array:
      if (step >= t.count) return fail("reference %u: index %u beyond %s", i, step, t.name);
      type = t.element;
      return true;
    case Kind::Optional:
    case Kind::UniquePtr:
      if (step != 0) return fail("reference %u: step %u into %s", i, step, t.name);
      type = t.element;
      return true;
    case Kind::Variant:
      if (step >= t.alternative_count) {
        return fail("reference %u: alternative %u of %s", i, step, t.name);
      }
      type = t.alternatives[step];
      return true;
    case Kind::String:
      type = t.element;
      return true;
    default:
      return fail("reference %u: a step into %s", i, t.name);
  }
}

bool PayloadReader::truncated(const char* what) { return fail("truncated in %s", what); }
bool PayloadReader::invalid_bool(std::uint8_t value) { return fail("bool value %u", value); }
bool PayloadReader::empty_array(const TypeInfo& type) {
  return fail("array of %" PRIu64 " empty elements", type.count);
}
bool PayloadReader::container_too_long(std::uint32_t count) {
  return fail("container count %u exceeds the payload", count);
}
bool PayloadReader::invalid_flag(const TypeInfo& type, std::uint8_t flag) {
  return fail("%s flag %u", type.kind == Kind::Optional ? "optional" : "unique_ptr", flag);
}
bool PayloadReader::invalid_alternative(std::uint32_t index) {
  return fail("variant index %u", index);
}
bool PayloadReader::shared_outside() { return fail("shared_ptr marked as outside"); }
bool PayloadReader::too_deep() {
  return fail("values nest deeper than the nesting limit of %d levels", kMaxValueNesting);
}
bool PayloadReader::invalid_reference(std::uint32_t i, const char* what, std::uint32_t value) {
  return fail("reference %u %s %u", i, what, value);
}
bool PayloadReader::missing_base(std::uint32_t i, const Reference& ref) {
  if (ref.base == kBaseObject) return fail("reference %u to a missing object %u", i, ref.a);
  return fail("reference %u to a missing element %u of container %u", i, ref.b, ref.a);
}
bool PayloadReader::wrong_target(std::uint32_t i, std::uint32_t type, std::uint32_t target) {
  return fail("reference %u: steps end at type %u, not %u", i, type, target);
}

bool PayloadReader::fail(const char* format, ...) {
  va_list args;
  va_start(args, format);
  set_corrupt_payload(error_, format, args);
  va_end(args);
  return false;
}

}  // namespace symcr::detail
