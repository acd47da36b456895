// The save path (docs/format.md §3): walks live memory with the schema and writes values only.
// Pointers are memoised by (address, pointee type); each distinct target is classified once
// (inside a checkpointed region, outside, or a new heap object traversed breadth-first) and
// resolved at the end into a base object or container element plus symbolic steps.
//
// All scratch state lives in a per-thread object whose buffers keep their capacity, so a
// steady state allocates nothing.
//
// One file, unlike restore and the planner: the encoder runs on every checkpoint, and its class
// must have internal linkage for GCC to inline its passes and value walk (split across files,
// the specimen's save measured 10% slower).
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include "address_table.hpp"
#include "clocks.hpp"
#include "crc32c.hpp"
#include "encode.hpp"
#include "payload_grammar.hpp"
#include "process_memory.hpp"
#include "schema_facts.hpp"
#include "scratch.hpp"

namespace symcr::detail {
namespace {

constexpr std::uint32_t kNoRegion = 0xFFFFFFFFu;
constexpr std::uint32_t kOutside = 0xFFFFFFFEu;  // memo value: target outside the state
constexpr unsigned kBucketShift = 6;             // region index granularity: 64 bytes
constexpr std::uintptr_t kLargeRegion = std::uintptr_t{64} << 10;  // indexed in a list instead

enum class RegionKind : std::uint8_t {
  Object,        // a root or heap object: `object` is its object number
  ContainerRun,  // contiguous elements of one container, from `first_index`
  Owned,         // a unique_ptr's pointee, reached through the unique_ptr at `owner_slot`
  StringChars,   // a string's heap buffer, reached through the string at `owner_slot`
};

struct Region {
  std::uintptr_t start, end;
  std::uint32_t type;  // Object/Owned: the object's type; ContainerRun: the element type
  RegionKind kind;
  std::uint32_t object;  // Object: object number; ContainerRun: container ordinal
  std::uint32_t first_index;
  std::uint32_t stride;
  std::uintptr_t owner_slot;
  std::uint32_t owner_type;
};

// A distinct (address, pointee type) a saved pointer holds: one reference-table entry.
struct PointerTarget {
  std::uintptr_t address;
  std::uint32_t type;    // pointee type
  std::uint32_t region;  // after classification
  bool shared;           // some shared_ptr holds this target
  bool may_own = false;  // some pointer not declared never-owning (kTypeNeverOwns) holds it
  // The first never-owning pointer holding it (its address and Pointer type), to name it when
  // the target turns out to be a heap object; kNoType when none.
  std::uintptr_t never_owner_slot = 0;
  std::uint32_t never_owner_type = kNoType;
};

struct HeapObject {
  std::uint32_t region;
  std::size_t owner_byte;  // payload offset of its owner byte (patched for shared targets)
};

struct ChainLink {  // the region's bounds are copied here: lookups touch no Region
  std::uintptr_t start, end;
  std::uint32_t region;
  std::uint32_t next;
};

struct Span {
  std::uintptr_t start, end;
};

// A heap object that encloses another object met before it (a pointer into a Node met before
// the pointer to the Node): created first in the next pass, so the earlier pointer becomes a
// path into it.
struct Enclosure {
  std::uintptr_t start;
  std::uint32_t type;
};

struct EncodeScratch {
  AddressTable memo;     // (address, pointee type) -> reference index or kOutside
  AddressTable buckets;  // (address >> kBucketShift, 0) -> first ChainLink
  std::vector<ChainLink> chain;
  std::vector<Region> regions;
  std::vector<std::uint32_t> large_regions;
  std::vector<PointerTarget> references;
  std::vector<HeapObject> heap;
  std::vector<std::uint32_t> steps;
  std::vector<Span> spans;          // overlap check of the fast pass
  std::vector<Span> spans_scratch;  // its radix sort's other buffer
  std::vector<Enclosure> enclosures;
  ProcessMemory memory;
};

class Encoder {
 public:
  Encoder(const Schema& schema, std::vector<std::uint8_t>& out, EncodeScratch& scratch,
          const SchemaFacts& facts)
      : schema_(schema),
        types_(schema.types),
        out_(out),
        pos_(out.size()),
        s_(scratch),
        track_regions_(facts.has_raw_pointers),
        track_references_(facts.has_references),
        facts_(facts) {}

  // Heap objects are first kept out of the region index (the index is what makes a large
  // graph slow); one sort at the end proves no heap object overlaps another region. When one
  // does (a pointer into an object met before any pointer to the object), the save runs again
  // with every heap object indexed. A heap object found to enclose one made earlier is
  // remembered, and the save runs again creating it first: the earlier pointer then refers
  // into it. Each rerun learns at least one enclosure, and a chain of nested enclosures is
  // learned from the inside out, so the reruns are bounded; overlaps that are not enclosures
  // are refused.
  Status run() {
    s_.enclosures.clear();
    Status status = run_pass();
    if (status.ok() && overlap_suspected_) {
      exact_ = true;
      constexpr int kMaxReruns = 64;
      for (int rerun = 0; (status = run_pass()).ok() && refold_; ++rerun) {
        if (rerun == kMaxReruns) {
          return Status(Error::Unsupported,
                        "cannot save: pointers into heap objects nest more than %d levels of "
                        "enclosing objects met after them",
                        kMaxReruns);
        }
      }
    }
    return status;
  }

 private:
  Status run_pass() {
    s_.memo.clear();
    s_.buckets.clear();
    s_.chain.clear();
    s_.regions.clear();
    s_.large_regions.clear();
    s_.references.clear();
    s_.heap.clear();
    memory_refreshed_ = false;
    overlap_suspected_ = false;
    refold_ = false;
    encoding_heap_ = kNoRegion;
    container_ordinal_ = 0;
    depth_ = 0;
    error_ = Status();
    pos_ = payload_start;
    fused_crc_ = 0;
    fused_to_ = payload_start;
    fused_ = false;
    fused_valid_ = true;

    for (std::uint32_t r = 0; r < schema_.root_count && ok(); ++r) {
      const RootInfo& root = schema_.roots[r];
      if (root.type >= schema_.type_count || !root.address) {
        return Status(Error::Unsupported, "root '%s' has no address or an invalid type", root.name);
      }
      const auto start = reinterpret_cast<std::uintptr_t>(root.address);
      if (track_references_) {
        add_region(Region{start, start + size_of(root.type), root.type, RegionKind::Object, r, 0, 0,
                          0, 0});
      }
    }
    for (std::uint32_t r = 0; r < schema_.root_count && ok(); ++r) {
      encode_object(schema_.roots[r].type,
                    static_cast<const std::uint8_t*>(schema_.roots[r].address));
    }
    if (!ok()) return finish_error();

    const std::size_t heap_count_at = pos_;
    put_u32(0);
    // The enclosing objects learned by an earlier pass, before any pointer into them.
    for (std::size_t e = 0; e < s_.enclosures.size() && ok(); ++e) {
      const Enclosure enclosure = s_.enclosures[e];
      if (find_region(enclosure.start) == kNoRegion) {
        new_heap_object(PointerTarget{enclosure.start, enclosure.type, kNoRegion, false});
      }
    }
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
    if (refold_) {
      out_.resize(payload_start);
      return Status();
    }
    if (!exact_ &&
        (overlap_suspected_ || (track_regions_ && !s_.heap.empty() && heap_objects_overlap()))) {
      overlap_suspected_ = true;
      out_.resize(payload_start);
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
      out_.resize(payload_start);
      return Status();
    }
    if (!facts_.clocks.empty()) put_clock_readings();
    out_.resize(pos_);
    return Status();
  }

  // The clocks' readings end the payload (docs/format.md §3), after everything they describe
  // was read from memory.
  void put_clock_readings() {
    if (given_readings != nullptr) {
      const std::size_t size = format::clock_readings_size(given_readings->count);
      std::memcpy(grow(size), given_readings->bytes, size);
      return;
    }
    format::store64(grow(format::kClockEpochSize), process_epoch());
    for (const ClockInfo* clock : facts_.clocks) {
      const std::int64_t reading = clock && clock->read ? clock->read() : 0;
      format::store64(grow(format::kClockReadingSize), static_cast<std::uint64_t>(reading));
    }
  }

  bool heap_objects_overlap() {
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
  void sort_spans() {
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
      for (std::size_t i = 0; i < n; ++i)
        ++counts[((from[i].start - low) >> shift) & (kDigits - 1)];
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

  bool ok() const { return error_.ok(); }
  Status finish_error() {
    out_.resize(payload_start);
    return error_;
  }
  std::uint32_t size_of(std::uint32_t type) const { return types_[type].size; }

  // ---- output --------------------------------------------------------------------------
  // out_ holds pos_ bytes written plus a little zero-filled slack (std::vector cannot grow
  // without value-initialising). The vector's capacity grows geometrically on its own, so the
  // slack only bounds how much is zero-filled ahead of use; large copies are appended without
  // any zero-fill.
  static constexpr std::size_t kSlack = 1024;
  static constexpr std::size_t kBulk = 4096;  // put_bytes at least this large: append directly
  std::uint8_t* grow(std::size_t n) {
    if (__builtin_expect(out_.size() - pos_ < n, 0)) out_.resize(pos_ + n + kSlack);
    std::uint8_t* at = out_.data() + pos_;
    pos_ += n;
    return at;
  }
  void put_bytes(const void* data, std::size_t n) {
    if (n >= kBulk) {
      const auto* bytes = static_cast<const std::uint8_t*>(data);
      if (n >= kFuseMin && fused_valid_) return put_fused(bytes, n);
      if (out_.size() - pos_ >= n) {
        std::memcpy(out_.data() + pos_, bytes, n);  // over an earlier record's bytes
      } else {
        out_.resize(pos_);  // drops the slack: trivially, nothing is freed
        out_.insert(out_.end(), bytes, bytes + n);
      }
      pos_ += n;
      return;
    }
    if (n) std::memcpy(grow(n), data, n);
  }
  void put_u8(std::uint8_t v) { *grow(1) = v; }
  // Fixed-size copies compile to single moves; the generic memcpy call would dominate.
  void put_scalar(const std::uint8_t* p, std::uint32_t size) {
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
  void put_u16(std::uint16_t v) { std::memcpy(grow(2), &v, 2); }
  void put_u32(std::uint32_t v) { std::memcpy(grow(4), &v, 4); }
  void patch_u32(std::size_t at, std::uint32_t v) {
    patched(at);
    std::memcpy(out_.data() + at, &v, 4);
  }

  // ---- the payload's CRC-32C, fused with large copies ----------------------------------
  // A copy of kFuseMin bytes or more is checksummed as it is made, together with the bytes
  // written before it; the record's CRC then combines the payload's (encode_record_as) instead
  // of reading the payload once more. Where the buffer already holds bytes (an earlier record
  // in the same buffer: periodic checkpoints), they are overwritten by one pass that loads,
  // checksums and stores each word (crc32c_copy). A buffer that must grow is appended to chunk
  // by chunk (std::vector cannot grow without writing its new bytes), each chunk checksummed
  // right after it was copied, while still in cache.
  static constexpr std::size_t kFuseMin = std::size_t{1} << 20;
  static constexpr std::size_t kFuseChunk = std::size_t{64} * 1024;
  void put_fused(const std::uint8_t* bytes, std::size_t n) {
    fused_crc_ = crc32c_extend(fused_crc_, out_.data() + fused_to_, pos_ - fused_to_);
    if (out_.size() - pos_ >= n) {
      fused_crc_ = crc32c_copy(fused_crc_, out_.data() + pos_, bytes, n);
    } else {
      out_.resize(pos_);
      if (out_.capacity() < pos_ + n + kSlack) out_.reserve(pos_ + n + kSlack);  // one growth
      for (std::size_t done = 0; done < n;) {
        const std::size_t length = n - done < kFuseChunk ? n - done : kFuseChunk;
        out_.insert(out_.end(), bytes + done, bytes + done + length);
        fused_crc_ = crc32c_extend(fused_crc_, out_.data() + pos_ + done, length);
        done += length;
      }
    }
    pos_ += n;
    fused_to_ = pos_;
    fused_ = true;
  }
  // A byte at `at` written again: a CRC already over it no longer holds.
  void patched(std::size_t at) {
    if (at < fused_to_) fused_valid_ = false;
  }

 public:
  // After run(): the payload's CRC-32C when a large copy computed most of it on the way.
  bool fused_payload_crc(std::uint32_t& crc) const {
    if (!fused_ || !fused_valid_ || !ok()) return false;
    crc = crc32c_extend(fused_crc_, out_.data() + fused_to_, pos_ - fused_to_);
    return true;
  }

 private:
  // ---- values --------------------------------------------------------------------------
  void encode(std::uint32_t type_index, const std::uint8_t* p) {
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
          add_region(Region{start, start + size_of(type.element), type.element, RegionKind::Owned,
                            0, 0, 0, reinterpret_cast<std::uintptr_t>(p), type_index});
        }
        descend_into(type.element, static_cast<const std::uint8_t*>(pointee));
        return;
      }
      case Kind::Pointer:
        encode_reference(type, *reinterpret_cast<const void* const*>(p), false);
        if (ok() && (type.flags & kTypeNeverOwns)) note_never_owner(type_index, p);
        return;
      case Kind::SharedPtr:
        encode_reference(type, static_cast<const SharedPtrOps*>(type.ops)->get(p), true);
        return;
    }
  }

  // Values are charged against the nesting limit as every reader charges them
  // (payload_grammar.hpp): a root or heap object its type's by-value levels, a container's
  // element or a unique_ptr's pointee one more level and its own type's.
  void encode_object(std::uint32_t type, const std::uint8_t* p) {
    const int outer = depth_;
    depth_ = static_cast<int>(facts_.nesting_levels[type]);
    encode_within_limit(type, p);
    depth_ = outer;
  }
  void descend_into(std::uint32_t type, const std::uint8_t* p) {
    const int outer = depth_;
    depth_ = element_depth(type);
    encode_within_limit(type, p);
    depth_ = outer;
  }
  int element_depth(std::uint32_t type) const {
    return depth_ + 1 + static_cast<int>(facts_.nesting_levels[type]);
  }
  void encode_within_limit(std::uint32_t type, const std::uint8_t* p) {
    if (depth_ > kMaxValueNesting) {
      fail_unsupported(
          "values nested deeper than the nesting limit of %d levels (use raw pointers for "
          "long chains)",
          kMaxValueNesting);
    } else {
      encode(type, p);
    }
  }

  void prefetch_references(const TypeInfo& type, const std::uint8_t* p) const {
    for (std::uint32_t f = 0; f < type.field_count; ++f) {
      const FieldInfo& field = type.fields[f];
      const TypeInfo& field_type = types_[field.type];
      if (field_type.kind != Kind::Pointer || field.bit_width) continue;
      std::uintptr_t target;
      std::memcpy(&target, p + field.offset, sizeof target);
      if (target) s_.memo.prefetch(target, field_type.element);
    }
  }

  __attribute__((noinline)) void encode_bit_field(const FieldInfo& field, const std::uint8_t* p) {
    const TypeInfo& type = types_[field.type];
    const unsigned bytes = (field.bit_offset + field.bit_width + 7u) / 8u;
    if (bytes > 16 || field.bit_width > 64)
      return fail_unsupported("a bit-field wider than 64 bits");
    unsigned __int128 raw = 0;
    std::memcpy(&raw, p + field.offset, bytes);
    const std::uint64_t mask =
        field.bit_width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << field.bit_width) - 1;
    std::uint64_t value = static_cast<std::uint64_t>(raw >> field.bit_offset) & mask;
    const TypeInfo& integer = type.kind == Kind::Enum ? types_[type.element] : type;
    if (integer.kind == Kind::Int && field.bit_width < 64 &&
        (value >> (field.bit_width - 1)) & 1u) {
      value |= ~mask;  // sign-extend
    }
    if (type.kind == Kind::Bool) value = value != 0;
    put_bytes(&value, type.size > 8 ? 8 : type.size);
  }

  struct ContainerWalk {
    Encoder* self;
    std::uint32_t element_type;
    std::uint32_t ordinal;
    std::uint32_t stride;
    std::uint32_t index;
    std::uint32_t run_first;
    std::uintptr_t run_start;
    std::uintptr_t run_end;
  };

  static void visit_element(void* context, const void* element) {
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

  void flush_run(ContainerWalk& walk) {
    if (walk.run_start == 0) return;
    add_region(Region{walk.run_start, walk.run_end, walk.element_type, RegionKind::ContainerRun,
                      walk.ordinal, walk.run_first, walk.stride, 0, 0});
    walk.run_start = 0;
  }

  __attribute__((noinline)) void encode_container(const TypeInfo& type, const std::uint8_t* p) {
    const auto* ops = static_cast<const ContainerOps*>(type.ops);
    const std::size_t count = ops->size(p);
    if (count > 0xFFFFFFFFu) return fail_unsupported("a container with more than 2^32 elements");
    put_u32(static_cast<std::uint32_t>(count));
    // Contiguous fixed-width little-endian scalars (wire width == size): one block.
    if (ops->contiguous_data && count > 0 && element_depth(type.element) <= kMaxValueNesting) {
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
  __attribute__((noinline)) void encode_reference(const TypeInfo& type, const void* target,
                                                  bool shared) {
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
    if (entry != kOutside && !(type.flags & kTypeNeverOwns)) s_.references[entry].may_own = true;
    if (entry == kOutside) {
      if (shared) {
        return fail_unsupported("a shared_ptr into static storage or the stack (object %p)",
                                target);
      }
      return put_u32(kOutsideCode);
    }
    if (shared) s_.references[entry].shared = true;
    put_u32(entry + kFirstReference);
  }

  bool is_outside(std::uintptr_t address) {
    // Roots (and container elements, unique_ptr pointees) are indexed when raw pointers exist.
    if ((track_regions_ ? find_region(address) : find_root(address)) != kNoRegion) return false;
    if (!memory_refreshed_) {
      s_.memory.refresh();
      memory_refreshed_ = true;
    }
    return s_.memory.is_static_or_stack(address);
  }

  std::uint32_t find_root(std::uintptr_t address) const {
    for (std::uint32_t r = 0; r < schema_.root_count; ++r) {
      const auto start = reinterpret_cast<std::uintptr_t>(schema_.roots[r].address);
      if (address >= start && address < start + size_of(schema_.roots[r].type)) return r;
    }
    return kNoRegion;
  }

  // A never-owning pointer's target: remembered until classified (only the last one written
  // can be it: encode_reference appended or found it just before).
  void note_never_owner(std::uint32_t pointer_type, const std::uint8_t* slot) {
    const void* target = *reinterpret_cast<const void* const*>(slot);
    if (!target) return;
    bool inserted = false;
    const std::uint32_t entry =
        s_.memo.find_or_insert(reinterpret_cast<std::uintptr_t>(target),
                               types_[pointer_type].element, kNoRegion, inserted);
    if (entry == kOutside || entry >= s_.references.size()) return;
    PointerTarget& reference = s_.references[entry];
    if (reference.never_owner_type != kNoType) return;
    reference.never_owner_slot = reinterpret_cast<std::uintptr_t>(slot);
    reference.never_owner_type = pointer_type;
  }

  // "vehicle.flightmode": the path of the pointer at `slot` (of Pointer type `type`), or its
  // address when it lies in no indexed region.
  __attribute__((cold)) void slot_path(std::uintptr_t slot, std::uint32_t type, char* out,
                                       std::size_t size) {
    std::snprintf(out, size, "the pointer at %p", reinterpret_cast<const void*>(slot));
    const std::uint32_t region = find_region(slot);
    Base base{};
    s_.steps.clear();
    if (region == kNoRegion || !resolve(region, slot, type, base, 0)) return;
    std::string path;
    std::uint32_t at = kNoType;
    if (base.kind == kBaseObject && base.a < schema_.root_count) {
      path = schema_.roots[base.a].name;
      at = schema_.roots[base.a].type;
    } else {
      const Region& r = s_.regions[region];
      char where[120];
      describe(r, where, sizeof where);
      path = where;
      at = r.type;
    }
    for (std::uint32_t step : s_.steps) {
      const TypeInfo& t = types_[at];
      const FieldInfo* member = t.kind == Kind::Struct ? step_member(t, step) : nullptr;
      if (member) {
        path += ".";
        path += member->name;
        at = member->type;
      } else {
        path += "[" + std::to_string(step) + "]";
        at = t.kind == Kind::Variant ? t.alternatives[step] : t.element;
      }
    }
    s_.steps.clear();
    std::snprintf(out, size, "%s", path.c_str());
  }

  void classify(std::size_t i) {
    const PointerTarget reference = s_.references[i];
    // Without raw pointers every target is a shared_ptr's whole object, deduplicated by the
    // memo already: no region lookup is needed.
    std::uint32_t region = track_regions_ ? find_region(reference.address) : kNoRegion;
    if (region == kNoRegion && !reference.may_own && reference.never_owner_type != kNoType) {
      char path[160];
      slot_path(reference.never_owner_slot, reference.never_owner_type, path, sizeof path);
      return fail_unsupported(
          "%s, declared never to own a heap object (SYMCR_NOT_OWNER / not_owner), points at a "
          "%s at %p on the heap, outside the checkpointed state",
          path, types_[reference.type].name, reinterpret_cast<const void*>(reference.address));
    }
    if (region == kNoRegion) {
      region = new_heap_object(reference);
    } else if (exact_) {
      // A heap object made earlier for a pointer to this object's first member: this object
      // encloses it.
      const Region& found = s_.regions[region];
      const Region target{reference.address,
                          reference.address + size_of(reference.type),
                          reference.type,
                          RegionKind::Object,
                          0,
                          0,
                          0,
                          0,
                          0};
      if (found.end < target.end) fold(target, /*heap_object=*/true, found);
    }
    s_.references[i].region = region;
  }

  std::uint32_t new_heap_object(const PointerTarget& reference) {
    std::uintptr_t start = reference.address;
    std::uint32_t type = reference.type;
    if (types_[type].flags & kTypePolymorphic) {
      // Saved as its dynamic type, or refused: an object of the static type would be sliced.
      if (!dynamic_type(start, type)) {
        char candidates[80];
        list_dynamic_types(reference.type, candidates, sizeof candidates);
        fail_unsupported(
            "a pointer to polymorphic class %s at %p: its object is no member or "
            "element of the state, and not of a class this build can create (%s)",
            types_[reference.type].name, reinterpret_cast<const void*>(reference.address),
            candidates);
        return 0;
      }
    }
    const std::uint32_t object = schema_.root_count + static_cast<std::uint32_t>(s_.heap.size());
    const std::uint32_t region = add_region(
        Region{start, start + size_of(type), type, RegionKind::Object, object, 0, 0, 0, 0},
        /*heap_object=*/true);
    if (!ok()) return region;
    put_u32(type);
    s_.heap.push_back(HeapObject{region, pos_});
    put_u8(reference.shared ? format::kHeapOwnerShared : format::kHeapOwnerRaw);
    encoding_heap_ = region;
    encode_object(type, reinterpret_cast<const std::uint8_t*>(start));
    encoding_heap_ = kNoRegion;
    return region;
  }

  // Itanium C++ ABI: an object's vtable pointer is its first word, and the word two before
  // the address it holds is the offset from this subobject to the complete object, whose own
  // vtable pointer identifies its class. On success, `address` and `type` are the complete
  // object's.
  bool dynamic_type(std::uintptr_t& address, std::uint32_t& type) const {
    const auto* vtable = *reinterpret_cast<const std::ptrdiff_t* const*>(address);
    const std::uintptr_t complete = address + static_cast<std::uintptr_t>(vtable[-2]);
    const void* complete_vtable = *reinterpret_cast<const void* const*>(complete);
    for (const SchemaFacts::DynamicType& candidate : facts_.dynamic_types) {
      if (candidate.vtable == complete_vtable) {
        address = complete;
        type = candidate.type;
        return true;
      }
    }
    return false;
  }

  __attribute__((cold)) void list_dynamic_types(std::uint32_t base, char* out,
                                                std::size_t size) const {
    std::size_t used = 0;
    out[0] = '\0';
    std::vector<std::uint32_t> pending;
    std::vector<bool> derived;  // the candidate and its bases
    for (const SchemaFacts::DynamicType& candidate : facts_.dynamic_types) {
      pending.assign(1, candidate.type);
      derived.clear();
      mark_with_bases(types_, schema_.type_count, pending, derived);
      if (!derived[base]) continue;
      const int n = std::snprintf(out + used, size - used, "%s%s", used ? ", " : "",
                                  types_[candidate.type].name);
      if (n < 0 || static_cast<std::size_t>(n) >= size - used) break;
      used += static_cast<std::size_t>(n);
    }
    if (used == 0) std::snprintf(out, size, "none derives from %s", types_[base].name);
  }

  // A shared_ptr target must be a whole heap object: sharing is kept by owning it.
  void check_shared_targets() {
    for (const PointerTarget& reference : s_.references) {
      if (!reference.shared) continue;
      const Region& region = s_.regions[reference.region];
      const bool whole_heap_object =
          region.kind == RegionKind::Object && region.object >= schema_.root_count &&
          region.start == reference.address && region.type == reference.type;
      if (!whole_heap_object) {
        return fail_unsupported(
            "a shared_ptr<%s> whose object (%p) lies inside another "
            "checkpointed object",
            types_[reference.type].name, reinterpret_cast<const void*>(reference.address));
      }
      const std::size_t owner_byte = s_.heap[region.object - schema_.root_count].owner_byte;
      patched(owner_byte);
      out_[owner_byte] = 1;
    }
  }

  // ---- the region index ----------------------------------------------------------------
  // Small regions are chained from every 64-byte bucket they touch; large ones sit in a list.
  std::uint32_t find_region(std::uintptr_t address) {
    if (std::uint32_t* head = s_.buckets.find(address >> kBucketShift, 0)) {
      for (std::uint32_t link = *head; link != kNoRegion; link = s_.chain[link].next) {
        const ChainLink& entry = s_.chain[link];
        if (address >= entry.start && address < entry.end) return entry.region;
      }
    }
    for (std::uint32_t index : s_.large_regions) {
      const Region& region = s_.regions[index];
      if (address >= region.start && address < region.end) return index;
    }
    return kNoRegion;
  }

  std::uint32_t overlapping(const Region& candidate) {
    for (std::uint32_t index : s_.large_regions) {
      const Region& region = s_.regions[index];
      if (candidate.start < region.end && region.start < candidate.end) return index;
    }
    const std::uintptr_t first = candidate.start >> kBucketShift;
    const std::uintptr_t last = (candidate.end - 1) >> kBucketShift;
    for (std::uintptr_t bucket = first; bucket <= last; ++bucket) {
      std::uint32_t* head = s_.buckets.find(bucket, 0);
      if (!head) continue;
      for (std::uint32_t link = *head; link != kNoRegion; link = s_.chain[link].next) {
        const ChainLink& entry = s_.chain[link];
        if (candidate.start < entry.end && entry.start < candidate.end) return entry.region;
      }
    }
    return kNoRegion;
  }

  std::uint32_t add_region(const Region& region, bool heap_object = false) {
    const auto index = static_cast<std::uint32_t>(s_.regions.size());
    if (!track_regions_ || (heap_object && !exact_)) {
      s_.regions.push_back(region);
      return index;
    }
    const std::uint32_t other = overlapping(region);
    if (other != kNoRegion) {
      // The fast pass may have made a heap object twice (its object unindexed), and after a
      // fold a pass's later overlaps may be its side effects: the next pass judges.
      if (!exact_ && !s_.heap.empty()) {
        overlap_suspected_ = true;
      } else if (!fold(region, heap_object, s_.regions[other]) && !refold_) {
        fail_overlap(region, s_.regions[other]);
      }
      s_.regions.push_back(region);  // not indexed: this pass's output is discarded
      return index;
    }
    s_.regions.push_back(region);
    if (region.end - region.start >= kLargeRegion) {
      s_.large_regions.push_back(index);
      return index;
    }
    const std::uintptr_t first = region.start >> kBucketShift;
    const std::uintptr_t last = (region.end - 1) >> kBucketShift;
    for (std::uintptr_t bucket = first; bucket <= last; ++bucket) {
      bool inserted = false;
      std::uint32_t& head = s_.buckets.find_or_insert(bucket, 0, kNoRegion, inserted);
      const std::uint32_t link = static_cast<std::uint32_t>(s_.chain.size());
      s_.chain.push_back(ChainLink{region.start, region.end, index, head});
      head = link;
    }
    return index;
  }

  // `added` overlaps `existing`: when `existing` is a heap object wholly inside `added`, or
  // inside the part (container elements, a unique_ptr's pointee, a string's characters) of the
  // heap object being encoded that `added` is, the enclosing heap object is remembered for the
  // next pass (run()) and true is returned.
  bool fold(const Region& added, bool heap_object, const Region& existing) {
    const bool existing_heap =
        existing.kind == RegionKind::Object && existing.object >= schema_.root_count;
    if (!existing_heap || existing.start < added.start || existing.end > added.end) return false;
    if (!heap_object && encoding_heap_ == kNoRegion) return false;
    const Region& enclosing = heap_object ? added : s_.regions[encoding_heap_];
    // An enclosure inside it, or the enclosed object itself when an earlier pass learned it
    // (an Item enclosing an int, in a heap Bag's vector), is made by its own traversal.
    const auto inside = [](const Enclosure& e, const Region& region) {
      return e.start >= region.start && e.start < region.end;
    };
    auto& enclosures = s_.enclosures;
    enclosures.erase(std::remove_if(enclosures.begin(), enclosures.end(),
                                    [&](const Enclosure& e) {
                                      return inside(e, enclosing) || inside(e, existing);
                                    }),
                     enclosures.end());
    enclosures.push_back(Enclosure{enclosing.start, enclosing.type});
    refold_ = true;
    return true;
  }

  void describe(const Region& region, char* buffer, std::size_t size) const {
    const char* type = types_[region.type].name;
    switch (region.kind) {
      case RegionKind::Object:
        if (region.object < schema_.root_count) {
          std::snprintf(buffer, size, "root '%s'", schema_.roots[region.object].name);
        } else {
          std::snprintf(buffer, size, "heap object #%u (%s)", region.object - schema_.root_count,
                        type);
        }
        return;
      case RegionKind::ContainerRun:
        std::snprintf(buffer, size, "elements of container #%u (%s)", region.object, type);
        return;
      case RegionKind::Owned:
        std::snprintf(buffer, size, "a unique_ptr's %s", type);
        return;
      case RegionKind::StringChars:
        std::snprintf(buffer, size, "the characters (%s) of a string", type);
        return;
    }
  }

  void fail_overlap(const Region& added, const Region& existing) {
    char a[120], b[120];
    describe(added, a, sizeof a);
    describe(existing, b, sizeof b);
    error_ = Status(Error::Unsupported,
                    "cannot save: %s at %p overlaps %s at %p, and neither encloses the other "
                    "(pointers of different types into the same bytes, e.g. into two members of "
                    "a union): mark all but one of those pointers SYMCR_SKIP",
                    a, reinterpret_cast<const void*>(added.start), b,
                    reinterpret_cast<const void*>(existing.start));
  }

  __attribute__((noinline, cold, format(printf, 2, 3))) void fail_unsupported(const char* format,
                                                                              ...) {
    if (!ok()) return;
    char buffer[200];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    error_ = Status(Error::Unsupported, "cannot save %s", buffer);
  }

  // ---- reference resolution ------------------------------------------------------------
  // Descends from an object of `type` at `base` to the subobject of `target_type` at
  // `target`, appending steps; backtracks where several fields start at the same address.
  bool descend(std::uint32_t type_index, std::uintptr_t base, std::uintptr_t target,
               std::uint32_t target_type) {
    if (target == base && type_index == target_type) return true;
    const TypeInfo& type = types_[type_index];
    switch (type.kind) {
      case Kind::Struct:
        // Fields, then the members a pointer may target without their values being saved.
        for (std::uint32_t f = 0; f < type.field_count + type.reference_member_count; ++f) {
          const FieldInfo& field = *step_member(type, f);
          if (field.bit_width) continue;
          const std::uintptr_t start = base + field.offset;
          if (target < start || target >= start + size_of(field.type)) continue;
          s_.steps.push_back(f);
          if (descend(field.type, start, target, target_type)) return true;
          s_.steps.pop_back();
        }
        return false;
      case Kind::Array: {
        const std::uint32_t stride = size_of(type.element);
        const std::uint64_t index = (target - base) / stride;
        if (index >= type.count) return false;
        s_.steps.push_back(static_cast<std::uint32_t>(index));
        if (descend(type.element, base + index * stride, target, target_type)) return true;
        s_.steps.pop_back();
        return false;
      }
      case Kind::Optional: {
        const void* value =
            static_cast<const OptionalOps*>(type.ops)->get(reinterpret_cast<const void*>(base));
        const auto start = reinterpret_cast<std::uintptr_t>(value);
        if (!value || target < start || target >= start + size_of(type.element)) return false;
        s_.steps.push_back(0);
        if (descend(type.element, start, target, target_type)) return true;
        s_.steps.pop_back();
        return false;
      }
      case Kind::String: {
        // A character: the step is its index, up to the terminator's position.
        const auto* ops = static_cast<const StringOps*>(type.ops);
        const auto* object = reinterpret_cast<const void*>(base);
        const auto start = reinterpret_cast<std::uintptr_t>(ops->data(object));
        const std::uint32_t width = size_of(type.element);
        if (target_type != type.element || target < start || (target - start) % width != 0) {
          return false;
        }
        const std::uint64_t index = (target - start) / width;
        if (index > ops->size(object) || index > 0xFFFFFFFFu) return false;
        s_.steps.push_back(static_cast<std::uint32_t>(index));
        return true;
      }
      case Kind::Variant: {
        const auto* ops = static_cast<const VariantOps*>(type.ops);
        const auto* object = reinterpret_cast<const void*>(base);
        const std::uint32_t index = ops->index(object);
        if (index >= type.alternative_count) return false;
        const auto start = reinterpret_cast<std::uintptr_t>(ops->get(object));
        const std::uint32_t alternative = type.alternatives[index];
        if (target < start || target >= start + size_of(alternative)) return false;
        s_.steps.push_back(index);
        if (descend(alternative, start, target, target_type)) return true;
        s_.steps.pop_back();
        return false;
      }
      default:
        return false;
    }
  }

  struct Base {
    std::uint8_t kind;  // a ReferenceBase
    std::uint32_t a, b;
  };

  // Fills s_.steps and `base` for the subobject of `type` at `address` inside `region_index`.
  bool resolve(std::uint32_t region_index, std::uintptr_t address, std::uint32_t type, Base& base,
               int depth) {
    const Region region = s_.regions[region_index];
    switch (region.kind) {
      case RegionKind::Object:
        base = Base{kBaseObject, region.object, 0};
        return descend(region.type, region.start, address, type);
      case RegionKind::ContainerRun: {
        const std::uint32_t offset =
            static_cast<std::uint32_t>((address - region.start) / region.stride);
        base = Base{kBaseElement, region.object, region.first_index + offset};
        return descend(region.type, region.start + std::uintptr_t{offset} * region.stride, address,
                       type);
      }
      case RegionKind::StringChars: {
        if (depth > kMaxValueNesting) return false;
        const std::uint32_t owner = find_region(region.owner_slot);
        return owner != kNoRegion &&
               resolve(owner, region.owner_slot, region.owner_type, base, depth + 1) &&
               descend(region.owner_type, region.owner_slot, address, type);
      }
      case RegionKind::Owned: {
        if (depth > kMaxValueNesting) return false;
        const std::uint32_t owner = find_region(region.owner_slot);
        if (owner == kNoRegion ||
            !resolve(owner, region.owner_slot, region.owner_type, base, depth + 1)) {
          return false;
        }
        s_.steps.push_back(0);
        return descend(region.type, region.start, address, type);
      }
    }
    return false;
  }

  void write_reference(std::size_t i) {
    const PointerTarget& reference = s_.references[i];
    s_.steps.clear();
    Base base{};
    if (!resolve(reference.region, reference.address, reference.type, base, 0)) {
      if (!exact_) {
        // Resolution may need a heap object in the index (a unique_ptr inside a heap
        // object owning the target): decide in the exact pass.
        overlap_suspected_ = true;
        return;
      }
      char where[120];
      describe(s_.regions[reference.region], where, sizeof where);
      return fail_unsupported(
          "a pointer to %s at %p: it lies inside %s but not at a %s subobject that is saved (a "
          "SYMCR_SKIP member or padding has no path)",
          types_[reference.type].name, reinterpret_cast<const void*>(reference.address), where,
          types_[reference.type].name);
    }
    if (s_.steps.size() > 0xFFFF) return fail_unsupported("a pointer nested 65536 levels deep");
    put_u8(base.kind);
    put_u32(base.a);
    if (base.kind == 1) put_u32(base.b);
    put_u16(static_cast<std::uint16_t>(s_.steps.size()));
    put_bytes(s_.steps.data(), s_.steps.size() * 4);
    put_u32(reference.type);
  }

 public:
  std::size_t payload_start = 0;
  const ClockReadings* given_readings = nullptr;  // encode_payload_at's, or null: read them now

 private:
  const Schema& schema_;
  const TypeInfo* types_;
  std::vector<std::uint8_t>& out_;
  std::size_t pos_;
  EncodeScratch& s_;
  const bool track_regions_;
  const bool track_references_;
  const SchemaFacts& facts_;
  bool memory_refreshed_ = false;
  bool exact_ = false;  // heap objects indexed too (the second pass)
  bool overlap_suspected_ = false;
  bool refold_ = false;          // an enclosure was learned: the pass runs again
  std::uint32_t fused_crc_ = 0;  // CRC-32C of out_ from payload_start to fused_to_ (put_fused)
  std::size_t fused_to_ = 0;
  bool fused_ = false;                       // a large copy was checksummed as it was made
  bool fused_valid_ = true;                  // and nothing before fused_to_ was written again since
  std::uint32_t encoding_heap_ = kNoRegion;  // region of the heap object being encoded
  std::uint32_t container_ordinal_ = 0;
  int depth_ = 0;
  Status error_;
};

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
         capacity_bytes(s.spans) + capacity_bytes(s.spans_scratch) + capacity_bytes(s.enclosures);
}

Status encode_payload_at(const Schema& schema, std::vector<std::uint8_t>& out, std::size_t at,
                         PayloadCrc* payload_crc, const ClockReadings* clock_readings) {
  const SchemaCacheEntry& cached = schema_cache_entry(schema);
  EncodeScratch& scratch = thread_encode_scratch();
  if (out.size() < at) out.resize(at);
  Encoder encoder(schema, out, scratch, cached.facts());
  encoder.payload_start = at;
  if (clock_readings != nullptr && clock_readings->count != cached.facts().clocks.size()) {
    return Status(Error::Unsupported, "%u clock readings given for a schema of %zu clocks",
                  clock_readings->count, cached.facts().clocks.size());
  }
  encoder.given_readings = clock_readings;
  const Status status = encoder.run();
  if (payload_crc) {
    payload_crc->known = status.ok() && encoder.fused_payload_crc(payload_crc->value);
  }
  return status;
}

Status encode_payload(const Schema& schema, std::vector<std::uint8_t>& out) {
  return encode_payload_at(schema, out, 0);
}

}  // namespace symcr::detail
