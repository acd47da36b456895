// Device plan images (device_plan_encode.hpp): the host planner's decisions for a previous
// build, compiled into the device profile's ops. The device profile's kinds have fixed wire
// sizes, so every value's wire offset is known here and arrays become loops.
#include "device_plan_encode.hpp"

#include <cstring>

#include "device_plan.hpp"
#include "plan.hpp"
#include "planner.hpp"
#include "wire.hpp"

namespace symcr::detail {
namespace {

namespace dp = symcr::device::plan;

// What the device runs when the image asks for something it cannot: the fixes a user has.
constexpr const char* kFixes =
    ": give it its previous type, rename it with SYMCR_RENAMED_FROM if it is another member "
    "now, keep it out of checkpoints with SYMCR_SKIP, or convert such checkpoints on the host "
    "(symcr convert) instead of naming this schema in PREVIOUS_SCHEMA";

struct Op {
  std::uint8_t code = 0, a = 0;
  std::uint16_t b = 0;
  std::uint32_t wire = 0, dst = 0;
};

class DeviceEncoder {
 public:
  DeviceEncoder(const Plan& plan) : plan_(plan), w_(*plan.writer), r_(*plan.reader) {}

  bool encode(std::uint64_t writer_hash, std::uint64_t reader_hash,
              std::vector<std::uint8_t>& image, std::string& error) {
    if (!plan_.status.ok()) {
      error =
          std::string("nothing of it restores into this build (") + plan_.status.message() + ")";
      return false;
    }
    std::uint64_t wire = 0;
    for (std::uint32_t i = 0; i < w_.root_count && error_.empty(); ++i) {
      const RootPlan& root = plan_.roots[i];
      const std::uint64_t size = fixed(w_.roots[i].type);
      if (root.reader_root != kNoType && root.node != nullptr) {
        push(Op{dp::kOpRoot, 0, 0, 0, root.reader_root});
        value(*root.node, static_cast<std::uint32_t>(wire), 0, w_.roots[i].name);
      }
      wire += size;
    }
    if (error_.empty() && (ops_.size() > 0xFFFF || table_.size() > 0xFFFF || wire > 0xFFFFFFFFu))
      fail(w_.root_count ? w_.roots[0].name : "", "makes a plan too large for the device");
    if (!error_.empty()) {
      error = error_;
      return false;
    }
    if (!paths()) {
      error = "'" + std::string(w_.root_count ? w_.roots[0].name : "") +
              "' makes a plan too large for the device (more than 65,534 types or members)";
      return false;
    }
    // Byte by byte: g++ 12 at -O2 misreads a range insert into the emptied vector as an
    // overflow (-Warray-bounds, -Wstringop-overflow).
    image.assign(sizeof dp::kPlanMagic, 0);
    std::memcpy(image.data(), dp::kPlanMagic, sizeof dp::kPlanMagic);
    put_u16(image, dp::kPlanVersion);
    put_u16(image, static_cast<std::uint16_t>(ops_.size()));
    put_u64(image, writer_hash);
    put_u64(image, reader_hash);
    put_u32(image, static_cast<std::uint32_t>(wire));
    put_u16(image, static_cast<std::uint16_t>(plan_.wire_sizes.clock_count));
    put_u16(image, static_cast<std::uint16_t>(table_.size()));
    put_u16(image, static_cast<std::uint16_t>(path_roots_.size() / 2));
    put_u16(image, static_cast<std::uint16_t>(path_types_.size() / 2));
    put_u32(image, static_cast<std::uint32_t>(path_fields_.size() / 2));
    static_assert(dp::kPathEntrySize == 4, "path entries are u16 pairs");
    for (const Op& op : ops_) {
      put_u8(image, op.code);
      put_u8(image, op.a);
      put_u16(image, op.b);
      put_u32(image, op.wire);
      put_u32(image, op.dst);
    }
    for (std::uint64_t entry : table_) put_u64(image, entry);
    for (const std::vector<std::uint32_t>* halves : {&path_roots_, &path_types_, &path_fields_}) {
      for (std::uint32_t half : *halves) put_u16(image, static_cast<std::uint16_t>(half));
    }
    return true;
  }

 private:
  std::uint64_t fixed(std::uint32_t writer_type) const {
    return plan_.wire_sizes.fixed[writer_type];
  }

  void fail(const std::string& path, const std::string& text) {
    if (error_.empty()) error_ = "'" + path + "' " + text;
  }

  void push(const Op& op) {
    ops_.push_back(op);
    mergeable_ = false;
  }
  // Bytes copied as they are, joined to the copy just before when they continue it.
  void copy(std::uint32_t wire, std::uint32_t dst, std::uint64_t length) {
    while (length > 0) {
      Op* last = mergeable_ ? &ops_.back() : nullptr;
      if (last && last->wire + last->b == wire && last->dst + last->b == dst &&
          last->b + length <= 0xFFFF) {
        last->b = static_cast<std::uint16_t>(last->b + length);
        return;
      }
      const std::uint16_t chunk = static_cast<std::uint16_t>(length > 0xFFFF ? 0xFFFF : length);
      push(Op{dp::kOpCopy, 0, chunk, wire, dst});
      mergeable_ = true;
      wire += chunk;
      dst += chunk;
      length -= chunk;
    }
  }
  std::uint16_t entries(std::initializer_list<std::uint64_t> values) {
    const std::size_t at = table_.size();
    table_.insert(table_.end(), values.begin(), values.end());
    return static_cast<std::uint16_t>(at);
  }

  // The scalar representation of a Bool/Int/UInt/Float/Enum type of `schema`.
  static std::uint8_t scalar_of(const Schema& schema, const TypeInfo& type) {
    const TypeInfo& number = type.kind == Kind::Enum ? schema.types[type.element] : type;
    const dp::ScalarKind kind = number.kind == Kind::Bool    ? dp::kBoolean
                                : number.kind == Kind::Int   ? dp::kSigned
                                : number.kind == Kind::Float ? dp::kFloat
                                                             : dp::kUnsigned;
    return dp::scalar(kind, static_cast<unsigned>(number.size));
  }

  void value(const PlanNode& n, std::uint32_t wire, std::uint32_t dst, const std::string& path,
             const FieldPlan* field = nullptr) {
    if (!error_.empty()) return;
    const bool bits = field && field->bit_width != 0;
    const bool ranged = field && field->has_range;
    switch (n.action) {
      case Action::Skip:
      case Action::Reject:  // its type changed beyond the rules: this build's value stays, as
        return;             // on the host (the build's report lists it)
      case Action::Union:
        return copy(wire, dst, r_.types[n.reader].size);
      case Action::Scalar: {
        const TypeInfo& wt = w_.types[n.writer];
        if (n.identical && !bits && !ranged && wt.kind != Kind::Bool) {
          return copy(wire, dst, wt.size);
        }
        return scalar(n, wire, dst, path, field);
      }
      case Action::Pointer: {
        push(Op{dp::kOpPointer, 0, entries({r_.types[n.reader].element}), wire, dst});
        return;
      }
      case Action::Array:
        return array(n, wire, dst, path);
      case Action::Struct:
        return structure(n, wire, dst, path);
      default:
        return fail(path, "is a kind the device profile does not hold" + std::string(kFixes));
    }
  }

  void scalar(const PlanNode& n, std::uint32_t wire, std::uint32_t dst, const std::string& path,
              const FieldPlan* field) {
    const TypeInfo& wt = w_.types[n.writer];
    const TypeInfo& rt = r_.types[n.reader];
    const std::uint8_t from = scalar_of(w_, wt), to = scalar_of(r_, rt);
    if ((wt.kind == Kind::Enum) != (rt.kind == Kind::Enum) &&
        ((from >> 4) == dp::kFloat || (to >> 4) == dp::kFloat)) {
      return fail(path, std::string("was a ") + wt.name + " and is a " + rt.name +
                            " now: the device profile converts an enum to and from integers "
                            "only" +
                            kFixes);
    }
    std::vector<std::uint64_t> pairs;
    if (wt.kind == Kind::Enum && rt.kind == Kind::Enum) {
      for (const EnumMapping& m : n.enum_map) {
        if (!m.mapped) continue;  // a value of it is refused: no enumerator of that name now
        pairs.push_back(static_cast<std::uint64_t>(m.writer_value));
        pairs.push_back(static_cast<std::uint64_t>(m.reader_value));
      }
      if (pairs.empty()) {
        return fail(path, std::string("is an enum none of whose enumerators (") + wt.name +
                              ") is in this build's " + rt.name + kFixes);
      }
    } else if (rt.kind == Kind::Enum) {
      // A number becomes an enum only as one of its enumerators' values: each maps to itself.
      // The device compares the writer's bits (sign-extended if it is signed), so a value is
      // paired only where equal bits mean equal numbers: no negative enumerator for an unsigned
      // writer, none at 2^63 or more (of an unsigned enum) for a signed one.
      const bool writer_signed = scalar_of(w_, wt) >> 4 == dp::kSigned;
      const bool reader_signed = r_.types[rt.element].kind == Kind::Int;
      for (std::uint32_t e = 0; e < rt.enumerator_count; ++e) {
        const std::int64_t value = rt.enumerators[e].value;
        if (value < 0 && (reader_signed ? !writer_signed : writer_signed)) continue;
        pairs.push_back(static_cast<std::uint64_t>(value));
        pairs.push_back(static_cast<std::uint64_t>(value));
      }
      if (pairs.empty()) {
        return fail(path, std::string("becomes the enum ") + rt.name +
                              ", which has no enumerator to hold its values" + kFixes);
      }
    }
    const bool ranged = field && field->has_range;
    const unsigned width = field ? field->bit_width : 0, offset = field ? field->bit_offset : 0;
    const std::uint64_t unit = width ? (offset + width + 7u) / 8u : 0;
    const std::uint64_t target = to | std::uint64_t{width} << 8 | std::uint64_t{offset} << 16 |
                                 unit << 24 | std::uint64_t{pairs.size() / 2} << 32 |
                                 (ranged ? dp::kTargetHasRange : 0);
    const std::uint16_t at = entries({target});
    if (ranged) {
      std::uint64_t low, high;
      std::memcpy(&low, &field->range_min, 8);
      std::memcpy(&high, &field->range_max, 8);
      entries({low, high});
    }
    table_.insert(table_.end(), pairs.begin(), pairs.end());
    push(Op{dp::kOpScalar, from, at, wire, dst});
  }

  void array(const PlanNode& n, std::uint32_t wire, std::uint32_t dst, const std::string& path) {
    const TypeInfo& wt = w_.types[n.writer];
    const std::uint64_t count = wt.count < n.reader_count ? wt.count : n.reader_count;
    if (count == 0 || n.element == nullptr) return;
    const std::uint64_t wire_stride = fixed(wt.element), dst_stride = n.reader_stride;
    const std::size_t loop = ops_.size();
    const bool merge = mergeable_;
    push(Op{dp::kOpLoop, 0, entries({count, wire_stride | dst_stride << 32}), wire, dst});
    value(*n.element, 0, 0, path + "[]");
    const std::size_t body = ops_.size() - loop - 1;
    const Op* only = body == 1 ? &ops_.back() : nullptr;
    if (body == 0 || (only && only->code == dp::kOpCopy && only->wire == 0 && only->dst == 0 &&
                      only->b == wire_stride && only->b == dst_stride)) {
      // Elements copied as they are (or nothing to do): one copy of them all.
      ops_.resize(loop);
      table_.resize(table_.size() - 1);
      mergeable_ = merge;
      if (body == 1) copy(wire, dst, count * wire_stride);
      return;
    }
    table_[ops_[loop].b] = count | std::uint64_t{static_cast<std::uint32_t>(body)} << 32;
    mergeable_ = false;
  }

  void structure(const PlanNode& n, std::uint32_t wire, std::uint32_t dst,
                 const std::string& path) {
    if (n.migrates) {
      return fail(path, std::string("has a symcr_migrate hook, which the device profile does "
                                    "not run") +
                            kFixes);
    }
    const TypeInfo& wt = w_.types[n.writer];
    std::uint64_t at = wire;
    for (std::size_t f = 0; f < n.fields.size() && f < wt.field_count; ++f) {
      const FieldPlan& field = n.fields[f];
      const FieldInfo& wf = wt.fields[f];
      const std::string member = path + "." + wf.name;
      if (field.reader_field != kNoType && field.node != nullptr) {
        if ((field.bit_width != 0 || field.has_range) && field.node->action != Action::Scalar &&
            field.node->action != Action::Skip) {
          return fail(member, "has a range or a bit-field on a value that is not a number");
        }
        value(*field.node, static_cast<std::uint32_t>(at), dst + field.reader_offset, member,
              &field);
        if (const FieldTime* time = reader_time(r_, n, field)) {
          const TypeInfo& rt = r_.types[field.node->reader];
          if (rt.kind != Kind::Int && rt.kind != Kind::UInt) {
            return fail(member,
                        "holds times in an array: the device profile rebases times "
                        "of integer members only" +
                            std::string(kFixes));
          }
          const std::uint32_t reader_clock = time->clock->index;
          const std::uint32_t writer_clock = reader_clock < plan_.writer_clock_of.size()
                                                 ? plan_.writer_clock_of[reader_clock]
                                                 : kNoType;
          if (writer_clock != kNoType) {  // no reading of its clock: the time is kept as saved
            push(Op{dp::kOpTime, static_cast<std::uint8_t>(rt.size),
                    entries({static_cast<std::uint64_t>(time->never),
                             std::uint64_t{writer_clock} << 32 | reader_clock}),
                    0, dst + field.reader_offset});
          }
        }
      }
      at += fixed(wf.type);
    }
    if (n.validated) push(Op{dp::kOpValidate, 0, entries({n.reader}), 0, dst});
  }

  // References by path: the writer's roots and types, each struct's members mapped to the
  // reader's by the plan. Only for a writer with pointers. False when an index does not fit
  // the tables' 16 bits.
  bool paths() {
    bool pointers = false;
    for (std::uint32_t t = 0; t < w_.type_count; ++t) pointers |= w_.types[t].kind == Kind::Pointer;
    if (!pointers) return true;
    // kNone (removed) becomes kNoPathIndex; any other index must stay below it.
    const auto narrow = [](std::vector<std::uint32_t>& halves) {
      for (std::uint32_t& half : halves) {
        if (half == dp::kNone)
          half = dp::kNoPathIndex;
        else if (half >= dp::kNoPathIndex)
          return false;
      }
      return true;
    };
    for (std::uint32_t i = 0; i < w_.root_count; ++i) {
      path_roots_.push_back(w_.roots[i].type);
      path_roots_.push_back(plan_.roots[i].reader_root);
    }
    for (std::uint32_t t = 0; t < w_.type_count; ++t) {
      const TypeInfo& type = w_.types[t];
      if (type.kind == Kind::Array) {
        path_types_.push_back(dp::kPathArray);
        path_types_.push_back(type.element);
      } else if (type.kind == Kind::Struct) {
        const PlanNode* mapped = nullptr;
        for (const PlanNode& n : plan_.nodes) {
          if (n.writer == t && n.action == Action::Struct) {
            mapped = &n;
            break;
          }
        }
        if (type.field_count >= dp::kNoPathIndex >> 2) return false;
        path_types_.push_back(dp::kPathStruct | type.field_count << 2);
        path_types_.push_back(static_cast<std::uint32_t>(path_fields_.size() / 2));
        for (std::uint32_t f = 0; f < type.field_count; ++f) {
          path_fields_.push_back(type.fields[f].type);
          path_fields_.push_back(
              mapped && f < mapped->fields.size() ? mapped->fields[f].reader_field : dp::kNone);
        }
      } else {
        path_types_.push_back(0);
        path_types_.push_back(0);
      }
    }
    return narrow(path_roots_) && narrow(path_types_) && narrow(path_fields_);
  }

  const Plan& plan_;
  const Schema& w_;
  const Schema& r_;
  std::vector<Op> ops_;
  bool mergeable_ = false;  // the last op is a copy that a following copy may extend
  std::vector<std::uint64_t> table_;
  std::vector<std::uint32_t> path_roots_, path_types_, path_fields_;
  std::string error_;
};

}  // namespace

bool device_plan_image_for(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                           std::uint64_t reader_hash, std::vector<std::uint8_t>& image,
                           std::string& error) {
  Plan plan;
  plan.writer = &writer;
  plan.reader = &reader;
  planning::Planner(plan).run();
  return device_plan_image_of(plan, writer_hash, reader_hash, image, error);
}

bool device_plan_image_of(const Plan& plan, std::uint64_t writer_hash, std::uint64_t reader_hash,
                          std::vector<std::uint8_t>& image, std::string& error) {
  return DeviceEncoder(plan).encode(writer_hash, reader_hash, image, error);
}

}  // namespace symcr::detail
