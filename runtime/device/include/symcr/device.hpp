// symcr's device profile: checkpoints for a microcontroller. C++11, no heap, no exceptions, no
// RTTI, no standard containers, no files: the caller gives the memory. It saves a program's
// roots into a buffer and restores a checkpoint written by the same build (the same schema
// hash) or by a previous build it carries a plan for (PREVIOUS_SCHEMA), in the record format
// of docs/format.md (schema referenced by hash), so the host's tools read what a device wrote.
//
// What it holds: bool, integers, floating point (4 and 8 bytes), enums, structs (bit-fields,
// bases), unions (raw bytes), fixed arrays, and raw pointers to objects inside the roots
// (saved as references by path; a pointer elsewhere keeps the running build's value). Strings,
// containers, optionals, variants and smart pointers need the host runtime.
//
// Restore is all-or-nothing and strict: the record's CRC, header, schema hash and program are
// checked, every value is decoded into a staged copy of the roots, each SYMCR_RANGE bound and
// symcr_validate hook is checked there, and only if everything holds are the roots written. A
// value out of its range or refused by its validator refuses the whole checkpoint.
#ifndef SYMCR_DEVICE_HPP
#define SYMCR_DEVICE_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/generated.hpp"

namespace symcr {
namespace device {

enum class Result : std::uint8_t {
  Ok = 0,
  NoSpace,            // the buffer (or scratch) is smaller than record_size() (scratch_size())
  Unsupported,        // the schema has a type the device profile cannot hold: see check_schema()
  Truncated,          // fewer bytes than the record says it has
  Corrupt,            // bad magic, sizes or checksum, or a payload that does not decode
  FutureVersion,      // written by a newer record format
  OtherSchema,        // written by a build that is neither this one nor one it has a plan for
  OtherProgram,       // written by another program
  Rejected,           // a value outside its SYMCR_RANGE, or refused by its symcr_validate
  TooManyPointers,    // more distinct pointer targets than kMaxReferences
  Empty,              // Ring::restore_latest: no slot was ever written
  SequenceExhausted,  // Ring::save: the newest record's sequence is the last a ring writes
  // (result_text() keeps its texts in this order, up to the last one above.)
};

// A short English description of `result`, for logs.
const char* result_text(Result result);

// The identity of a build's schema: its tables and the hash of their serialised form, which
// symcr-gen emits as constants (symcr_program_schema_hash()).
// `plans`: how checkpoints of previous builds restore into this one (symcr-gen's
// PREVIOUS_SCHEMA, one plan image per previous build; null and 0 when there are none).
//
// Restoring through plans needs the cross-version executor, which a firmware links only when
// it uses plans (a few KB of flash): the generated code of a build with PREVIOUS_SCHEMA links
// it, and so does the four-argument constructor. A Build given plans any other way restores
// another build's record as OtherSchema.
struct Build {
  // (Parameters named unlike the members: user code may build with -Wshadow.)
  Build(const Schema* own_schema = nullptr, std::uint64_t own_schema_hash = 0)
      : schema(own_schema), schema_hash(own_schema_hash), plans(nullptr), plan_count(0) {}
  Build(const Schema* own_schema, std::uint64_t own_schema_hash,
        const PlannedSchema* previous_plans, std::uint32_t previous_plan_count);
  const Schema* schema;
  std::uint64_t schema_hash;
  const PlannedSchema* plans;
  std::uint32_t plan_count;
};
// The program's own build (its generated tables: a PROFILE device build's compact ones,
// symcr_program_device_schema(), else symcr_program_schema(); its emitted hash and its previous
// builds' plans); `schema` is null when the program has no generated code.
Build program_build();

// Ok when every type reachable from the roots is one the device profile holds; else
// Unsupported, with `type` (if given) set to the first type that is not.
Result check_schema(const Schema& schema, std::uint32_t* type = nullptr);

// Bytes of a record of the roots: the header and a payload whose size the schema fixes.
std::size_t record_size(const Schema& schema);
// Bytes of scratch restore needs: a staged copy of every root.
std::size_t scratch_size(const Schema& schema);

// The most distinct pointer targets one checkpoint may hold.
constexpr std::size_t kMaxReferences = 32;
// The deepest path from a root to a pointer's target (fields and array elements).
constexpr std::size_t kMaxPathSteps = 16;
// Clocks whose times a checkpoint may hold (symcr-gen's `clock`): more is Unsupported.
constexpr std::size_t kMaxClocks = 8;

// Writes the record of the roots' current values into out[0, capacity); `*size` is its size.
Result save(const Build& build, std::uint64_t sequence, std::uint8_t* out, std::size_t capacity,
            std::size_t* size);

// Restores the record in bytes[0, size) into the roots, through `scratch` (scratch_size()
// bytes, any alignment). On any result but Ok nothing of the roots has changed. `*sequence`,
// if given, is the record's sequence.
Result restore(const Build& build, const std::uint8_t* bytes, std::size_t size,
               std::uint8_t* scratch, std::size_t scratch_capacity,
               std::uint64_t* sequence = nullptr);

// The payload alone (docs/format.md §3), for a caller that checked the record around it (its
// CRC, its schema hash being `schema`'s, its program): restore() without the header checks.
Result restore_payload(const Schema& schema, const std::uint8_t* payload, std::size_t size,
                       std::uint8_t* scratch, std::size_t scratch_capacity);

// Where a ring keeps its checkpoints: a memory region that keeps its bytes across a reset
// (backup SRAM: erase_unit 1, no erase), or a block device written after erasing whole units
// (a flash sector: erase_unit its size, erase() required). Offsets are from the region's start.
struct Storage {
  std::size_t size;
  std::size_t erase_unit;  // 0 or 1: bytes can be rewritten in place
  bool (*read)(void* context, std::size_t offset, void* out, std::size_t n);
  bool (*write)(void* context, std::size_t offset, const void* data, std::size_t n);
  bool (*erase)(void* context, std::size_t offset, std::size_t n);  // units; null if none
  void* context;
};
// A Storage over plain memory at `base`: backup SRAM, or RAM a reset does not clear.
Storage memory_storage(void* base, std::size_t size);

// Slots over a Storage, each holding one record: save() writes the slot after the newest whole
// record (a reset during the write destroys only that slot), restore_latest() restores the
// newest slot that restores and falls back past corrupt, torn and refused ones. Only records
// whose CRC holds count: a torn or damaged slot never decides where saving goes on. Sequences
// run from 1 to kLastRingSequence; a record outside that range is not the ring's. At most
// kMaxSlots slots. docs/device.md lists the guarantees (D1-D6).
constexpr std::size_t kMaxSlots = 8;
constexpr std::uint64_t kLastRingSequence = ~std::uint64_t{0} - 1;  // not all ones: erased flash
class Ring {
 public:
  // `slot_size` bytes per slot, a multiple of the storage's erase unit; two slots at least.
  Result open(const Storage& storage, std::size_t slot_size);

  // Saves into the slot after the newest whole record, with the sequence after its; `buffer`
  // holds the record while it is written. SequenceExhausted, changing nothing, when that record's
  // sequence is kLastRingSequence (only a record written elsewhere gets there).
  Result save(const Build& build, std::uint8_t* buffer, std::size_t capacity);

  // Restores the newest slot that restores; `buffer` receives each slot as it is read (a slot's
  // size at least). `*slot` and `*sequence`, if given, say what was restored; `*skipped`, how
  // many newer slots were passed over. The result is the newest slot's when none restores, and
  // Empty when nothing was ever saved.
  Result restore_latest(const Build& build, std::uint8_t* buffer, std::size_t capacity,
                        std::uint8_t* scratch, std::size_t scratch_capacity,
                        std::uint64_t* sequence = nullptr, std::size_t* slot = nullptr,
                        std::size_t* skipped = nullptr);

  std::size_t slot_count() const { return slot_count_; }
  // The newest whole record's sequence when opened, then the last save's; 0: none.
  std::uint64_t last_sequence() const { return last_sequence_; }

 private:
  // Each slot's sequence from its header (0: empty, unreadable or out of range), newest first
  // in `order`; the count in `order` is returned. Unchecked: see whole().
  std::size_t scan(std::uint64_t* sequences, std::size_t* order) const;
  // Whether the slot holds a record whose CRC holds (read in pieces, no buffer needed).
  bool whole(std::size_t slot) const;
  // The first of `order` that is whole, or kMaxSlots.
  std::size_t newest_whole(const std::size_t* order, std::size_t used) const;

  Storage storage_{};
  std::size_t slot_size_ = 0;
  std::size_t slot_count_ = 0;
  std::uint64_t last_sequence_ = 0;
};

}  // namespace device
}  // namespace symcr

#endif  // SYMCR_DEVICE_HPP
