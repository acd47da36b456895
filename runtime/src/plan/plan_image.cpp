// Decoding plan images (plan_image.hpp): what a program does, when it restores a checkpoint of
// a build it has a plan for. The encoder (symcr-gen's and the tests') is plan_image_encode.cpp.
#include "plan_image.hpp"

#include <cstring>
#include <string>

#include "wire.hpp"

namespace symcr::detail {
namespace {

using namespace plan_image;

class ImageReader {
 public:
  ImageReader(const std::uint8_t* data, std::size_t size, Plan& plan, std::size_t node_count)
      : in_(data, size), plan_(plan), node_count_(node_count) {}

  bool ok() const { return ok_; }
  bool at_end() const { return in_.at_end(); }
  template <typename T>
  T fixed() {
    T value{};
    ok_ = ok_ && in_.read(value);
    return value;
  }
  std::uint8_t u8() { return fixed<std::uint8_t>(); }
  std::uint16_t u16() { return fixed<std::uint16_t>(); }
  std::uint32_t u32() { return fixed<std::uint32_t>(); }
  std::uint64_t u64() { return fixed<std::uint64_t>(); }
  // A count of items of at least `item_size` bytes each, checked against what is left.
  std::uint32_t count(std::size_t item_size) {
    const std::uint32_t n = u32();
    if (ok_ && static_cast<std::uint64_t>(n) * item_size > in_.remaining()) ok_ = false;
    return ok_ ? n : 0;
  }
  std::string text() {
    const std::uint32_t n = count(1);
    const std::uint8_t* bytes = nullptr;
    ok_ = ok_ && in_.bytes(n, bytes);
    return ok_ ? std::string(reinterpret_cast<const char*>(bytes), n) : std::string();
  }
  const PlanNode* node() {
    const std::uint32_t index = u32();
    if (index == 0) return nullptr;
    if (index > node_count_) {
      ok_ = false;
      return nullptr;
    }
    return &plan_.nodes[index - 1];
  }
  // A type index of `schema`, or kNoType where `allow_none`.
  std::uint32_t type(const Schema& schema, bool allow_none) {
    const std::uint32_t t = u32();
    if (!(t < schema.type_count || (allow_none && t == kNoType))) ok_ = false;
    return t;
  }
  const char* name() {
    const auto kind = static_cast<NameKind>(u8());
    if (kind == NameKind::Null || !ok_) return nullptr;
    if (kind == NameKind::Text) {
      plan_.image_names.push_back(text());
      return plan_.image_names.back().c_str();
    }
    const std::uint32_t a = u32(), b = u32();
    const Schema& w = *plan_.writer;
    const TypeInfo* type = kind != NameKind::RootName && a < w.type_count ? &w.types[a] : nullptr;
    switch (kind) {
      case NameKind::TypeName:
        if (type) return type->name;
        break;
      case NameKind::FieldName:
        if (type && b < type->field_count) return type->fields[b].name;
        break;
      case NameKind::EnumeratorName:
        if (type && b < type->enumerator_count) return type->enumerators[b].name;
        break;
      case NameKind::RootName:
        if (a < w.root_count) return w.roots[a].name;
        break;
      default:
        break;
    }
    ok_ = false;
    return nullptr;
  }

 private:
  WireReader in_;
  Plan& plan_;
  std::size_t node_count_;
  bool ok_ = true;
};

bool decode_node(ImageReader& in, const Plan& plan, PlanNode& n) {
  const Schema& writer = *plan.writer;
  const Schema& reader = *plan.reader;
  n.writer = in.type(writer, true);
  n.reader = in.type(reader, true);
  n.action = static_cast<Action>(in.u8());
  n.decision = static_cast<Decision>(in.u8());
  const std::uint8_t bits = in.u8();
  n.lossy = bits & kLossy;
  n.identical = bits & kIdentical;
  n.validated = bits & kValidated;
  n.migrates = bits & kMigrates;
  n.flat_reader = bits & kFlatReader;
  n.copy_only = bits & kCopyOnly;
  n.copy_state = in.u8();
  n.detail = in.text();
  n.skip = in.node();
  n.element = in.node();
  n.element_skip = in.node();
  n.reader_count = in.u64();
  n.reader_stride = in.u32();
  n.enum_map.resize(in.count(18));
  for (EnumMapping& m : n.enum_map) {
    m.writer_value = in.fixed<std::int64_t>();
    m.name = in.name();
    m.mapped = in.u8() != 0;
    m.reader_value = in.fixed<std::int64_t>();
  }
  n.fields.resize(in.count(38));
  for (FieldPlan& f : n.fields) {
    f.node = in.node();
    f.reader_field = in.u32();
    f.reader_offset = in.u32();
    f.bit_offset = in.u16();
    f.bit_width = in.u16();
    f.has_range = in.u8() != 0;
    f.range_min = in.fixed<double>();
    f.range_max = in.fixed<double>();
    f.counter = in.u32();
    f.name = in.name();
  }
  n.alternatives.resize(in.count(4));
  for (const PlanNode*& a : n.alternatives) a = in.node();
  n.alternative_map.resize(in.count(4));
  for (std::uint32_t& r : n.alternative_map) r = in.u32();
  n.copy_wire = in.u32();
  n.copy_runs.resize(in.count(12));
  for (CopyRun& r : n.copy_runs) r = CopyRun{in.u32(), in.u32(), in.u32()};
  n.copy_bools.resize(in.count(4));
  for (std::uint32_t& wire : n.copy_bools) wire = in.u32();
  n.copy_bits.resize(in.count(14));
  for (CopyBits& b : n.copy_bits) {
    b.wire = in.u32();
    b.dst = in.u32();
    b.bit_offset = in.u16();
    b.width = in.u16();
    b.size = in.u8();
    b.is_signed = in.u8() != 0;
  }
  // The hook is a symbol of this build: bound here, as the planner binds it.
  n.migrate = n.migrates && n.reader < reader.type_count ? reader.types[n.reader].migrate : nullptr;
  return in.ok();
}

}  // namespace

bool decode_plan_image(const std::uint8_t* image, std::size_t size, std::uint64_t writer_hash,
                       std::uint64_t reader_hash, Plan& plan) {
  constexpr std::size_t kHeaderSize = sizeof kImageMagic + 4 + 8 + 8 + 4;
  if (image == nullptr || size < kHeaderSize ||
      std::memcmp(image, kImageMagic, sizeof kImageMagic) != 0) {
    return false;
  }
  WireReader header(image + sizeof kImageMagic, size - sizeof kImageMagic);
  std::uint32_t version = 0, node_count = 0;
  std::uint64_t image_writer = 0, image_reader = 0;
  header.read(version);
  header.read(image_writer);
  header.read(image_reader);
  header.read(node_count);
  if (version != kImageVersion || image_writer != writer_hash || image_reader != reader_hash ||
      node_count > size) {
    return false;
  }
  plan.nodes.resize(node_count);  // first, so that references resolve to stable addresses
  ImageReader in(image + kHeaderSize, size - kHeaderSize, plan, node_count);
  for (PlanNode& n : plan.nodes) {
    if (!decode_node(in, plan, n)) return false;
  }
  const Schema& writer = *plan.writer;
  const Schema& reader = *plan.reader;
  plan.roots.resize(in.count(12));
  for (RootPlan& r : plan.roots) {
    r.reader_root = in.u32();
    r.node = in.node();
    r.counter = in.u32();
    if (r.node == nullptr || (r.reader_root != kNoType && r.reader_root >= reader.root_count)) {
      return false;
    }
  }
  plan.heap_nodes.resize(in.count(4));
  for (const PlanNode*& n : plan.heap_nodes) n = in.node();
  plan.shared_types.resize(in.count(4));
  for (std::uint32_t& t : plan.shared_types) t = in.u32();
  plan.wire_sizes.least.resize(in.count(8));
  for (std::uint64_t& v : plan.wire_sizes.least) v = in.u64();
  plan.wire_sizes.fixed.resize(in.count(8));
  for (std::uint64_t& v : plan.wire_sizes.fixed) v = in.u64();
  // Not in the image: the levels follow from the writer schema alone.
  plan.wire_sizes.levels = value_levels(writer);
  plan.wire_sizes.clock_count = static_cast<std::uint32_t>(schema_clocks(writer).size());
  map_clocks(plan);
  plan.counter_paths.resize(in.count(2));
  for (Plan::CounterPath& c : plan.counter_paths) {
    c.scope = in.name();
    c.name = in.name();
  }
  plan.copy_only_payload = in.u8() != 0;
  plan.copy_only_payload_size = in.u64();
  mark_judged_parts(plan);
  const auto error = static_cast<Error>(in.u8());
  const std::string message = in.text();
  if (error != Error::None) plan.status = Status(error, "%s", message.c_str());
  return in.ok() && in.at_end() && plan.roots.size() == writer.root_count &&
         plan.heap_nodes.size() == writer.type_count &&
         plan.shared_types.size() == reader.type_count &&
         plan.wire_sizes.least.size() == writer.type_count &&
         plan.wire_sizes.fixed.size() == writer.type_count;
}

}  // namespace symcr::detail
