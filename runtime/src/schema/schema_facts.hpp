// Per-Schema facts computed once and cached with the serialised schema: what the save and
// restore paths need to know about a schema as a whole.
#ifndef SYMCR_SRC_SCHEMA_FACTS_HPP
#define SYMCR_SRC_SCHEMA_FACTS_HPP

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <vector>

#include "crc32c.hpp"
#include "device_format.hpp"
#include "first_time.hpp"
#include "schema_blob.hpp"
#include "schema_sizes.hpp"
#include "symcr/device.hpp"
#include "symcr/generated.hpp"

namespace symcr::detail {

// A contiguous span of live bytes that is also contiguous on the wire.
struct FlatRun {
  std::uint32_t offset;
  std::uint32_t length;
};
inline constexpr std::uint32_t kNotFlat = 0xFFFFFFFFu;

struct SchemaFacts {
  bool has_raw_pointers = false;  // some type is Kind::Pointer: interior targets must resolve
  bool has_references = false;    // Pointer or SharedPtr: the reference memo is needed
  // Plain types (integers, enums, float/double, unions, structs/arrays of only those, no
  // bit-fields) save as a few memcpy runs: per type, its runs in `flat_runs` or kNotFlat.
  std::vector<std::uint32_t> flat_first;
  std::vector<std::uint32_t> flat_count;
  std::vector<std::uint32_t> flat_wire_size;
  std::vector<FlatRun> flat_runs;
  std::vector<bool> has_pointer_fields;       // per type: a Struct with raw Pointer fields
  std::vector<std::uint32_t> nesting_levels;  // per type: WireSizes::levels
  // kTypeDynamicType classes by their vtable: how saving learns a heap object's dynamic type.
  struct DynamicType {
    const void* vtable;
    std::uint32_t type;
  };
  std::vector<DynamicType> dynamic_types;
  // The clocks whose readings end every payload (schema_sizes.hpp: schema_clocks).
  std::vector<const ClockInfo*> clocks;
};

SchemaFacts compute_schema_facts(const Schema& schema);

// Whether any type of `schema` has a symcr_validate.
inline bool any_validator(const Schema& schema) {
  for (std::uint32_t t = 0; t < schema.type_count; ++t) {
    if (schema.types[t].validate != nullptr) return true;
  }
  return false;
}

// The blob and facts of `schema`, each computed on its first use (a restore needs only the
// blob; saving needs the facts). Both live as long as the process.
struct SchemaCacheEntry {
  SchemaBlob blob;
  const Schema* schema = nullptr;
  const SchemaFacts& facts() const {
    std::call_once(facts_computed_, [this] { facts_ = compute_schema_facts(*schema); });
    return facts_;
  }
  // Every type reachable from the roots is one the device profile's decoder holds, and that
  // decoder restores it as the planned path does, so a checkpoint of this very schema can be
  // restored without a plan (restore.cpp).
  bool device_holdable() const {
    std::call_once(device_checked_, [this] {
      // Times of clocks are rebased value by value, which that decoder leaves to the device. A
      // validator judges a value-initialised staged object on the planned path, a copy of the
      // running state (its skipped members included) in that decoder.
      device_holdable_ = device::check_schema(*schema) == device::Result::Ok &&
                         schema_clocks(*schema).empty() && !any_validator(*schema);
      if (device_holdable_) held_shape_ = device::detail::payload_shape(*schema);
    });
    return device_holdable_;
  }
  // What each payload of a device_holdable() schema holds, for that decoder, with the steps of
  // its walk once prepare_held_steps() wrote them.
  device::detail::PayloadShape held_shape() const {
    device::detail::PayloadShape shape = held_shape_;
    if (held_steps_ready_.load(std::memory_order_acquire)) {
      shape.steps = held_steps_.data();
      shape.step_count = held_steps_.size();
    }
    return shape;
  }
  // Writes the steps of that decoder's walk (device::detail::held_steps()) for a
  // device_holdable() schema, when a store is opened (prepare_restore): the process's first
  // restore into this schema then copies runs of bytes where the walk decoded value by value.
  // Not at that restore itself: writing the steps costs about what they save once.
  void prepare_held_steps() const {
    std::call_once(held_steps_made_, [this] {
      const std::size_t count = device::detail::held_steps(*schema, nullptr, 0, kMaxHeldSteps);
      if (count == 0 || count > kMaxHeldSteps) return;
      held_steps_.resize(count);
      device::detail::held_steps(*schema, held_steps_.data(), count, kMaxHeldSteps);
      held_steps_ready_.store(true, std::memory_order_release);
    });
  }
  // The blob's share of a record's CRC (crc32c_span), computed at its first use: every
  // standalone record of this schema carries the blob inline, checked without reading it twice.
  const Crc32cSpan& blob_crc() const {
    std::call_once(blob_crc_computed_, [this] { blob_crc_ = crc32c_span(blob.data, blob.size); });
    return blob_crc_;
  }
  // True the first time it is asked: the process's first restore of this schema into itself.
  bool first_same_build_restore() const { return restored_.claim(); }
  // The scratch of the process's first restore into this schema through one of the device
  // profile's decoders (restore.cpp), allocated and written when a store is opened
  // (prepare_restore): freshly allocated scratch met a page fault in a fresh process, a third
  // of that restore's time. Only small scratch is prepared, as it is kept until taken.
  void prepare_first_scratch() const {
    std::call_once(first_scratch_made_, [this] {
      const std::size_t size = device::scratch_size(*schema);
      if (size > kMaxPreparedScratch) return;
      std::uint8_t* bytes = std::allocator<std::uint8_t>().allocate(size);
      std::memset(bytes, 0, size);
      first_scratch_.store(bytes, std::memory_order_release);
    });
  }
  // The prepared scratch (device::scratch_size(*schema) bytes from std::allocator, the
  // caller's to free) to its first taker; nullptr when none was prepared or it is taken.
  std::uint8_t* take_first_scratch() const {
    return first_scratch_.exchange(nullptr, std::memory_order_acq_rel);
  }

 private:
  mutable std::once_flag facts_computed_;
  mutable SchemaFacts facts_;
  mutable std::once_flag device_checked_;
  mutable bool device_holdable_ = false;
  mutable device::detail::PayloadShape held_shape_{};
  // A walk of more steps than this (arrays of structs with bools or pointers) runs itself.
  static constexpr std::size_t kMaxHeldSteps = 4096;
  mutable std::once_flag held_steps_made_;
  mutable std::vector<device::detail::HeldStep> held_steps_;
  mutable std::atomic<bool> held_steps_ready_{false};
  mutable FirstTime restored_;
  static constexpr std::size_t kMaxPreparedScratch = std::size_t{64} * 1024;
  mutable std::once_flag first_scratch_made_;
  mutable std::atomic<std::uint8_t*> first_scratch_{nullptr};
  mutable std::once_flag blob_crc_computed_;
  mutable Crc32cSpan blob_crc_;
};
const SchemaCacheEntry& schema_cache_entry(const Schema& schema);

// Marks each type in `pending` and, transitively, its base classes (`marked` is grown to
// type_count); empties `pending`.
void mark_with_bases(const TypeInfo* types, std::uint32_t type_count,
                     std::vector<std::uint32_t>& pending, std::vector<bool>& marked);
void serialise_schema(const Schema& schema, std::vector<std::uint8_t>& out);

// Scalar helpers shared by the engine.
inline bool is_scalar_kind(Kind kind) {
  return kind == Kind::Bool || kind == Kind::Int || kind == Kind::UInt || kind == Kind::Float ||
         kind == Kind::Enum;
}
const char* kind_name(Kind kind);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCHEMA_FACTS_HPP
