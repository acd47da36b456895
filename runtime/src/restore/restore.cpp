// The restore path (docs/resolution.md): a payload written with the writer schema is decoded
// twice along the same plan.
//   Pass 1 (Check) reads everything, checks every bound, conversion, enumerator, range,
//   validator and reference, and builds the report; nothing live is written.
//   Pass 2 (Apply) runs only when pass 1 succeeded (and, in strict mode, found nothing lossy):
//   it decodes again, writing into live objects, materialises heap objects, and fixes up
//   pointer slots last.
// Both passes are one traversal (restore_traversal.hpp), so per-value facts that pass 1 decides
// (validator verdicts, pointer decisions, container counts) are looked up by their ordinal in
// stream order in pass 2.
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "device_format.hpp"
#include "device_plan_encode.hpp"
#include "parsed_schema.hpp"
#include "report_access.hpp"
#include "restore_payload.hpp"
#include "restore_traversal.hpp"
#include "schema_facts.hpp"
#include "scratch.hpp"
#include "symcr/device.hpp"

namespace symcr::detail {
namespace {

template <typename T>
std::size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

// The last restore's scratch on this thread (thread_scratch_bytes).
thread_local std::size_t last_restore_scratch = 0;

}  // namespace

namespace restoring {

Status Restorer::check() {
  CheckPass pass(*this);
  Traversal<CheckPass> walk(*this, pass);
  PayloadReader& in = walk.reader();
  ClockReadings readings;
  if (!walk.objects() || !decode_references(in) || !in.clock_readings(readings) || !in.finish() ||
      !check_slots()) {
    return error_;
  }
  decide_clock_deltas(readings);
  claim_live_objects();
  decide_materialisation();
  for (RefRecord& ref : refs_) map_reference(ref);
  decide_slots();
  summarise_rejections();
  return Status();
}

// Capacity of the decoding tables (thread_scratch_bytes).
std::size_t Restorer::scratch_bytes() const {
  return lease_.table_bytes() + explained_.bucket_count() * sizeof(void*) +
         explained_.size() * (sizeof(std::pair<std::uint32_t, std::string>) + 2 * sizeof(void*));
}

std::size_t RestoreTables::bytes() const {
  std::size_t total =
      bytes_of(frames) + bytes_of(rejection_counts) + bytes_of(handed_counts) + bytes_of(verdicts) +
      bytes_of(part_verdicts) + bytes_of(slots) + bytes_of(containers) + bytes_of(heap) +
      bytes_of(refs) + bytes_of(steps) + bytes_of(mapped) + bytes_of(claimed) +
      materialisable.capacity() / 8 + bytes_of(element_needed) + bytes_of(heap_live) +
      bytes_of(holders) + bytes_of(applied_slots) + bytes_of(element_slots) +
      bytes_of(element_addresses) + bytes_of(string_scratch) + bytes_of(clock_deltas);
  for (const std::vector<void*>& addresses : element_addresses) total += bytes_of(addresses);
  for (const RefRecord& ref : refs) total += ref.why.capacity();
  return total;
}

void RestoreTables::reserve_first_records() {
  constexpr std::size_t kRecords = 16;  // a specimen's restore (a few pointers and modes) fits
  frames.reserve(kRecords);
  slots.reserve(kRecords);
  refs.reserve(kRecords);
  steps.reserve(kRecords);
  mapped.reserve(kRecords);
  applied_slots.reserve(kRecords);
}

void RestoreTables::clear() {
  frames.clear();
  rejection_counts.clear();
  handed_counts.clear();
  verdicts.clear();
  part_verdicts.clear();
  slots.clear();
  containers.clear();
  heap.clear();
  refs.clear();
  steps.clear();
  mapped.clear();
  claimed.clear();
  materialisable.clear();
  element_needed.clear();
  heap_live.clear();
  holders.clear();
  applied_slots.clear();
  element_slots.clear();
  for (std::vector<void*>& addresses : element_addresses) addresses.clear();  // kept for reuse
  string_scratch.clear();
  clock_deltas.clear();
}

namespace {
thread_local RestoreTables kept_tables;
thread_local bool kept_tables_leased = false;
}  // namespace

RestoreTablesLease::RestoreTablesLease() : kept_(!kept_tables_leased) {
  tables_ = kept_ ? &kept_tables : new RestoreTables();
  kept_tables_leased = true;
  tables_->clear();
}

void RestoreTablesLease::prepare_thread_tables() {
  if (!kept_tables_leased) kept_tables.reserve_first_records();
}

std::size_t RestoreTablesLease::table_bytes() const {
  if (counted_bytes_ == kNotCounted) counted_bytes_ = tables_->bytes();
  return counted_bytes_;
}

RestoreTablesLease::~RestoreTablesLease() {
  if (!kept_) {
    delete tables_;
    return;
  }
  if (table_bytes() > kKeptRestoreTableBytes) *tables_ = RestoreTables();
  kept_tables_leased = false;
}

void Restorer::apply() {
  create_heap_objects();
  ApplyPass pass(*this, report_);
  // Cannot fail: pass 1 checked the same bytes along the same plan.
  Traversal<ApplyPass>(*this, pass).objects();
  fix_up_slots();
  for (std::size_t h = 0; h < holders_.size(); ++h) {
    if (!holders_[h]) continue;
    const auto* ops = static_cast<const SharedPtrOps*>(
        reader_.types[plan_.shared_types[heap_[h].node->reader]].ops);
    ops->destroy_holder(holders_[h]);
  }
}

}  // namespace restoring

namespace {

using restoring::copy_only_valid;
using restoring::copy_only_write;

// The fast path for a copy-only plan (the same build, or changes that only move fields): true
// when the payload is exactly the roots' copy programs and two empty sections, every bool 0 or
// 1 and every bit-field value within its width, after copying (if `apply`). False for anything
// else, leaving the general decoder to find and name the fault; nothing is written then.
bool restore_copy_only(const Plan& plan, const std::uint8_t* payload, std::size_t size,
                       bool apply) {
  if (payload == nullptr || size != plan.copy_only_payload_size) return false;
  const Schema& reader = *plan.reader;
  const std::uint8_t* at = payload;
  for (const RootPlan& root : plan.roots) {
    if (!copy_only_valid(*root.node, at)) return false;
    at += root.node->copy_wire;
  }
  std::uint32_t heap_count = 0, reference_count = 0;
  std::memcpy(&heap_count, at, sizeof heap_count);  // zero in any byte order
  std::memcpy(&reference_count, at + sizeof heap_count, sizeof reference_count);
  if (heap_count != 0 || reference_count != 0) return false;
  if (!apply) return true;
  at = payload;
  for (const RootPlan& root : plan.roots) {
    copy_only_write(*root.node, at,
                    static_cast<std::uint8_t*>(reader.roots[root.reader_root].address));
    at += root.node->copy_wire;
  }
  return true;
}

// The schema-level report of restoring a schema into itself, planned when first read: the
// same-build path below restores without a plan.
struct SameBuildReport final : ReportSource {
  SameBuildReport(const Schema& schema, std::uint64_t hash) : schema_(schema), hash_(hash) {}
  const std::vector<ReportEntry>& entries() const override {
    std::call_once(planned_, [this] {
      Status status;
      plan_ = plan_for(schema_, hash_, schema_, status);
    });
    static const std::vector<ReportEntry> kNone;
    return plan_ ? plan_->entries() : kNone;
  }

 private:
  const Schema& schema_;
  std::uint64_t hash_;
  mutable std::once_flag planned_;
  mutable std::shared_ptr<const Plan> plan_;
};

// Scratch for one of the device profile's decoders restoring into `reader`: the one prepared
// when the store was opened, if it is still there, or else allocated. Not kept, and not
// zero-filled (a decoder stages every root's bytes before it reads them). Through
// std::allocator, as containers allocate: in a fresh process new[] and delete[] are often not
// bound yet, and binding them lazily cost more than a tenth of a first restore.
class HeldScratch {
 public:
  explicit HeldScratch(const SchemaCacheEntry& reader)
      : size_(device::scratch_size(*reader.schema)), bytes_(reader.take_first_scratch()) {
    if (bytes_ == nullptr) bytes_ = std::allocator<std::uint8_t>().allocate(size_);
  }
  ~HeldScratch() { std::allocator<std::uint8_t>().deallocate(bytes_, size_); }
  HeldScratch(const HeldScratch&) = delete;
  HeldScratch& operator=(const HeldScratch&) = delete;
  std::uint8_t* bytes() const { return bytes_; }
  std::size_t size() const { return size_; }

 private:
  std::size_t size_;
  std::uint8_t* bytes_;
};

// The first restore of a build's own checkpoint in a process, every type one the device
// profile's decoder holds: that small table-driven decoder restores it with no plan to build,
// which is what a freshly started build waited for. Later restores use the plan, built once:
// its copy programs are faster when repeated. The decoder is all-or-nothing, so anything it
// refuses (a value its range or validator rejects, heap objects, a damaged payload) has changed
// nothing and goes the general way, which applies the rules per value and names the fault.
// Strict mode goes the general way too: it decides from the plan.
bool restore_same_build(const Schema& schema, std::uint64_t hash, const std::uint8_t* payload,
                        std::size_t size, Report& report) {
  const SchemaCacheEntry& entry = schema_cache_entry(schema);
  if (!entry.first_same_build_restore() || !entry.device_holdable()) return false;
  const HeldScratch scratch(entry);
  const device::detail::PayloadShape shape = entry.held_shape();
  if (device::detail::restore_held_payload(schema, payload, size, scratch.bytes(), scratch.size(),
                                           &shape, /*as_host=*/true) != device::Result::Ok) {
    return false;
  }
  ReportAccess::set_source(report, std::make_shared<SameBuildReport>(schema, hash));
  last_restore_scratch = 0;  // no decoding tables
  return true;
}

// The device profile's cross-version executor (device_plan.cpp) is declared weak, for firmware
// that has no plans: this reference links it into every host program.
extern "C" const char symcr_device_plan_executor;
[[maybe_unused]] __attribute__((used)) const char* const kDevicePlanExecutor =
    &symcr_device_plan_executor;

// Whether the value of `n` and everything in it is written by the executor exactly as the
// planned path writes it: nothing left out (a field, an element, a value that changed kind),
// whose bytes the executor would skip where the planned path checks them, and no validator
// (the planned path judges a value-initialised staged object, the executor a copy of the
// running build's). A pointer's target is a reference, not a value decoded here.
bool written_alike(const PlanNode* n) {
  if (n == nullptr || n->validated) return false;
  switch (n->action) {
    case Action::Scalar:
    case Action::Union:
    case Action::Pointer:
      return true;
    case Action::Array:
      return n->element_skip == nullptr && written_alike(n->element);
    case Action::Struct:
      for (const FieldPlan& field : n->fields) {
        if (field.reader_field == kNoType || !written_alike(field.node)) return false;
      }
      return true;
    default:
      return false;
  }
}

// Encodes `plan` for the device profile's cross-version executor, once, when that executor
// holds it: both builds' types are ones the device profile holds, with no times of clocks (it
// rebases every time, as after a reset), every root is kept and written alike, and the
// executor carries out each of the plan's decisions.
void make_held_image(const Plan& plan, std::uint64_t writer_hash) {
  std::call_once(plan.held_image_made, [&plan, writer_hash] {
    const Schema& reader = *plan.reader;
    if (!plan.status.ok() || plan.wire_sizes.clock_count != 0 ||
        !schema_cache_entry(reader).device_holdable() ||
        device::check_schema(*plan.writer) != device::Result::Ok) {
      return;
    }
    for (const RootPlan& root : plan.roots) {
      if (root.reader_root == kNoType || !written_alike(root.node)) return;
    }
    std::string refused;
    if (!device_plan_image_of(plan, writer_hash, schema_blob(reader).hash, plan.held_image,
                              refused)) {
      plan.held_image.clear();
      return;
    }
    plan.held_image_ready.store(true, std::memory_order_release);
  });
}

// The first restore through a plan in a process, when prepare_restore encoded it for the device
// profile's cross-version executor: that small executor restores another build's checkpoint as
// restore_same_build restores the build's own, with far less code to bring into the caches
// than the two passes, and as all-or-nothing: whatever it refuses goes the general way.
bool restore_held_across(const Plan& plan, const std::uint8_t* payload, std::size_t size) {
  if (!plan.held_image_ready.load(std::memory_order_acquire) || !plan.restored.claim()) {
    return false;
  }
  const HeldScratch scratch(schema_cache_entry(*plan.reader));
  const PlannedSchema planned{0, plan.held_image.data(),
                              static_cast<std::uint32_t>(plan.held_image.size())};
  return device::detail::restore_planned_payload(*plan.reader, planned, payload, size,
                                                 scratch.bytes(), scratch.size(),
                                                 /*as_host=*/true) == device::Result::Ok;
}

Report run_restore(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                   std::size_t size, const Schema& reader, const RestoreOptions& options,
                   bool plan_only, bool apply, std::shared_ptr<const ParsedSchema> writer_owner) {
  Report report;
  if (&writer == &reader && apply && !plan_only && !options.strict &&
      restore_same_build(reader, writer_hash, payload, size, report)) {
    return report;
  }
  Status status;
  std::shared_ptr<const Plan> plan =
      plan_for(writer, writer_hash, reader, status, std::move(writer_owner));
  if (!plan) {
    ReportAccess::set_status(report, status);
    return report;
  }
  // The schema-level entries depend only on the plan: shared with it, copied only if a
  // value-level entry is added.
  ReportAccess::set_source(report, plan);
  if (!plan->status.ok()) {
    ReportAccess::set_status(report, plan->status);
    return report;
  }
  if (!payload && size) {
    ReportAccess::set_status(report, Status(Error::Corrupt, "invalid payload: no bytes"));
    return report;
  }
  const bool strict_refusal = options.strict && plan->any_lossy();
  if (!plan_only && !strict_refusal && plan->copy_only_payload &&
      restore_copy_only(*plan, payload, size, apply)) {
    last_restore_scratch = 0;  // no decoding tables
    return report;
  }
  if (apply && !plan_only && !options.strict && restore_held_across(*plan, payload, size)) {
    last_restore_scratch = 0;
    return report;
  }
  std::size_t value_rejections = 0;
  restoring::Restorer restorer(*plan, payload, size, report, /*dry_run=*/!apply);
  if (!plan_only) {
    status = restorer.check();
    if (!status.ok()) {
      ReportAccess::set_status(report, status);
      return report;
    }
    value_rejections = restorer.value_rejections();
  }
  if (options.strict && (value_rejections > 0 || plan->any_lossy())) {
    const ReportEntry* first = nullptr;
    for (const ReportEntry& entry : report.entries()) {
      if (entry.lossy) {
        first = &entry;
        break;
      }
    }
    ReportAccess::set_status(
        report,
        Status(Error::Strict, "strict mode: lossy restore refused (first: %s: %s %s)",
               first ? first->path.c_str() : "?", first ? decision_name(first->decision) : "",
               first ? first->detail.c_str() : ""));
    return report;
  }
  if (apply) restorer.apply();
  last_restore_scratch = restorer.scratch_bytes();
  return report;
}

}  // namespace

ScratchBytes thread_scratch_bytes() {
  ScratchBytes bytes;
  bytes.checkpoint = encode_scratch_bytes();
  bytes.restore = last_restore_scratch;
  return bytes;
}

Report restore_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                       std::size_t size, const Schema& reader, const RestoreOptions& options,
                       std::shared_ptr<const ParsedSchema> writer_owner) {
  return run_restore(writer, writer_hash, payload, size, reader, options, false, true,
                     std::move(writer_owner));
}

void prepare_restore(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                     std::shared_ptr<const ParsedSchema> writer_owner) {
  const SchemaCacheEntry& entry = schema_cache_entry(reader);
  if (&writer == &reader) {
    if (entry.device_holdable()) {
      entry.prepare_held_steps();
      entry.prepare_first_scratch();
    }
    return;
  }
  Status ignored;
  const std::shared_ptr<const Plan> plan =
      plan_for(writer, writer_hash, reader, ignored, std::move(writer_owner));
  restoring::RestoreTablesLease::prepare_thread_tables();
  if (!plan) return;
  make_held_image(*plan, writer_hash);
  if (plan->held_image_ready.load(std::memory_order_acquire)) entry.prepare_first_scratch();
}

Report plan_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                    std::size_t size, const Schema& reader, const RestoreOptions& options) {
  const bool plan_only = payload == nullptr && size == 0;
  return run_restore(writer, writer_hash, payload, size, reader, options, plan_only, false,
                     nullptr);
}

}  // namespace symcr::detail
