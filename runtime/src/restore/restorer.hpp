// Restore's decoder (restore.cpp): the Restorer, which runs the passes over one payload and
// keeps the records pass 1 makes for the later passes. Internal to the runtime. Its work is
// split by job:
//   restore.cpp             the two passes and the entry points, and the copy-only fast path
//   restore_traversal.hpp   the one traversal of values along the plan, and its passes
//   restore_values.cpp      that traversal's code (hot: kept in one file for inlining)
//   restore_references.cpp  the reference table, pointer decisions, heap objects, fix-ups
#ifndef SYMCR_SRC_RESTORER_HPP
#define SYMCR_SRC_RESTORER_HPP

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "payload_grammar.hpp"
#include "plan.hpp"
#include "scalar.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail::restoring {

// ---- copy-only values (PlanNode::copy_only) ------------------------------------------------
// Little-endian, as the copy runs assume; the planner allows sizes 1, 2, 4 and 8.
inline std::uint64_t bit_field_raw(const CopyBits& bits, const std::uint8_t* wire) {
  const std::uint8_t* at = wire + bits.wire;
  switch (bits.size) {
    case 1:
      return at[0];
    case 2: {
      std::uint16_t raw;
      std::memcpy(&raw, at, sizeof raw);
      return raw;
    }
    case 4: {
      std::uint32_t raw;
      std::memcpy(&raw, at, sizeof raw);
      return raw;
    }
    case 8: {
      std::uint64_t raw;
      std::memcpy(&raw, at, sizeof raw);
      return raw;
    }
    default: {
      std::uint64_t raw = 0;
      std::memcpy(&raw, at, bits.size);
      return raw;
    }
  }
}

inline Number bit_field_value(const CopyBits& bits, const std::uint8_t* wire) {
  Number value;
  const std::uint64_t raw = bit_field_raw(bits, wire);
  if (bits.is_signed) {
    const unsigned unused = 64 - 8 * bits.size;
    value.tag = Number::Tag::Signed;
    value.s = static_cast<std::int64_t>(raw << unused) >> unused;
  } else {
    value.tag = Number::Tag::Unsigned;
    value.u = raw;
  }
  return value;
}

// fits_bits(bit_field_value(bits, wire), ...) for the wire integer `raw`, inline.
inline bool copy_bits_fit(const CopyBits& bits, std::uint64_t raw) {
  if (bits.width >= 64) return true;
  if (!bits.is_signed) return (raw >> bits.width) == 0;
  const unsigned unused = 64 - 8 * unsigned{bits.size};
  const std::int64_t value = static_cast<std::int64_t>(raw << unused) >> unused;
  const std::int64_t high = value >> (bits.width - 1);  // all sign: 0 or -1 when it fits
  return high == 0 || high == -1;
}

// The first pass's checks of a copy-only value at `wire`: bools are 0 or 1, bit-field values
// fit their widths. False sends the value to the general path, which names the fault.
inline bool copy_only_valid(const PlanNode& n, const std::uint8_t* wire) {
  for (std::uint32_t offset : n.copy_bools) {
    if (wire[offset] > 1) return false;
  }
  for (const CopyBits& bits : n.copy_bits) {
    if (!copy_bits_fit(bits, bit_field_raw(bits, wire))) return false;
  }
  return true;
}

// Writes a bit-field's value (its checked wire integer) into its storage unit, byte by byte:
// the unit's bytes past the field are not touched.
inline void copy_bits_to(std::uint8_t* unit, const CopyBits& bits, std::uint64_t raw) {
  const unsigned end = unsigned{bits.bit_offset} + bits.width;
  if (end > 64) {  // the field's low bits are all that is stored: its sign does not matter
    Number value;
    value.tag = Number::Tag::Unsigned;
    value.u = raw;
    store_bits(unit, bits.bit_offset, bits.width, value);
    return;
  }
  const unsigned bytes = (end + 7) / 8;
  std::uint64_t word = 0;
  for (unsigned i = 0; i < bytes; ++i) word |= std::uint64_t{unit[i]} << (8 * i);
  const std::uint64_t mask =
      (bits.width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits.width) - 1)
      << bits.bit_offset;
  word = (word & ~mask) | ((raw << bits.bit_offset) & mask);
  for (unsigned i = 0; i < bytes; ++i) unit[i] = static_cast<std::uint8_t>(word >> (8 * i));
}

inline void copy_only_write(const PlanNode& n, const std::uint8_t* wire, std::uint8_t* dst) {
  for (const CopyRun& run : n.copy_runs) {
    format::copy_bytes(dst + run.dst, wire + run.wire, run.length);
  }
  for (const CopyBits& bits : n.copy_bits) {
    copy_bits_to(dst + bits.dst, bits, bit_field_raw(bits, wire));
  }
}

constexpr std::uint32_t kMaxConcretePerField = 100;

enum class SlotOutcome : std::uint8_t { Skip, Null, Outside, Target, Rejected };

struct SlotRecord {
  std::uint32_t code;          // wire value: kNullCode, kOutsideCode, kFirstReference + i
  std::uint32_t pointer_type;  // writer pointer type
  const PlanNode* node;        // restorable pointer node, or nullptr
  bool shared;
  std::uintptr_t live;  // the reader's current pointer (raw slots with a place)
  std::uint32_t counter;
  std::uint32_t object;  // the object (root or heap) holding the slot
  SlotOutcome outcome;
};

struct ContainerRecord {
  std::uint32_t count;
  const PlanNode* element;  // restorable element node, or a skip node
  std::uint32_t object;     // the object (root or heap) holding the container
};

struct HeapRecord {
  std::uint32_t type;
  std::uint8_t owner;
  const PlanNode* node;
  // A value in it was refused: not created, pointers keep their values. `validator`: one of
  // them by its type's symcr_validate (else a rule rejected it).
  bool refused;
  bool validator;
};

struct MappedStep {
  enum class Kind : std::uint8_t { Offset, Optional, Unique, Variant, Character } kind;
  std::uint32_t holder_type;  // reader type whose ops apply
  std::uint64_t value;
};

struct RefRecord : Reference {
  std::uint32_t steps_at = 0;
  bool resolved = false;
  std::uint32_t reader_type = kNoType;
  std::uint32_t mapped_at = 0, mapped_count = 0;
  std::string why;
};

struct AppliedSlot {
  std::uint32_t ordinal;
  std::uint8_t* address;
};

// The decoding tables of one restore. A thread keeps one set between restores (a restore
// of the same state then allocates nothing), unless a restore grew it past
// kKeptRestoreTableBytes (a large graph's tables are freed when it is done).
struct RestoreTables {
  std::vector<PathFrame> frames;
  std::vector<std::uint32_t> rejection_counts;
  std::vector<std::uint32_t> handed_counts;
  std::vector<std::uint8_t> verdicts;
  std::vector<std::uint8_t> part_verdicts;
  std::vector<SlotRecord> slots;
  std::vector<ContainerRecord> containers;
  std::vector<HeapRecord> heap;
  std::vector<RefRecord> refs;
  std::vector<std::uint32_t> steps;
  std::vector<MappedStep> mapped;
  std::vector<void*> claimed;
  std::vector<bool> materialisable;
  std::vector<std::uint32_t> element_needed;
  std::vector<void*> heap_live;
  std::vector<void*> holders;
  std::vector<AppliedSlot> applied_slots;
  std::vector<std::uint32_t> element_slots;
  std::vector<std::vector<void*>> element_addresses;  // cleared lists stay, for their capacity
  std::vector<std::uint8_t> string_scratch;
  std::vector<std::int64_t> clock_deltas;

  // Capacity in bytes (thread_scratch_bytes).
  std::size_t bytes() const;
  void clear();
  // Room for the records of a small first restore (prepare_restore).
  void reserve_first_records();
};

constexpr std::size_t kKeptRestoreTableBytes = std::size_t{64} * 1024;

// The tables a Restorer decodes with: the thread's kept set, or a set of its own when a
// restore runs inside another one on this thread (a hook or validator that restores).
class RestoreTablesLease {
 public:
  RestoreTablesLease();
  ~RestoreTablesLease();
  RestoreTablesLease(const RestoreTablesLease&) = delete;
  RestoreTablesLease& operator=(const RestoreTablesLease&) = delete;
  // Writable until table_bytes() is asked: the restore is done with them then.
  RestoreTables& tables() { return *tables_; }
  const RestoreTables& tables() const { return *tables_; }
  // The tables' bytes(), counted once: asked for thread_scratch_bytes, and again at the end.
  std::size_t table_bytes() const;
  // Makes this thread's kept set ahead of its first restore (prepare_restore): its first use
  // registers its destruction at thread exit (a call bound lazily), and a first restore's records
  // would grow each vector from nothing.
  static void prepare_thread_tables();

 private:
  static constexpr std::size_t kNotCounted = ~std::size_t{0};
  RestoreTables* tables_;
  bool kept_;  // the thread's set, handed back at the end
  mutable std::size_t counted_bytes_ = kNotCounted;
};

template <typename Pass>
class Traversal;
class CheckPass;
class StagePass;
class ApplyPass;
class ExplainPass;

class Restorer {
 public:
  // `dry_run`: a plan of a build known only by its schema (no code): types it can create are
  // known by their kTypeCreatable flag instead of a Lifecycle; nothing is ever applied.
  Restorer(const Plan& plan, const std::uint8_t* payload, std::size_t size, Report& report,
           bool dry_run)
      : plan_(plan),
        writer_(*plan.writer),
        reader_(*plan.reader),
        payload_(payload),
        size_(size),
        report_(report),
        dry_run_(dry_run),
        frames_(lease_.tables().frames),
        rejection_counts_(lease_.tables().rejection_counts),
        handed_counts_(lease_.tables().handed_counts),
        verdicts_(lease_.tables().verdicts),
        part_verdicts_(lease_.tables().part_verdicts),
        slots_(lease_.tables().slots),
        containers_(lease_.tables().containers),
        heap_(lease_.tables().heap),
        refs_(lease_.tables().refs),
        steps_(lease_.tables().steps),
        mapped_(lease_.tables().mapped),
        claimed_(lease_.tables().claimed),
        materialisable_(lease_.tables().materialisable),
        element_needed_(lease_.tables().element_needed),
        heap_live_(lease_.tables().heap_live),
        holders_(lease_.tables().holders),
        applied_slots_(lease_.tables().applied_slots),
        element_slots_(lease_.tables().element_slots),
        element_addresses_(lease_.tables().element_addresses),
        string_scratch_(lease_.tables().string_scratch),
        clock_deltas_(lease_.tables().clock_deltas) {}

  Status check();

  std::size_t value_rejections() const { return value_rejections_; }

  // Capacity of the decoding tables (thread_scratch_bytes).
  std::size_t scratch_bytes() const;

  void apply();

 private:
  template <typename>
  friend class Traversal;
  friend class CheckPass;
  friend class ApplyPass;

  // ---- errors and report ---------------------------------------------------------------
  __attribute__((format(printf, 2, 3))) const Status& corrupt(const char* format, ...);

  // `counts` (rejection_counts_ or handed_counts_) at `counter`: both are sized on the first
  // value-level entry, so that a restore without one never fills them.
  std::uint32_t& entry_count(std::vector<std::uint32_t>& counts, std::uint32_t counter) {
    if (counts.empty()) {
      rejection_counts_.assign(plan_.counter_paths.size() + 1, 0);
      handed_counts_.assign(plan_.counter_paths.size() + 1, 0);
    }
    return counts[counter];
  }

  void summarise_rejections();

  std::string counter_path(std::uint32_t counter) const;

  // The counter of every heap object's values: past the plan's counters.
  std::uint32_t heap_counter() const {
    return static_cast<std::uint32_t>(plan_.counter_paths.size());
  }

  // A hostile (or merely old) checkpoint must not make restore allocate more than its own size
  // justifies: a 4-byte count of empty writer elements must not become 2^20 elements of a
  // reader type that grew to 64 KiB. Allowed: a fixed 64 MiB, or 16 bytes of this build's
  // memory per payload byte, whichever is larger (a 256 MiB vector<double> restores).
  bool allocation_justified(std::uint32_t count, std::uint32_t reader_container) const {
    constexpr std::uint64_t kAlwaysAllowed = std::uint64_t{64} << 20;
    constexpr std::uint64_t kBytesPerPayloadByte = 16;
    const std::uint64_t element_size = reader_.types[reader_.types[reader_container].element].size;
    const std::uint64_t needed = std::uint64_t{count} * element_size;
    return needed <= kAlwaysAllowed || needed / kBytesPerPayloadByte <= size_;
  }

  // ---- references ----------------------------------------------------------------------
  bool decode_references(PayloadReader& in);

  bool check_slots();

  bool inside_reader_root(std::uintptr_t address) const;

  // docs/resolution.md, pointers: a non-null pointer the new build already holds, of the pointee's
  // type, lends its object to the heap object it now refers to (once; never an object in a root).
  void claim_live_objects();

  // A heap object is created (or claimed) only when the new build can make it and a pointer
  // that will really be restored reaches it from a restored root, so nothing is allocated for
  // pointers in dropped fields. A shared_ptr object must be reached through a shared_ptr: with
  // no restored owner it would die at once and leave raw pointers to it dangling.
  void decide_materialisation();

  // Maps a reference's writer steps onto reader steps by name (via the plan), never offsets.
  void map_reference(RefRecord& ref);
  void map_by_names(RefRecord& ref, std::uint32_t writer, std::uint32_t reader, std::uint16_t from);

  // Decides every pointer slot; the concrete paths of the few reported ones are rendered by a
  // third walk (ExplainPass) rather than remembered for every pointer of a large graph.
  void decide_slots();

  // ---- pass 2 --------------------------------------------------------------------------
  void create_heap_objects();

  void* target_of(const RefRecord& ref);

  void fix_up_slots();

  // ---- clocks (docs/resolution.md, Clocks) --------------------------------------------------
  // After pass 1 read the payload's clock readings: how far each reader clock moves its times
  // (rebasing_ when the checkpoint is another process's), and the report's lines for them.
  void decide_clock_deltas(const ClockReadings& readings);
  // A time of `time`'s clock just written at `dst` as reader type `type`, in the write pass:
  // moved by the clock's delta, in the integer's own wrapping arithmetic.
  void rebase(std::uint8_t* dst, const TypeInfo& type, const FieldTime& time) const;

  const Plan& plan_;
  const Schema& writer_;
  const Schema& reader_;
  Status error_;
  const std::uint8_t* payload_;
  std::size_t size_;
  Report& report_;
  const bool dry_run_;
  RestoreTablesLease lease_;

  std::vector<PathFrame>& frames_;                // every traversal's path, one at a time
  std::vector<std::uint32_t>& rejection_counts_;  // per counter, sized by entry_count
  // A copy of a copy-only value failed its checks (Traversal::copy): pass 2 checks again.
  bool copy_refused_ = false;
  std::size_t value_rejections_ = 0;
  std::vector<std::uint32_t>& handed_counts_;  // per field, as rejection_counts_
  std::size_t values_handed_ = 0;

  // ---- pass 1's records, looked up by the later passes at their cursors (Cursors) -----------
  std::vector<std::uint8_t>& verdicts_;
  std::vector<std::uint8_t>& part_verdicts_;  // Traversal::begin_part / end_part
  std::vector<SlotRecord>& slots_;
  std::unordered_map<std::uint32_t, std::string> explained_;  // slot ordinal -> path
  std::vector<ContainerRecord>& containers_;
  std::vector<HeapRecord>& heap_;
  std::vector<RefRecord>& refs_;
  std::vector<std::uint32_t>& steps_;
  std::vector<MappedStep>& mapped_;
  std::vector<void*>& claimed_;
  std::vector<bool>& materialisable_;
  std::vector<std::uint32_t>& element_needed_;

  std::vector<void*>& heap_live_;
  std::vector<void*>& holders_;
  std::vector<AppliedSlot>& applied_slots_;
  std::vector<std::uint32_t>& element_slots_;
  std::vector<std::vector<void*>>& element_addresses_;  // the first element_lists_ in use
  std::size_t element_lists_ = 0;
  std::vector<std::uint8_t>& string_scratch_;

  bool rebasing_ = false;
  std::vector<std::int64_t>& clock_deltas_;  // per reader clock
};

}  // namespace symcr::detail::restoring

#endif  // SYMCR_SRC_RESTORER_HPP
