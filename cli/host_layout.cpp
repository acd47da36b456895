#include "host_layout.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace symcr::cli {
namespace {

// ClockInfo::read takes no argument: one reading function per clock index, each returning its
// entry of the conversion's "now".
std::int64_t clock_now[HostLayout::kMaxClocks];
template <std::size_t I>
std::int64_t read_clock_now() {
  return clock_now[I];
}
template <std::size_t... I>
constexpr std::array<std::int64_t (*)(), sizeof...(I)> clock_readers(std::index_sequence<I...>) {
  return {{&read_clock_now<I>...}};
}
constexpr auto kClockReaders = clock_readers(std::make_index_sequence<HostLayout::kMaxClocks>());

bool is_clock_time(const FieldInfo& field) {
  return (field.flags & kFieldClockTime) != 0 && field.time != nullptr &&
         field.time->clock != nullptr;
}

constexpr int kMaxNesting = 64;  // as deep as a source nests types by value

std::uint32_t align_up(std::uint32_t value, std::uint32_t align) {
  return (value + align - 1) / align * align;
}

}  // namespace

Status HostLayout::extent_of(std::uint32_t t, int depth) {
  if (t >= build_->type_count || depth > kMaxNesting) {
    return Status(Error::Corrupt, "type index %u out of range or nested too deep", t);
  }
  Extent& extent = extents_[t];
  if (extent.done) return Status();
  const TypeInfo& type = build_->types[t];
  TypeInfo& ours = types_[t];
  std::uint32_t size = type.size, align = 1;
  switch (type.kind) {
    case Kind::Bool:
      size = 1;
      break;
    case Kind::Int:
    case Kind::UInt:
    case Kind::Enum:
    case Kind::Float:
      if (type.size == 0 || type.size > 16) {
        return Status(Error::Unsupported, "type '%s' has a size of %u bytes", type.name, type.size);
      }
      align = type.size > alignof(std::max_align_t) ? alignof(std::max_align_t) : type.size;
      break;
    case Kind::Union:  // raw bytes
      align = type.align == 0 || type.align > alignof(std::max_align_t) ? alignof(std::max_align_t)
                                                                        : type.align;
      break;
    case Kind::Pointer:
      size = sizeof(void*);
      align = alignof(void*);
      break;
    case Kind::Array: {
      const Status element = extent_of(type.element, depth + 1);
      if (!element.ok()) return element;
      const Extent& e = extents_[type.element];
      if (type.count > (UINT32_MAX / (e.size == 0 ? 1 : e.size))) {
        return Status(Error::TooLarge, "array '%s' is too large to lay out", type.name);
      }
      size = e.size * static_cast<std::uint32_t>(type.count);
      align = e.align;
      break;
    }
    case Kind::Struct: {
      // Members in order, each at its alignment; bit-fields that shared a storage unit in the
      // build (the same offset) share one here.
      std::vector<FieldInfo>& fields = fields_[t];
      fields.assign(type.fields, type.fields + type.field_count);
      std::uint32_t cursor = 0, unit = 0;
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        const Status member = extent_of(type.fields[f].type, depth + 1);
        if (!member.ok()) return member;
        const Extent& m = extents_[type.fields[f].type];
        const bool shares_unit = f > 0 && type.fields[f].bit_width != 0 &&
                                 type.fields[f - 1].bit_width != 0 &&
                                 type.fields[f].offset == type.fields[f - 1].offset;
        if (!shares_unit) unit = align_up(cursor, m.align);
        fields[f].offset = unit;
        if (unit + m.size > cursor) cursor = unit + m.size;
        if (m.align > align) align = m.align;
      }
      size = align_up(cursor == 0 ? 1 : cursor, align);
      ours.fields = fields.empty() ? nullptr : fields.data();
      // Reference members lie among members this layout leaves out: they have no place in it,
      // and a pointer to one is reported as not restored.
      ours.flags &= ~std::uint32_t{kTypeReferenceMembers};
      ours.reference_members = nullptr;
      ours.reference_member_count = 0;
      break;
    }
    default:
      return Status(Error::Unsupported,
                    "type '%s' needs the build's own code (a string, container, optional, "
                    "variant or smart pointer): only the device profile's kinds are converted",
                    type.name);
  }
  ours.size = size;
  ours.align = align;
  ours.ops = nullptr;
  ours.lifecycle = nullptr;
  ours.validate = nullptr;  // the build's code: its device runs it when it restores
  ours.migrate = nullptr;
  extent = Extent{size, align, true};
  return Status();
}

Status HostLayout::lay_out(const Schema& build, std::uint64_t input_size) {
  build_ = &build;
  types_.assign(build.types, build.types + build.type_count);
  fields_.assign(build.type_count, {});
  extents_.assign(build.type_count, Extent{});
  roots_.assign(build.roots, build.roots + build.root_count);
  memory_.clear();
  for (RootInfo& root : roots_) {
    const Status laid = extent_of(root.type, 0);
    if (!laid.ok()) return laid;
  }
  // Types reached only through pointers: laid out where they can be (a pointer's target is
  // found by its type); the others keep the build's numbers and no code, as in a schema file.
  for (std::uint32_t t = 0; t < build.type_count; ++t) {
    if (!extent_of(t, 0).ok()) {
      types_[t].ops = nullptr;
      types_[t].lifecycle = nullptr;
      types_[t].validate = nullptr;
      types_[t].migrate = nullptr;
    }
  }
  std::uint64_t total = 0;
  for (const RootInfo& root : roots_) total += extents_[root.type].size;
  if (total > kAlwaysAllowed && total / kBytesPerInputByte > input_size) {
    return Status(Error::TooLarge,
                  "the build's roots take %llu bytes, more than a conversion of %llu input bytes "
                  "lays out (%llu MiB, or %llu bytes per input byte)",
                  static_cast<unsigned long long>(total),
                  static_cast<unsigned long long>(input_size),
                  static_cast<unsigned long long>(kAlwaysAllowed >> 20),
                  static_cast<unsigned long long>(kBytesPerInputByte));
  }
  for (RootInfo& root : roots_) {
    const std::size_t size = extents_[root.type].size;
    const std::size_t cells = (size + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t);
    memory_.emplace_back(new std::max_align_t[cells == 0 ? 1 : cells]());
    root.address = memory_.back().get();
  }
  schema_ = Schema{types_.data(), build.type_count, roots_.data(), build.root_count, build.program};
  return Status();
}

Status HostLayout::read_clocks_as(const std::map<std::string, std::int64_t>& now) {
  if (!clocks_copied_) {
    std::uint32_t count = 0;
    std::size_t time_fields = 0;
    for (const std::vector<FieldInfo>& fields : fields_) {
      for (const FieldInfo& field : fields) {
        if (!is_clock_time(field)) continue;
        if (field.time->clock->index >= kMaxClocks) {
          return Status(Error::Unsupported, "the build has more than %u clocks", kMaxClocks);
        }
        if (field.time->clock->index >= count) count = field.time->clock->index + 1;
        ++time_fields;
      }
    }
    // Sized once, never again: the fields point into both (and the schema's cached facts
    // into clocks_).
    clocks_.assign(count, ClockInfo{nullptr, nullptr, 0});
    times_.reserve(time_fields);
    for (std::vector<FieldInfo>& fields : fields_) {
      for (FieldInfo& field : fields) {
        if (!is_clock_time(field)) continue;
        ClockInfo& ours = clocks_[field.time->clock->index];
        if (ours.name == nullptr) ours = *field.time->clock;
        times_.push_back(FieldTime{&ours, field.time->never});
        field.time = &times_.back();
      }
    }
    clocks_copied_ = true;
  }
  for (ClockInfo& clock : clocks_) {
    const auto found = clock.name != nullptr ? now.find(clock.name) : now.end();
    clock.read = found != now.end() ? kClockReaders[clock.index] : nullptr;
    if (found != now.end()) clock_now[clock.index] = found->second;
  }
  return Status();
}

}  // namespace symcr::cli
