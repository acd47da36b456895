// The save path's encoder (encode.cpp). Internal to the runtime. Its work is split by job:
//   encode.cpp             the passes, the output buffer, values, pointers met while saving
//   encode_references.cpp  classifying each pointer's target (inside, outside, a new heap
//                          object, its dynamic type) and resolving it into base and steps
//   encode_regions.cpp     the region index: which saved object holds an address
#ifndef SYMCR_SRC_ENCODER_HPP
#define SYMCR_SRC_ENCODER_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "address_table.hpp"
#include "engine.hpp"
#include "payload_grammar.hpp"
#include "process_memory.hpp"
#include "schema_facts.hpp"

namespace symcr::detail::encoding {

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
  // with every heap object indexed, which resolves it or refuses it.
  Status run();

 private:
  Status run_pass();

  bool heap_objects_overlap();

  // Sorts s_.spans by start. Large graphs: an LSD radix sort over the bits in which the starts
  // differ (heap addresses span a few hundred MB: three 11-bit passes instead of N log N
  // mispredicted comparisons).
  void sort_spans();

  bool ok() const { return error_.ok(); }
  Status finish_error();
  std::uint32_t size_of(std::uint32_t type) const { return types_[type].size; }

  // ---- output --------------------------------------------------------------------------
  // out_ holds pos_ bytes written plus a little zero-filled slack (std::vector cannot grow
  // without value-initialising). The vector's capacity grows geometrically on its own, so the
  // slack only bounds how much is zero-filled ahead of use; large copies are appended without
  // any zero-fill.
  static constexpr std::size_t kSlack = 1024;
  static constexpr std::size_t kBulk = 4096;  // put_bytes at least this large: append directly
  std::uint8_t* grow(std::size_t n);
  void put_bytes(const void* data, std::size_t n);
  void put_u8(std::uint8_t v) { *grow(1) = v; }
  // Fixed-size copies compile to single moves; the generic memcpy call would dominate.
  void put_scalar(const std::uint8_t* p, std::uint32_t size);
  void put_u16(std::uint16_t v) { std::memcpy(grow(2), &v, 2); }
  void put_u32(std::uint32_t v) { std::memcpy(grow(4), &v, 4); }
  void patch_u32(std::size_t at, std::uint32_t v) { std::memcpy(out_.data() + at, &v, 4); }

  // ---- values --------------------------------------------------------------------------
  void encode(std::uint32_t type_index, const std::uint8_t* p);

  void descend_into(std::uint32_t type, const std::uint8_t* p);

  void prefetch_references(const TypeInfo& type, const std::uint8_t* p) const;

  __attribute__((noinline)) void encode_bit_field(const FieldInfo& field, const std::uint8_t* p);

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

  static void visit_element(void* context, const void* element);

  void flush_run(ContainerWalk& walk);

  __attribute__((noinline)) void encode_container(const TypeInfo& type, const std::uint8_t* p);

  // ---- references ----------------------------------------------------------------------
  __attribute__((noinline)) void encode_reference(const TypeInfo& type, const void* target,
                                                  bool shared);

  bool is_outside(std::uintptr_t address);

  std::uint32_t find_root(std::uintptr_t address) const;

  void classify(std::size_t i);

  std::uint32_t new_heap_object(const PointerTarget& reference);

  // Itanium C++ ABI: an object's vtable pointer is its first word, and the word two before
  // the address it holds is the offset from this subobject to the complete object, whose own
  // vtable pointer identifies its class. On success, `address` and `type` are the complete
  // object's.
  bool dynamic_type(std::uintptr_t& address, std::uint32_t& type) const;

  __attribute__((cold)) void list_dynamic_types(std::uint32_t base, char* out,
                                                std::size_t size) const;

  // A shared_ptr target must be a whole heap object: sharing is kept by owning it.
  void check_shared_targets();

  // ---- the region index ----------------------------------------------------------------
  // Small regions are chained from every 64-byte bucket they touch; large ones sit in a list.
  std::uint32_t find_region(std::uintptr_t address);

  std::uint32_t overlapping(const Region& candidate);

  std::uint32_t add_region(const Region& region, bool heap_object = false);

  void describe(const Region& region, char* buffer, std::size_t size) const;

  void fail_overlap(const Region& added, const Region& existing);

  __attribute__((noinline, cold, format(printf, 2, 3))) void fail_unsupported(const char* format,
                                                                              ...);

  // ---- reference resolution ------------------------------------------------------------
  // Descends from an object of `type` at `base` to the subobject of `target_type` at
  // `target`, appending steps; backtracks where several fields start at the same address.
  bool descend(std::uint32_t type_index, std::uintptr_t base, std::uintptr_t target,
               std::uint32_t target_type);

  struct Base {
    std::uint8_t kind;  // a ReferenceBase
    std::uint32_t a, b;
  };

  // Fills s_.steps and `base` for the subobject of `type` at `address` inside `region_index`.
  bool resolve(std::uint32_t region_index, std::uintptr_t address, std::uint32_t type, Base& base,
               int depth);

  void write_reference(std::size_t i);

 public:
  std::size_t start_ = 0;

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
  std::uint32_t container_ordinal_ = 0;
  int depth_ = 0;
  Status error_;
};

}  // namespace symcr::detail::encoding

#endif  // SYMCR_SRC_ENCODER_HPP
