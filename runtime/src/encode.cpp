// The save path (docs/format.md §3): walks live memory with the schema and writes values only.
// Pointers are memoised by (address, pointee type); each distinct target is classified once
// (inside a checkpointed region, outside, or a new heap object traversed breadth-first) and
// resolved at the end into a base object or container element plus symbolic steps.
//
// All scratch state lives in a per-thread object whose buffers keep their capacity, so a
// steady state allocates nothing.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include "encoder.hpp"

namespace symcr::detail {
namespace encoding {

// Heap objects are first kept out of the region index (the index is what makes a large
// graph slow); one sort at the end proves no heap object overlaps another region. When one
// does (a pointer into an object met before any pointer to the object), the save runs again
// with every heap object indexed, which resolves it or refuses it.
Status Encoder::run() {
  Status status = run_pass();
  if (status.ok() && overlap_suspected_) {
    exact_ = true;
    status = run_pass();
  }
  return status;
}

Status Encoder::run_pass() {
  s_.memo.clear();
  s_.buckets.clear();
  s_.chain.clear();
  s_.regions.clear();
  s_.large_regions.clear();
  s_.references.clear();
  s_.heap.clear();
  memory_refreshed_ = false;
  overlap_suspected_ = false;
  container_ordinal_ = 0;
  depth_ = 0;
  error_ = Status();
  pos_ = start_;

  for (std::uint32_t r = 0; r < schema_.root_count && ok(); ++r) {
    const RootInfo& root = schema_.roots[r];
    if (root.type >= schema_.type_count || !root.address) {
      return Status(Error::Unsupported, "root '%s' has no address or an invalid type", root.name);
    }
    const auto start = reinterpret_cast<std::uintptr_t>(root.address);
    if (track_references_) {
      add_region(
          Region{start, start + size_of(root.type), root.type, RegionKind::Object, r, 0, 0, 0, 0});
    }
  }
  for (std::uint32_t r = 0; r < schema_.root_count && ok(); ++r) {
    encode(schema_.roots[r].type, static_cast<const std::uint8_t*>(schema_.roots[r].address));
  }
  if (!ok()) return finish_error();

  const std::size_t heap_count_at = pos_;
  put_u32(0);
  // Breadth-first: classifying a target may create a heap object whose traversal appends
  // more references; the loop runs until no reference is left unclassified.
  for (std::size_t i = 0; i < s_.references.size() && ok(); ++i) {
    // Targets are visited in discovery order, far apart in memory: start loading a few
    // ahead so that their cache misses overlap.
    constexpr std::size_t kAhead = 8;
    if (i + kAhead < s_.references.size()) {
      __builtin_prefetch(reinterpret_cast<const void*>(s_.references[i + kAhead].address));
    }
    classify(i);
  }
  if (!ok()) return finish_error();
  if (!exact_ && track_regions_ && !s_.heap.empty() && heap_objects_overlap()) {
    overlap_suspected_ = true;
    out_.resize(start_);
    return Status();
  }
  check_shared_targets();
  if (!ok()) return finish_error();
  patch_u32(heap_count_at, static_cast<std::uint32_t>(s_.heap.size()));

  put_u32(static_cast<std::uint32_t>(s_.references.size()));
  for (std::size_t i = 0; i < s_.references.size() && ok() && !overlap_suspected_; ++i) {
    write_reference(i);
  }
  if (!ok()) return finish_error();
  if (overlap_suspected_) {
    out_.resize(start_);
    return Status();
  }
  out_.resize(pos_);
  return Status();
}

bool Encoder::heap_objects_overlap() {
  s_.spans.clear();
  for (const Region& region : s_.regions) s_.spans.push_back(Span{region.start, region.end});
  sort_spans();
  for (std::size_t i = 1; i < s_.spans.size(); ++i) {
    if (s_.spans[i].start < s_.spans[i - 1].end) return true;
  }
  return false;
}

// Sorts s_.spans by start. Large graphs: an LSD radix sort over the bits in which the starts
// differ (heap addresses span a few hundred MB: three 11-bit passes instead of N log N
// mispredicted comparisons).
void Encoder::sort_spans() {
  const std::size_t n = s_.spans.size();
  if (n < 2048) {
    std::sort(s_.spans.begin(), s_.spans.end(),
              [](const Span& a, const Span& b) { return a.start < b.start; });
    return;
  }
  std::uintptr_t low = s_.spans[0].start, high = low;
  for (const Span& span : s_.spans) {
    low = span.start < low ? span.start : low;
    high = span.start > high ? span.start : high;
  }
  const std::uintptr_t range = high - low;
  const int bits = range ? 64 - __builtin_clzll(static_cast<unsigned long long>(range)) : 0;
  constexpr int kDigitBits = 11;
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  s_.spans_scratch.resize(n);
  std::size_t counts[kDigits];
  for (int shift = 0; shift < bits; shift += kDigitBits) {
    const Span* from = s_.spans.data();
    Span* to = s_.spans_scratch.data();
    std::memset(counts, 0, sizeof counts);
    for (std::size_t i = 0; i < n; ++i) ++counts[((from[i].start - low) >> shift) & (kDigits - 1)];
    std::size_t sum = 0;
    for (std::size_t d = 0; d < kDigits; ++d) {
      const std::size_t c = counts[d];
      counts[d] = sum;
      sum += c;
    }
    for (std::size_t i = 0; i < n; ++i) {
      to[counts[((from[i].start - low) >> shift) & (kDigits - 1)]++] = from[i];
    }
    s_.spans.swap(s_.spans_scratch);  // both keep their capacity
  }
}

Status Encoder::finish_error() {
  out_.resize(start_);
  return error_;
}

std::uint8_t* Encoder::grow(std::size_t n) {
  if (__builtin_expect(out_.size() - pos_ < n, 0)) out_.resize(pos_ + n + kSlack);
  std::uint8_t* at = out_.data() + pos_;
  pos_ += n;
  return at;
}

void Encoder::put_bytes(const void* data, std::size_t n) {
  if (n >= kBulk) {
    out_.resize(pos_);  // drops the slack: trivially, nothing is freed
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out_.insert(out_.end(), bytes, bytes + n);
    pos_ += n;
    return;
  }
  if (n) std::memcpy(grow(n), data, n);
}

// Fixed-size copies compile to single moves; the generic memcpy call would dominate.
void Encoder::put_scalar(const std::uint8_t* p, std::uint32_t size) {
  switch (size) {
    case 1:
      *grow(1) = *p;
      return;
    case 2:
      std::memcpy(grow(2), p, 2);
      return;
    case 4:
      std::memcpy(grow(4), p, 4);
      return;
    case 8:
      std::memcpy(grow(8), p, 8);
      return;
    default:
      put_bytes(p, size);
      return;
  }
}

// ---- values --------------------------------------------------------------------------
void Encoder::encode(std::uint32_t type_index, const std::uint8_t* p) {
  const std::uint32_t first_run = facts_.flat_first[type_index];
  if (first_run != kNotFlat) {
    const FlatRun* run = facts_.flat_runs.data() + first_run;
    if (__builtin_expect(facts_.flat_wire_size[type_index] >= kBulk, 0)) {
      for (std::uint32_t r = facts_.flat_count[type_index]; r > 0; --r, ++run) {
        put_bytes(p + run->offset, run->length);
      }
      return;
    }
    std::uint8_t* at = grow(facts_.flat_wire_size[type_index]);
    for (std::uint32_t r = facts_.flat_count[type_index]; r > 0; --r, ++run) {
      std::memcpy(at, p + run->offset, run->length);
      at += run->length;
    }
    return;
  }
  const TypeInfo& type = types_[type_index];
  switch (type.kind) {
    case Kind::Bool:
      put_u8(*p != 0);
      return;
    case Kind::Int:
    case Kind::UInt:
    case Kind::Enum:
      put_scalar(p, type.size);
      return;
    case Kind::Float:
      if (type.size == 16) {  // x87 extended: 10 significant bytes, the rest is padding
        std::uint8_t* at = grow(16);
        std::memcpy(at, p, 10);
        std::memset(at + 10, 0, 6);
      } else {
        put_scalar(p, type.size);
      }
      return;
    case Kind::Union:
      put_bytes(p, type.size);
      return;
    case Kind::Struct:
      if (facts_.has_pointer_fields[type_index]) prefetch_references(type, p);
      for (std::uint32_t f = 0; f < type.field_count && ok(); ++f) {
        const FieldInfo& field = type.fields[f];
        const TypeInfo& field_type = types_[field.type];
        if (field.bit_width) {
          encode_bit_field(field, p);
        } else if (field_type.kind == Kind::Int || field_type.kind == Kind::UInt ||
                   field_type.kind == Kind::Enum) {
          put_scalar(p + field.offset, field_type.size);  // the common case, without a call
        } else {
          encode(field.type, p + field.offset);
        }
      }
      return;
    case Kind::Array: {
      const std::uint32_t stride = size_of(type.element);
      const TypeInfo& element = types_[type.element];
      if (element.kind == Kind::Int || element.kind == Kind::UInt ||
          (element.kind == Kind::Float && element.size != 16) || element.kind == Kind::Enum) {
        put_bytes(p, stride * type.count);  // packed scalars: one copy
        return;
      }
      for (std::uint64_t i = 0; i < type.count && ok(); ++i) encode(type.element, p + i * stride);
      return;
    }
    case Kind::String: {
      const auto* ops = static_cast<const StringOps*>(type.ops);
      const std::size_t length = ops->size(p);
      if (length > 0xFFFFFFFFu) return fail_unsupported("a string longer than 2^32 characters");
      put_u32(static_cast<std::uint32_t>(length));
      const void* data = ops->data(p);
      put_bytes(data, length * size_of(type.element));
      // Characters in a buffer of their own (not the string's inline one, which its object's
      // region covers) can be pointed into: index them, terminator position included.
      const auto start = reinterpret_cast<std::uintptr_t>(data);
      const auto object = reinterpret_cast<std::uintptr_t>(p);
      if (track_regions_ && (start < object || start >= object + type.size)) {
        add_region(Region{start, start + (length + 1) * size_of(type.element), type.element,
                          RegionKind::StringChars, 0, 0, 0, object, type_index});
      }
      return;
    }
    case Kind::Container:
      encode_container(type, p);
      return;
    case Kind::Optional: {
      const void* value = static_cast<const OptionalOps*>(type.ops)->get(p);
      put_u8(value != nullptr);
      if (value) encode(type.element, static_cast<const std::uint8_t*>(value));
      return;
    }
    case Kind::Variant: {
      const auto* ops = static_cast<const VariantOps*>(type.ops);
      const std::uint32_t index = ops->index(p);
      put_u32(index);
      if (index == kNoType) return;
      if (index >= type.alternative_count)
        return fail_unsupported("a variant index beyond its alternatives");
      encode(type.alternatives[index], static_cast<const std::uint8_t*>(ops->get(p)));
      return;
    }
    case Kind::UniquePtr: {
      const void* pointee = static_cast<const UniquePtrOps*>(type.ops)->get(p);
      put_u8(pointee != nullptr);
      if (!pointee) return;
      const auto start = reinterpret_cast<std::uintptr_t>(pointee);
      if (track_regions_) {
        add_region(Region{start, start + size_of(type.element), type.element, RegionKind::Owned, 0,
                          0, 0, reinterpret_cast<std::uintptr_t>(p), type_index});
      }
      descend_into(type.element, static_cast<const std::uint8_t*>(pointee));
      return;
    }
    case Kind::Pointer:
      encode_reference(type, *reinterpret_cast<const void* const*>(p), false);
      return;
    case Kind::SharedPtr:
      encode_reference(type, static_cast<const SharedPtrOps*>(type.ops)->get(p), true);
      return;
  }
}

void Encoder::descend_into(std::uint32_t type, const std::uint8_t* p) {
  if (++depth_ > kMaxValueNesting) {
    fail_unsupported(
        "nesting deeper than %d containers or unique_ptrs (use raw pointers "
        "or containers for long chains)",
        kMaxValueNesting);
  } else {
    encode(type, p);
  }
  --depth_;
}

void Encoder::prefetch_references(const TypeInfo& type, const std::uint8_t* p) const {
  for (std::uint32_t f = 0; f < type.field_count; ++f) {
    const FieldInfo& field = type.fields[f];
    const TypeInfo& field_type = types_[field.type];
    if (field_type.kind != Kind::Pointer || field.bit_width) continue;
    std::uintptr_t target;
    std::memcpy(&target, p + field.offset, sizeof target);
    if (target) s_.memo.prefetch(target, field_type.element);
  }
}

void Encoder::encode_bit_field(const FieldInfo& field, const std::uint8_t* p) {
  const TypeInfo& type = types_[field.type];
  const unsigned bytes = (field.bit_offset + field.bit_width + 7u) / 8u;
  if (bytes > 16 || field.bit_width > 64) return fail_unsupported("a bit-field wider than 64 bits");
  unsigned __int128 raw = 0;
  std::memcpy(&raw, p + field.offset, bytes);
  const std::uint64_t mask =
      field.bit_width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << field.bit_width) - 1;
  std::uint64_t value = static_cast<std::uint64_t>(raw >> field.bit_offset) & mask;
  const TypeInfo& integer = type.kind == Kind::Enum ? types_[type.element] : type;
  if (integer.kind == Kind::Int && field.bit_width < 64 && (value >> (field.bit_width - 1)) & 1u) {
    value |= ~mask;  // sign-extend
  }
  if (type.kind == Kind::Bool) value = value != 0;
  put_bytes(&value, type.size > 8 ? 8 : type.size);
}

void Encoder::visit_element(void* context, const void* element) {
  auto* walk = static_cast<ContainerWalk*>(context);
  Encoder& self = *walk->self;
  if (!self.ok()) return;
  if (self.track_regions_) {
    const auto address = reinterpret_cast<std::uintptr_t>(element);
    if (walk->run_start != 0 && address == walk->run_end) {
      walk->run_end += walk->stride;
    } else {
      self.flush_run(*walk);
      walk->run_start = address;
      walk->run_end = address + walk->stride;
      walk->run_first = walk->index;
    }
  }
  ++walk->index;
  self.descend_into(walk->element_type, static_cast<const std::uint8_t*>(element));
}

void Encoder::flush_run(ContainerWalk& walk) {
  if (walk.run_start == 0) return;
  add_region(Region{walk.run_start, walk.run_end, walk.element_type, RegionKind::ContainerRun,
                    walk.ordinal, walk.run_first, walk.stride, 0, 0});
  walk.run_start = 0;
}

void Encoder::encode_container(const TypeInfo& type, const std::uint8_t* p) {
  const auto* ops = static_cast<const ContainerOps*>(type.ops);
  const std::size_t count = ops->size(p);
  if (count > 0xFFFFFFFFu) return fail_unsupported("a container with more than 2^32 elements");
  put_u32(static_cast<std::uint32_t>(count));
  // Contiguous fixed-width little-endian scalars (wire width == size): one block.
  if (ops->contiguous_data && count > 0 && depth_ < kMaxValueNesting) {
    const TypeInfo& element = types_[type.element];
    if (element.kind == Kind::Int || element.kind == Kind::UInt || element.kind == Kind::Enum ||
        (element.kind == Kind::Float && element.size != 16)) {
      const auto* data = static_cast<const std::uint8_t*>(ops->contiguous_data(p));
      const std::uint32_t ordinal = container_ordinal_++;
      if (track_regions_) {
        const auto start = reinterpret_cast<std::uintptr_t>(data);
        add_region(Region{start, start + count * element.size, type.element,
                          RegionKind::ContainerRun, ordinal, 0, element.size, 0, 0});
      }
      put_bytes(data, count * element.size);
      return;
    }
  }
  ContainerWalk walk{this, type.element, container_ordinal_++, size_of(type.element), 0, 0, 0, 0};
  ops->for_each(p, &Encoder::visit_element, &walk);
  if (ok() && walk.index != count) {
    return fail_unsupported("a container whose size() disagrees with its iteration");
  }
  if (track_regions_ && ok()) flush_run(walk);
}

// ---- references ----------------------------------------------------------------------
void Encoder::encode_reference(const TypeInfo& type, const void* target, bool shared) {
  if (!target) return put_u32(kNullCode);
  const auto address = reinterpret_cast<std::uintptr_t>(target);
  bool inserted = false;
  std::uint32_t& entry = s_.memo.find_or_insert(address, type.element, kNoRegion, inserted);
  if (inserted) {
    if (!shared && is_outside(address)) {
      entry = kOutside;
    } else {
      entry = static_cast<std::uint32_t>(s_.references.size());
      s_.references.push_back(PointerTarget{address, type.element, kNoRegion, shared});
    }
  }
  if (entry == kOutside) {
    if (shared) {
      return fail_unsupported("a shared_ptr into static storage or the stack (object %p)", target);
    }
    return put_u32(kOutsideCode);
  }
  if (shared) s_.references[entry].shared = true;
  put_u32(entry + kFirstReference);
}

void Encoder::fail_unsupported(const char* format, ...) {
  if (!ok()) return;
  char buffer[200];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  error_ = Status(Error::Unsupported, "cannot save %s", buffer);
}

}  // namespace encoding

namespace {

using encoding::Encoder;
using encoding::EncodeScratch;

EncodeScratch& thread_encode_scratch() {
  thread_local EncodeScratch scratch;
  return scratch;
}

template <typename T>
std::size_t capacity_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace

std::size_t encode_scratch_bytes() {
  const EncodeScratch& s = thread_encode_scratch();
  return s.memo.capacity_bytes() + s.buckets.capacity_bytes() + capacity_bytes(s.chain) +
         capacity_bytes(s.regions) + capacity_bytes(s.large_regions) +
         capacity_bytes(s.references) + capacity_bytes(s.heap) + capacity_bytes(s.steps) +
         capacity_bytes(s.spans) + capacity_bytes(s.spans_scratch);
}

Status append_payload(const Schema& schema, std::vector<std::uint8_t>& out) {
  const SchemaCacheEntry& cached = schema_cache_entry(schema);
  EncodeScratch& scratch = thread_encode_scratch();
  const std::size_t start = out.size();
  Encoder encoder(schema, out, scratch, cached.facts);
  encoder.start_ = start;
  return encoder.run();
}

Status encode_payload(const Schema& schema, std::vector<std::uint8_t>& out) {
  out.clear();
  return append_payload(schema, out);
}

}  // namespace symcr::detail
