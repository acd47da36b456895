// Resolution of a writer schema against the reader schema (docs/resolution.md), and the cache of
// plans. Struct-to-struct matching is decided by the holder (root or field name): a type
// renamed without annotation still matches through the field that holds it. Type names are
// compared only where no holder exists: bases, variant alternatives and pointees.
#include <algorithm>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "parsed_schema.hpp"
#include "plan_image.hpp"
#include "planner.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "unicode.hpp"

namespace symcr::detail {

void map_clocks(Plan& plan) {
  plan.reader_clocks = schema_clocks(*plan.reader);
  const std::vector<const ClockInfo*> writer_clocks = schema_clocks(*plan.writer);
  plan.writer_clock_of.assign(plan.reader_clocks.size(), kNoType);
  for (std::size_t c = 0; c < plan.reader_clocks.size(); ++c) {
    const ClockInfo* clock = plan.reader_clocks[c];
    if (!clock || !clock->name) continue;
    for (std::size_t w = 0; w < writer_clocks.size(); ++w) {
      if (writer_clocks[w] && writer_clocks[w]->name &&
          std::strcmp(writer_clocks[w]->name, clock->name) == 0) {
        plan.writer_clock_of[c] = static_cast<std::uint32_t>(w);
      }
    }
  }
}

const FieldTime* reader_time(const Schema& reader, const PlanNode& n, const FieldPlan& field) {
  if (field.reader_field == kNoType || n.reader >= reader.type_count) return nullptr;
  const FieldInfo& f = reader.types[n.reader].fields[field.reader_field];
  return (f.flags & kFieldClockTime) && f.time && f.time->clock ? f.time : nullptr;
}

namespace planning {

// Once per (writer, reader) pair, then cached: cold, so that it and what only it calls are
// optimised for size (tens of KB of .text) and kept off the hot pages.
void Planner::run() {
  plan_.wire_sizes = wire_sizes(writer_);
  plan_.shared_types.assign(reader_.type_count, kNoType);
  for (std::uint32_t t = 0; t < reader_.type_count; ++t) {
    const TypeInfo& type = reader_.types[t];
    if (type.kind == Kind::SharedPtr && type.element < reader_.type_count &&
        plan_.shared_types[type.element] == kNoType) {
      plan_.shared_types[type.element] = t;
    }
  }
  find_dynamic_bases();
  plan_roots();
  plan_.heap_nodes.assign(writer_.type_count, nullptr);
  for (std::uint32_t t = 0; t < writer_.type_count; ++t) {
    const TypeInfo& type = writer_.types[t];
    if ((type.kind == Kind::Pointer || type.kind == Kind::SharedPtr) &&
        type.element < writer_.type_count && !plan_.heap_nodes[type.element]) {
      plan_.heap_nodes[type.element] =
          node(type.element, find_reader_type(writer_.types[type.element]));
    }
  }
  // A heap object behind a pointer to a polymorphic base is saved as its dynamic type.
  for (std::uint32_t t = 0; t < writer_.type_count; ++t) {
    if ((writer_.types[t].flags & kTypeDynamicType) && writer_.types[t].kind == Kind::Struct &&
        !plan_.heap_nodes[t]) {
      plan_.heap_nodes[t] = node(t, find_reader_type(writer_.types[t]));
    }
  }
  map_clocks(plan_);
  decide_migrations();
  mark_judged_parts(plan_);
  for (PlanNode& n : plan_.nodes) compute_copy(n);
  compute_copy_only_payload();
  if (too_deep_) {
    plan_.status =
        Status(Error::Corrupt, "invalid schema: types nest deeper than %d levels", kMaxPlanDepth);
  }
}

// Per writer type: the writer knew a class equal to it or derived from it that it could save
// as a heap object's dynamic type.
void Planner::find_dynamic_bases() {
  std::vector<std::uint32_t> pending;
  for (std::uint32_t t = 0; t < writer_.type_count; ++t) {
    if (writer_.types[t].flags & kTypeDynamicType) pending.push_back(t);
  }
  dynamic_bases_.clear();
  mark_with_bases(writer_.types, writer_.type_count, pending, dynamic_bases_);
}

// ---- matching ------------------------------------------------------------------------
std::uint32_t Planner::find_reader_type(const TypeInfo& writer) const {
  // A restricted view (a shallow root's, or one of its reference members') shares its class's
  // name but never stands for the class.
  auto same_view = [&](const TypeInfo& reader) {
    return ((reader.flags ^ writer.flags) & kTypeShallow) == 0;
  };
  for (std::uint32_t t = 0; t < reader_.type_count; ++t) {
    if (same_name(reader_.types[t].name, writer.name) && reader_.types[t].kind == writer.kind &&
        same_view(reader_.types[t]))
      return t;
  }
  for (std::uint32_t t = 0; t < reader_.type_count; ++t) {
    if (names_match(writer, reader_.types[t]) && same_view(reader_.types[t])) return t;
  }
  return kNoType;
}

void Planner::plan_roots() {
  plan_.roots.resize(writer_.root_count);
  bool any_restorable = false;
  // Each reader root takes at most one writer root: exact names first, then old names.
  std::vector<std::uint32_t> matches(writer_.root_count, kNoType);
  std::vector<bool> taken(reader_.root_count, false);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t wr = 0; wr < writer_.root_count; ++wr) {
      for (std::uint32_t rr = 0; rr < reader_.root_count && matches[wr] == kNoType; ++rr) {
        const bool named = pass == 0
                               ? same_name(reader_.roots[rr].name, writer_.roots[wr].name)
                               : in_aliases(writer_.roots[wr].name, reader_.roots[rr].renamed_from);
        if (named && !taken[rr]) {
          matches[wr] = rr;
          taken[rr] = true;
        }
      }
    }
  }
  for (std::uint32_t wr = 0; wr < writer_.root_count; ++wr) {
    const RootInfo& writer = writer_.roots[wr];
    const std::uint32_t match = matches[wr];
    RootPlan& root = plan_.roots[wr];
    root.reader_root = match;
    root.node = node(writer.type, match == kNoType ? kNoType : reader_.roots[match].type);
    root.counter = new_counter(nullptr, writer.name);
    if (match != kNoType && root.node->action != Action::Reject) any_restorable = true;
  }
  if (writer_.root_count > 0 && !any_restorable) {
    plan_.status =
        Status(Error::Incompatible, "no root of the checkpoint can be restored into this build");
  }
}

std::uint32_t Planner::new_counter(const char* scope, const char* name) {
  plan_.counter_paths.push_back(Plan::CounterPath{scope, name});
  return static_cast<std::uint32_t>(plan_.counter_paths.size() - 1);
}

}  // namespace planning

namespace {

using planning::in_aliases;
using planning::Planner;
using planning::same_name;

struct CachedPlan {
  std::uint64_t writer_hash;
  const Schema* reader;
  const TypeInfo* reader_types;
  const RootInfo* reader_roots;
  std::shared_ptr<const Plan> plan;

  bool serves(std::uint64_t hash, const Schema& r) const {
    return writer_hash == hash && reader == &r && reader_types == r.types &&
           reader_roots == r.roots;
  }
};

std::mutex& plan_cache_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::deque<CachedPlan>& plan_cache() {
  static auto* cache = new std::deque<CachedPlan>();  // never freed
  return *cache;
}

// The image symcr-gen embedded for restoring checkpoints of the build whose schema hashes to
// `writer_hash` into the program's schema `reader` (PREVIOUS_SCHEMA), decoded into `plan`.
bool decode_embedded_plan(std::uint64_t writer_hash, const Schema& reader, Plan& plan) {
  if (!symcr_program_plans || !symcr_program_schema || symcr_program_schema() != &reader) {
    return false;
  }
  std::uint32_t count = 0;
  const PlannedSchema* embedded = symcr_program_plans(&count);
  for (std::uint32_t i = 0; embedded != nullptr && i < count; ++i) {
    if (embedded[i].writer_hash == writer_hash) {
      return decode_plan_image(embedded[i].image, embedded[i].size, writer_hash,
                               schema_blob(reader).hash, plan);
    }
  }
  return false;
}

}  // namespace

namespace {

// Whether restoring `n` itself may reject a value the checkpoint holds (its parts aside).
bool rejects_values(const PlanNode& n, const Schema& writer, const Schema& reader) {
  if (n.writer >= writer.type_count || n.reader >= reader.type_count) return false;
  switch (n.action) {
    case Action::Scalar:
      return !n.identical;
    case Action::String:
      return writer.types[writer.types[n.writer].element].size !=
             reader.types[reader.types[n.reader].element].size;
    case Action::Variant:
      return std::find(n.alternative_map.begin(), n.alternative_map.end(), kNoType) !=
             n.alternative_map.end();
    case Action::Struct:
      for (std::size_t f = 0; f < n.fields.size(); ++f) {
        const FieldPlan& field = n.fields[f];
        if (field.reader_field == kNoType) continue;
        if (field.has_range) return true;
        const TypeInfo& written = writer.types[n.writer];
        const std::uint16_t written_width =
            f < written.field_count ? written.fields[f].bit_width : 0;
        if (field.bit_width &&
            (written_width == 0 || written_width > field.bit_width || !field.node->identical)) {
          return true;
        }
      }
      return false;
    default:
      return false;
  }
}

}  // namespace

void mark_judged_parts(Plan& plan) {
  const auto holds = [](const PlanNode* part) { return part && part->holds_judged; };
  for (PlanNode& n : plan.nodes) {
    n.holds_judged = n.validated || rejects_values(n, *plan.writer, *plan.reader);
  }
  // A least fixed point: a recursive type's answer depends on itself.
  for (bool grew = true; grew;) {
    grew = false;
    for (auto it = plan.nodes.rbegin(); it != plan.nodes.rend(); ++it) {
      PlanNode& n = *it;
      if (n.holds_judged) continue;
      bool any = false;
      switch (n.action) {
        case Action::Struct:
          for (const FieldPlan& field : n.fields) any = any || holds(field.node);
          break;
        case Action::Array:
        case Action::Container:
        case Action::Optional:
        case Action::UniquePtr:
          any = holds(n.element);
          break;
        case Action::Variant:
          for (const PlanNode* alternative : n.alternatives) any = any || holds(alternative);
          break;
        default:  // scalars, strings, unions; pointees are objects of their own
          break;
      }
      if (any) {
        n.holds_judged = true;
        grew = true;
      }
    }
  }
}

bool names_match(const TypeInfo& writer, const TypeInfo& reader) {
  return same_name(writer.name, reader.name) || in_aliases(writer.name, reader.renamed_from);
}

std::shared_ptr<const Plan> plan_for(const Schema& writer, std::uint64_t writer_hash,
                                     const Schema& reader, Status& status,
                                     std::shared_ptr<const ParsedSchema> writer_owner) {
  constexpr std::size_t kMaxPlans = 8;
  {
    std::lock_guard<std::mutex> lock(plan_cache_mutex());
    for (const CachedPlan& cached : plan_cache()) {
      // The counts guard against a caller passing one hash for different schemas.
      if (cached.serves(writer_hash, reader) &&
          cached.plan->writer->type_count == writer.type_count &&
          cached.plan->writer->root_count == writer.root_count) {
        return cached.plan;
      }
    }
  }
  auto plan = std::make_shared<Plan>();
  // Cached plans never point into a caller's buffers: the writer is the reader (which outlives
  // its plans, as the cache's key), a parsed schema shared with the caller, or else a copy (a
  // round trip through the wire form).
  if (&writer == &reader) {
    plan->writer = &reader;
  } else if (writer_owner && &writer_owner->schema() == &writer) {
    plan->writer_owner = std::move(writer_owner);
    plan->writer = &writer;
  } else {
    SchemaBlob blob;
    serialise_blob(writer, blob);
    auto copy = std::make_shared<ParsedSchema>();
    status = parse_schema(blob.data, blob.size, *copy);
    if (!status.ok()) return nullptr;
    plan->writer = &copy->schema();
    plan->writer_owner = std::move(copy);
  }
  plan->reader = &reader;
  if (plan->writer_owner) {
    const std::vector<std::uint8_t>& bytes = plan->writer_owner->bytes();
    plan->writer_crc = crc32c_span(bytes.data(), bytes.size());
  }
  if (!decode_embedded_plan(writer_hash, reader, *plan)) {
    if (!plan->nodes.empty()) {  // an image that did not fit: planned afresh, as without one
      auto fresh = std::make_shared<Plan>();
      fresh->writer_owner = plan->writer_owner;
      fresh->writer_crc = plan->writer_crc;
      fresh->writer = plan->writer;
      fresh->reader = plan->reader;
      plan = std::move(fresh);
    }
    Planner(*plan).run();
  }
  derive_copy_segments(*plan);
  std::lock_guard<std::mutex> lock(plan_cache_mutex());
  plan_cache().push_front(CachedPlan{writer_hash, &reader, reader.types, reader.roots, plan});
  if (plan_cache().size() > kMaxPlans) plan_cache().pop_back();
  return plan;
}

std::shared_ptr<const Plan> cached_plan(std::uint64_t writer_hash, const Schema& reader) {
  std::lock_guard<std::mutex> lock(plan_cache_mutex());
  for (const CachedPlan& cached : plan_cache()) {
    if (cached.serves(writer_hash, reader)) return cached.plan;
  }
  return nullptr;
}

}  // namespace symcr::detail
