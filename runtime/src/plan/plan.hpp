// Resolution (docs/resolution.md): how each writer type of a checkpoint maps onto the running
// build's (reader) types. A plan is built once per (writer schema hash, reader schema) and
// cached; restore then only follows it.
#ifndef SYMCR_SRC_PLAN_HPP
#define SYMCR_SRC_PLAN_HPP

#include <atomic>
#include <cstdint>
#include <cstring>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "crc32c.hpp"
#include "first_time.hpp"
#include "parsed_schema.hpp"
#include "payload_grammar.hpp"
#include "report_access.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

enum class Action : std::uint8_t {
  Skip,    // no reader counterpart: decode and check the writer value, write nothing
  Reject,  // incompatible: decode with `skip`, keep the reader's value
  Scalar,  // Bool/Int/UInt/Float/Enum to Bool/Int/UInt/Float/Enum, converted per value
  Struct,
  Union,  // raw bytes, sizes equal
  Array,
  String,
  Container,
  Optional,
  Variant,
  UniquePtr,
  Pointer,
  SharedPtr,
};

struct PlanNode;

struct FieldPlan {
  const PlanNode* node = nullptr;        // (writer field type, reader field type or kNoType)
  std::uint32_t reader_field = kNoType;  // kNoType: the field was removed
  std::uint32_t reader_offset = 0;
  std::uint16_t bit_offset = 0;  // reader bit-field
  std::uint16_t bit_width = 0;
  bool has_range = false;  // reader field's SYMCR_RANGE
  double range_min = 0, range_max = 0;
  std::uint32_t counter = 0;  // per-field index for capping value-level entries
  const char* name = "";      // writer field name (concrete paths)
  // reader_time() of this field, looked up once (derive_copy_segments; never encoded).
  const FieldTime* time = nullptr;
};

// A writer enumerator's value and where it goes. Unmapped when none of the value's names is
// the reader's, or when its names (aliases) name different reader values: `name` is then one the
// reader has (reader_enumerator() finds it), so that the two are told apart where said.
struct EnumMapping {
  std::int64_t writer_value;
  const char* name;
  bool mapped;
  std::int64_t reader_value;
};

// The enumerator of enum `type` named `name`, or null: enumerators map by name.
inline const EnumeratorInfo* reader_enumerator(const TypeInfo& type, const char* name) {
  for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
    if (std::strcmp(type.enumerators[e].name ? type.enumerators[e].name : "", name ? name : "") ==
        0) {
      return &type.enumerators[e];
    }
  }
  return nullptr;
}
// Why `mapping`, unmapped, restores nothing: its name is not the reader's, or its aliases part
// ways there.
inline std::string unmapped_enumerator(const TypeInfo& reader, const EnumMapping& mapping) {
  return std::string(mapping.name ? mapping.name : "") +
         (reader_enumerator(reader, mapping.name) != nullptr
              ? " and its aliases name different values in this build"
              : " not in this build");
}

// A byte copy of a copy-only value: `length` wire bytes at `wire` go to `dst` in the reader.
struct CopyRun {
  std::uint32_t wire;
  std::uint32_t dst;
  std::uint32_t length;
};

// A bit-field of a copy-only value: the integer in `size` wire bytes at `wire` goes into the
// `width` bits from `bit_offset` of the storage unit at `dst` in the reader, if it fits.
struct CopyBits {
  std::uint32_t wire;
  std::uint32_t dst;
  std::uint16_t bit_offset;
  std::uint16_t width;
  std::uint8_t size;
  bool is_signed;
};

struct PlanNode;

// Fields [first_field, end_field) of a struct that is not copy-only as a whole: when `copy` is
// set, consecutive copy-only fields restored as one copy program (its offsets are the
// struct's); else the one field the decoder handles in place (a pointer, a container, a
// converted, ranged or validated value, a bit-field, a time of a clock, a removed field).
struct CopySegment {
  std::uint32_t first_field;
  std::uint32_t end_field;
  const PlanNode* copy;
};

struct PlanNode {
  std::uint32_t writer = kNoType;
  std::uint32_t reader = kNoType;
  Action action = Action::Skip;
  Decision decision = Decision::Restored;
  bool lossy = false;
  std::string detail;

  const PlanNode* skip = nullptr;              // Reject: how to consume the writer value
  bool identical = false;                      // Scalar: same representation, copy the bytes
  std::vector<EnumMapping> enum_map;           // Scalar from an enum: writer value -> reader value
  std::vector<FieldPlan> fields;               // Struct: one per writer field, in writer order
  const PlanNode* element = nullptr;           // Array, Container, Optional, UniquePtr, pointers
  const PlanNode* element_skip = nullptr;      // Array: elements beyond the reader's length, if any
  std::uint64_t reader_count = 0;              // Array
  std::uint32_t reader_stride = 0;             // Array: reader element size
  std::vector<const PlanNode*> alternatives;   // Variant: per writer alternative
  std::vector<std::uint32_t> alternative_map;  // Variant: reader index or kNoType

  bool validated = false;  // reader type has a symcr_validate
  // This value or a part of it (a field, an element, a contained value; not a pointee, an
  // object of its own) may be refused value by value: validated, or converted by a rule that
  // can reject (a scalar conversion, a bit-field, a range, a re-encoded string, a variant
  // alternative the reader lacks). A container element holding one is judged as a whole.
  // Derived from the other nodes (mark_judged_parts), never encoded in a plan image.
  bool holds_judged = false;
  // Struct: the writer's type differs from the reader's in its values (a field added, removed,
  // renamed or converted, at any depth; see docs/resolution.md), and the reader type has a
  // symcr_migrate hook (or, in a schema file, kTypeMigrated): restore calls `migrate`, which
  // is null when the reader is a schema without code (the CLI's plan).
  bool migrates = false;
  void (*migrate)(void* object, const OldValues& old) = nullptr;
  bool flat_reader = false;  // reader type is plain bytes (staged by copy)

  // Copy-only (structs, arrays, identical scalars and unions all the way down: every field
  // kept, no conversion, range or nested validator; integer bit-fields allowed): restoring it
  // is checking the bools and bit-field values and copying `copy_runs` and `copy_bits`, over
  // exactly `copy_wire` payload bytes.
  bool copy_only = false;
  std::uint8_t copy_state = 0;  // planner: 0 not computed, 1 computed or under way
  std::uint32_t copy_wire = 0;
  std::vector<CopyRun> copy_runs;
  std::vector<std::uint32_t> copy_bools;  // wire offsets of bools, each must be 0 or 1
  std::vector<CopyBits> copy_bits;
  // Struct, not copy-only, with a run of copy-only fields: its fields as segments
  // (derive_copy_segments), so that a state holding a few pointers still restores its
  // plain bytes by bulk copies. Derived from the other nodes, never encoded in a plan image.
  std::vector<CopySegment> copy_segments;
};

struct RootPlan {
  std::uint32_t reader_root = kNoType;  // kNoType: root removed
  const PlanNode* node = nullptr;
  std::uint32_t counter = 0;
};

struct Plan final : ReportSource {
  // The schema-level report, written on first use (a restore that is not strict and whose
  // report is not read never writes it) and then kept; thread-safe.
  const std::vector<ReportEntry>& entries() const override;
  // Some schema-level decision loses data (what strict mode refuses); writes the report.
  bool any_lossy() const;

  // Owns *writer, whose names the cached plan must outlive the caller's schema with; null when
  // the writer is the reader itself (restoring the same build).
  std::shared_ptr<const ParsedSchema> writer_owner;
  // writer_owner's bytes' share of a record's CRC: a standalone record carrying them inline (an
  // earlier build's checkpoint restored again) is checked without reading them twice.
  Crc32cSpan writer_crc;
  const Schema* writer = nullptr;
  const Schema* reader = nullptr;
  std::deque<PlanNode> nodes;               // stable addresses
  std::vector<RootPlan> roots;              // per writer root
  std::vector<const PlanNode*> heap_nodes;  // per writer type: how a heap object maps
  std::vector<std::uint32_t> shared_types;  // per reader type: a SharedPtr<it> type or kNoType
  WireSizes wire_sizes;                     // per writer type (payload_grammar.hpp)
  // Per counter, its schema-level path "scope::name" (a root: its name alone), spelled only
  // when a value-level entry needs it. The names point into the writer schema.
  struct CounterPath {
    const char* scope;  // a field's writer type name, or nullptr for a root
    const char* name;
  };
  std::vector<CounterPath> counter_paths;
  // Names a decoded plan image spelled out (plan_image.hpp): in the writer schema otherwise.
  std::deque<std::string> image_names;
  // Every root kept and copy-only (see PlanNode::copy_only): restore checks the size and the
  // bools and copies, without the general decoder.
  bool copy_only_payload = false;
  std::uint64_t copy_only_payload_size = 0;
  // The copy programs of PlanNode::copy_segments (stable addresses; not plan nodes).
  std::deque<PlanNode> segment_programs;
  // The reader's clocks (by ClockInfo::index) and, for each, the writer's clock of that name
  // (kNoType when the checkpoint has no reading of it): map_clocks().
  std::vector<const ClockInfo*> reader_clocks;
  std::vector<std::uint32_t> writer_clock_of;
  Status status;  // Incompatible when nothing can be restored

  // The plan as the device profile's cross-version executor runs it (device_plan_encode.hpp),
  // for the process's first restore through the plan (restore.cpp). prepare_restore encodes it
  // once, if that executor holds the plan, and then sets held_image_ready.
  mutable std::once_flag held_image_made;
  mutable std::vector<std::uint8_t> held_image;
  mutable std::atomic<bool> held_image_ready{false};
  mutable FirstTime restored;  // that first restore has been taken

  // Written once by entries() (Planner::build_report).
  mutable std::once_flag report_written;
  mutable std::vector<ReportEntry> report_entries;
  mutable bool report_lossy = false;
};

// The cached plan for restoring checkpoints written with `writer` (whose serialised form
// hashes to `writer_hash`) into `reader`. A new plan shares `writer_owner` (which owns
// `writer`) if given, uses the reader if `writer` is the reader, and else keeps a copy.
std::shared_ptr<const Plan> plan_for(const Schema& writer, std::uint64_t writer_hash,
                                     const Schema& reader, Status& status,
                                     std::shared_ptr<const ParsedSchema> writer_owner = nullptr);

// Plans `writer` against `reader`, bypassing the cache and any embedded image, and encodes the
// plan as an image (plan_image.hpp): what symcr-gen embeds for a previous build's schema.
// A plan that restores nothing (Incompatible) is encoded as well: restore reports it the same.
void plan_image_for(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                    std::uint64_t reader_hash, std::vector<std::uint8_t>& image);

// A cached plan for (writer_hash, reader), or nullptr; no plan is built. For callers holding
// an inline schema: when its bytes are the plan's writer's, it need not be hashed or parsed.
std::shared_ptr<const Plan> cached_plan(std::uint64_t writer_hash, const Schema& reader);

bool names_match(const TypeInfo& writer, const TypeInfo& reader);

// Fills Plan::reader_clocks and writer_clock_of from the plan's schemas (planned or decoded).
void map_clocks(Plan& plan);
// The reader field a FieldPlan of struct node `n` restores into is a time of a clock.
const FieldTime* reader_time(const Schema& reader, const PlanNode& n, const FieldPlan& field);

// Sets every node's holds_judged from the nodes' `validated`, their conversions and their parts:
// once a plan's nodes are final (planned, or decoded from an image).
void mark_judged_parts(Plan& plan);

// Sets every struct node's copy_segments (and fills Plan::segment_programs) from the nodes'
// copy programs, and every FieldPlan::time: once a plan's nodes are final (planned, or decoded
// from an image).
void derive_copy_segments(Plan& plan);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PLAN_HPP
