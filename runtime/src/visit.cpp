// Decoding a payload against its writer schema alone, for the CLI (inspect, diff): every
// scalar leaf is reported with its concrete path and wire bytes; pointers with a textual
// target. Two walks: the first finds the reference table (which follows the values) and the
// paths of containers, the second reports the leaves.
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "engine.hpp"
#include "wire.hpp"

namespace symcr::detail {
namespace {

constexpr int kMaxDepth = 1000;

class Walker {
 public:
  Walker(const Schema& writer, const std::uint8_t* payload, std::size_t size, ValueVisitor& visitor)
      : w_(writer), payload_(payload), size_(size), visitor_(visitor) {}

  Status run() {
    emit_ = false;
    if (!walk_all()) return error_;
    if (!read_references()) return error_;
    if (!in_.at_end()) return fail("%zu bytes after the references", in_.remaining());
    emit_ = true;
    walk_all();
    return error_;
  }

 private:
  __attribute__((format(printf, 2, 3))) const Status& fail(const char* format, ...) {
    va_list args;
    va_start(args, format);
    set_corrupt_payload(error_, format, args);
    va_end(args);
    return error_;
  }
  __attribute__((noinline, cold)) bool truncated() { return fail("truncated at %s", path_.c_str()).ok(); }

  bool walk_all() {
    in_ = WireReader(payload_, size_);
    container_ordinal_ = 0;
    for (std::uint32_t r = 0; r < w_.root_count; ++r) {
      if (w_.roots[r].type >= w_.type_count) return fail("root type out of range").ok();
      path_ = w_.roots[r].name;
      if (!value(w_.roots[r].type, 0)) return false;
    }
    std::uint32_t heap_count = 0;
    if (!in_.read(heap_count)) return truncated();
    if (heap_count > in_.remaining() / 5) return fail("heap count %u", heap_count).ok();
    for (std::uint32_t h = 0; h < heap_count; ++h) {
      std::uint32_t type = 0;
      std::uint8_t owner = 0;
      if (!in_.read(type) || !in_.read(owner)) return truncated();
      if (type >= w_.type_count || owner > 1) return fail("heap object %u header", h).ok();
      if (!emit_) heap_types_.push_back(type);
      char name[64];
      std::snprintf(name, sizeof name, "heap#%u(", h);
      path_ = std::string(name) + w_.types[type].name + ")";
      if (!value(type, 0)) return false;
    }
    return true;
  }

  bool value(std::uint32_t type_index, int depth) {
    if (depth > kMaxDepth) return fail("nesting deeper than %d", kMaxDepth).ok();
    const TypeInfo& type = w_.types[type_index];
    const std::size_t mark = path_.size();
    const std::uint8_t* bytes = nullptr;
    switch (type.kind) {
      case Kind::Bool: case Kind::Int: case Kind::UInt: case Kind::Float: case Kind::Enum:
      case Kind::Union:
        if (!in_.bytes(type.size, bytes)) return truncated();
        if (type.kind == Kind::Bool && bytes[0] > 1) return fail("bool %u at %s", bytes[0], path_.c_str()).ok();
        if (emit_) visitor_.leaf(path_.c_str(), type, bytes, type.size, nullptr);
        return true;
      case Kind::Struct:
        for (std::uint32_t f = 0; f < type.field_count; ++f) {
          path_ += '.';
          path_ += type.fields[f].name;
          if (!value(type.fields[f].type, depth)) return false;
          path_.resize(mark);
        }
        return true;
      case Kind::Array:
        for (std::uint64_t i = 0; i < type.count; ++i) {
          char index[32];
          std::snprintf(index, sizeof index, "[%" PRIu64 "]", i);
          path_ += index;
          if (!value(type.element, depth)) return false;
          path_.resize(mark);
        }
        return true;
      case Kind::String: {
        std::uint32_t length = 0;
        const std::uint32_t width = w_.types[type.element].size;
        if (!in_.read(length) || length > in_.remaining() / width ||
            !in_.bytes(std::size_t{length} * width, bytes)) {
          return truncated();
        }
        if (emit_) visitor_.leaf(path_.c_str(), type, bytes, std::size_t{length} * width, nullptr);
        return true;
      }
      case Kind::Container: {
        std::uint32_t count = 0;
        if (!in_.read(count)) return truncated();
        if (count > in_.remaining() && count > (1u << 20)) return fail("container count %u", count).ok();
        const std::uint32_t ordinal = container_ordinal_++;
        if (!emit_) {
          container_paths_.push_back(path_);
          container_counts_.push_back(count);
          container_types_.push_back(type.element);
        }
        (void)ordinal;
        for (std::uint32_t i = 0; i < count; ++i) {
          char index[32];
          std::snprintf(index, sizeof index, "[%u]", i);
          path_ += index;
          if (!value(type.element, depth + 1)) return false;
          path_.resize(mark);
        }
        return true;
      }
      case Kind::Optional:
      case Kind::UniquePtr: {
        std::uint8_t present = 0;
        if (!in_.read(present)) return truncated();
        if (present > 1) return fail("presence flag %u at %s", present, path_.c_str()).ok();
        return present ? value(type.element, depth + 1) : true;
      }
      case Kind::Variant: {
        std::uint32_t index = 0;
        if (!in_.read(index)) return truncated();
        if (index == kNoType) return true;
        if (index >= type.alternative_count) return fail("variant index %u", index).ok();
        path_ += '<';
        path_ += w_.types[type.alternatives[index]].name;
        path_ += '>';
        const bool ok = value(type.alternatives[index], depth);
        path_.resize(mark);
        return ok;
      }
      case Kind::Pointer:
      case Kind::SharedPtr: {
        const std::uint8_t* code_bytes = nullptr;
        if (!in_.bytes(4, code_bytes)) return truncated();
        std::uint32_t code = 0;
        std::memcpy(&code, code_bytes, 4);
        if (emit_) {
          const char* text = "null";
          if (code == 1) text = "outside";
          if (code >= 2) text = code - 2 < targets_.size() ? targets_[code - 2].c_str() : "-> ?";
          visitor_.leaf(path_.c_str(), type, code_bytes, 4, text);
        }
        return true;
      }
    }
    return fail("unknown kind").ok();
  }

  bool read_references() {
    std::uint32_t count = 0;
    if (!in_.read(count)) return truncated();
    if (count > in_.remaining() / 11) return fail("reference count %u", count).ok();
    for (std::uint32_t i = 0; i < count; ++i) {
      std::uint8_t base = 0;
      std::uint32_t a = 0, b = 0, type = 0;
      std::uint16_t steps = 0;
      if (!in_.read(base) || !in_.read(a) || base > 1 || (base == 1 && !in_.read(b)) ||
          !in_.read(steps)) {
        return fail("reference %u", i).ok();
      }
      std::string text = "-> ";
      char buffer[64];
      if (base == 0 && a < w_.root_count) {
        text += w_.roots[a].name;
        type = w_.roots[a].type;
      } else if (base == 0 && a - w_.root_count < heap_types_.size()) {
        type = heap_types_[a - w_.root_count];
        std::snprintf(buffer, sizeof buffer, "heap#%u(", a - w_.root_count);
        text += buffer;
        text += w_.types[type].name;
        text += ')';
      } else if (base == 1 && a < container_paths_.size() && b < container_counts_[a]) {
        std::snprintf(buffer, sizeof buffer, "[%u]", b);
        text += container_paths_[a] + buffer;
        type = container_types_[a];
      } else {
        return fail("reference %u to a missing object", i).ok();
      }
      for (std::uint16_t s = 0; s < steps; ++s) {
        std::uint32_t step = 0;
        if (!in_.read(step)) return truncated();
        const TypeInfo& t = w_.types[type];
        if (t.kind == Kind::Struct && step < t.field_count) {
          text += '.';
          text += t.fields[step].name;
          type = t.fields[step].type;
        } else if ((t.kind == Kind::Array && step < t.count) || t.kind == Kind::String) {
          std::snprintf(buffer, sizeof buffer, "[%u]", step);  // an element or a character
          text += buffer;
          type = t.element;
        } else if ((t.kind == Kind::Optional || t.kind == Kind::UniquePtr) && step == 0) {
          type = t.element;
        } else if (t.kind == Kind::Variant && step < t.alternative_count) {
          type = t.alternatives[step];
          text += '<';
          text += w_.types[type].name;
          text += '>';
        } else {
          return fail("reference %u has an invalid step", i).ok();
        }
      }
      std::uint32_t target = 0;
      if (!in_.read(target)) return truncated();
      if (target != type) return fail("reference %u ends at the wrong type", i).ok();
      targets_.push_back(std::move(text));
    }
    return true;
  }

  const Schema& w_;
  const std::uint8_t* payload_;
  std::size_t size_;
  ValueVisitor& visitor_;
  WireReader in_;
  Status error_;
  bool emit_ = false;
  std::string path_;
  std::uint32_t container_ordinal_ = 0;
  std::vector<std::uint32_t> heap_types_;
  std::vector<std::string> container_paths_;
  std::vector<std::uint32_t> container_counts_;
  std::vector<std::uint32_t> container_types_;
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
