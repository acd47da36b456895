// Encoding plan images (plan_image.hpp): symcr-gen's side, and the tests'. A program that only
// decodes images does not link this file.
#include <map>
#include <string>

#include "plan_image.hpp"
#include "planner.hpp"
#include "wire.hpp"

namespace symcr::detail {
namespace {

using namespace plan_image;

class ImageWriter {
 public:
  ImageWriter(const Plan& plan, std::vector<std::uint8_t>& out) : out_(out) {
    std::uint32_t index = 0;
    for (const PlanNode& n : plan.nodes) node_index_[&n] = ++index;
    const Schema& w = *plan.writer;
    for (std::uint32_t t = 0; t < w.type_count; ++t) {
      const TypeInfo& type = w.types[t];
      names_.emplace(type.name, Ref{NameKind::TypeName, t, 0});
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        names_.emplace(type.fields[f].name, Ref{NameKind::FieldName, t, f});
      }
      for (std::uint32_t e = 0; e < type.enumerator_count; ++e) {
        names_.emplace(type.enumerators[e].name, Ref{NameKind::EnumeratorName, t, e});
      }
    }
    for (std::uint32_t r = 0; r < w.root_count; ++r) {
      names_.emplace(w.roots[r].name, Ref{NameKind::RootName, r, 0});
    }
  }

  void u8(std::uint8_t v) { put_u8(out_, v); }
  void u16(std::uint16_t v) { put_u16(out_, v); }
  void u32(std::uint32_t v) { put_u32(out_, v); }
  void u64(std::uint64_t v) { put_u64(out_, v); }
  void i64(std::int64_t v) { put_le(out_, v); }
  void f64(double v) { put_le(out_, v); }
  void text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    out_.insert(out_.end(), s.begin(), s.end());
  }
  void node(const PlanNode* n) { u32(n ? node_index_.at(n) : 0); }
  void name(const char* s) {
    if (s == nullptr) {
      u8(static_cast<std::uint8_t>(NameKind::Null));
      return;
    }
    const auto found = names_.find(s);
    if (found == names_.end()) {  // not the writer's own string: spelled out
      u8(static_cast<std::uint8_t>(NameKind::Text));
      text(s);
      return;
    }
    u8(static_cast<std::uint8_t>(found->second.kind));
    u32(found->second.a);
    u32(found->second.b);
  }
  template <typename T, typename Each>
  void list(const std::vector<T>& items, Each each) {
    u32(static_cast<std::uint32_t>(items.size()));
    for (const T& item : items) each(item);
  }

 private:
  struct Ref {
    NameKind kind;
    std::uint32_t a, b;
  };
  std::vector<std::uint8_t>& out_;
  std::map<const PlanNode*, std::uint32_t> node_index_;
  std::map<const char*, Ref> names_;  // by address: the plan points into the writer schema
};

void encode_node(ImageWriter& out, const PlanNode& n) {
  out.u32(n.writer);
  out.u32(n.reader);
  out.u8(static_cast<std::uint8_t>(n.action));
  out.u8(static_cast<std::uint8_t>(n.decision));
  out.u8(static_cast<std::uint8_t>((n.lossy ? kLossy : 0) | (n.identical ? kIdentical : 0) |
                                   (n.validated ? kValidated : 0) | (n.migrates ? kMigrates : 0) |
                                   (n.flat_reader ? kFlatReader : 0) |
                                   (n.copy_only ? kCopyOnly : 0)));
  out.u8(n.copy_state);
  out.text(n.detail);
  out.node(n.skip);
  out.node(n.element);
  out.node(n.element_skip);
  out.u64(n.reader_count);
  out.u32(n.reader_stride);
  out.list(n.enum_map, [&](const EnumMapping& m) {
    out.i64(m.writer_value);
    out.name(m.name);
    out.u8(m.mapped ? 1 : 0);
    out.i64(m.reader_value);
  });
  out.list(n.fields, [&](const FieldPlan& f) {
    out.node(f.node);
    out.u32(f.reader_field);
    out.u32(f.reader_offset);
    out.u16(f.bit_offset);
    out.u16(f.bit_width);
    out.u8(f.has_range ? 1 : 0);
    out.f64(f.range_min);
    out.f64(f.range_max);
    out.u32(f.counter);
    out.name(f.name);
  });
  out.list(n.alternatives, [&](const PlanNode* a) { out.node(a); });
  out.list(n.alternative_map, [&](std::uint32_t r) { out.u32(r); });
  out.u32(n.copy_wire);
  out.list(n.copy_runs, [&](const CopyRun& r) {
    out.u32(r.wire);
    out.u32(r.dst);
    out.u32(r.length);
  });
  out.list(n.copy_bools, [&](std::uint32_t wire) { out.u32(wire); });
  out.list(n.copy_bits, [&](const CopyBits& b) {
    out.u32(b.wire);
    out.u32(b.dst);
    out.u16(b.bit_offset);
    out.u16(b.width);
    out.u8(b.size);
    out.u8(b.is_signed ? 1 : 0);
  });
}

}  // namespace

void encode_plan_image(const Plan& plan, std::uint64_t writer_hash, std::uint64_t reader_hash,
                       std::vector<std::uint8_t>& bytes) {
  bytes.clear();
  ImageWriter out(plan, bytes);
  bytes.insert(bytes.end(), kImageMagic, kImageMagic + sizeof kImageMagic);
  out.u32(kImageVersion);
  out.u64(writer_hash);
  out.u64(reader_hash);
  out.u32(static_cast<std::uint32_t>(plan.nodes.size()));
  for (const PlanNode& n : plan.nodes) encode_node(out, n);
  out.list(plan.roots, [&](const RootPlan& r) {
    out.u32(r.reader_root);
    out.node(r.node);
    out.u32(r.counter);
  });
  out.list(plan.heap_nodes, [&](const PlanNode* n) { out.node(n); });
  out.list(plan.shared_types, [&](std::uint32_t t) { out.u32(t); });
  out.list(plan.wire_sizes.least, [&](std::uint64_t v) { out.u64(v); });
  out.list(plan.wire_sizes.fixed, [&](std::uint64_t v) { out.u64(v); });
  out.list(plan.counter_paths, [&](const Plan::CounterPath& c) {
    out.name(c.scope);
    out.name(c.name);
  });
  out.u8(plan.copy_only_payload ? 1 : 0);
  out.u64(plan.copy_only_payload_size);
  out.u8(static_cast<std::uint8_t>(plan.status.error()));
  out.text(plan.status.message());
}

void plan_image_for(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                    std::uint64_t reader_hash, std::vector<std::uint8_t>& image) {
  Plan plan;
  plan.writer = &writer;
  plan.reader = &reader;
  planning::Planner(plan).run();
  encode_plan_image(plan, writer_hash, reader_hash, image);
}

}  // namespace symcr::detail
