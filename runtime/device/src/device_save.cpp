// The device profile's save: the roots' values in schema order (docs/format.md §3), no heap
// objects, and a reference per distinct pointer target inside the roots, found by address.
#include <cstring>

#include "device_format.hpp"

namespace symcr {
namespace device {
namespace {

struct Target {
  std::uintptr_t address;
  std::uint32_t type;
  std::uint32_t root;  // the root holding it
};

class Saver {
 public:
  Saver(const Schema& schema, std::uint8_t* out, std::size_t capacity)
      : schema_(schema), out_(out), capacity_(capacity) {}

  Result run(std::size_t* size) {
    at_ = format::kRecordHeaderSize;
    for (std::uint32_t r = 0; r < schema_.root_count && result_ == Result::Ok; ++r) {
      value(schema_.roots[r].type, static_cast<const std::uint8_t*>(schema_.roots[r].address));
    }
    put32(0);                                          // heap_count: no heap objects
    put32(static_cast<std::uint32_t>(target_count_));  // ref_count
    for (std::size_t i = 0; i < target_count_ && result_ == Result::Ok; ++i) reference(i);
    clock_readings();
    *size = at_;
    return result_;
  }

 private:
  void put(const void* bytes, std::size_t n) {
    if (result_ != Result::Ok) return;
    if (n > capacity_ - at_) {
      result_ = Result::NoSpace;
      return;
    }
    std::memcpy(out_ + at_, bytes, n);
    at_ += n;
  }
  // Integers in memory order: little-endian, the wire's (device_format.hpp).
  void put32(std::uint32_t v) { put(&v, 4); }
  void put64(std::uint64_t v) { put(&v, 8); }

  // The epoch 0 (a device restores only after a reset: its times always move) and each
  // clock's reading.
  void clock_readings() {
    const std::uint32_t clocks = detail::clock_count(schema_);
    if (clocks == 0) return;
    if (clocks > kMaxClocks) {
      result_ = Result::Unsupported;
      return;
    }
    put64(0);
    for (std::uint32_t c = 0; c < clocks; ++c) {
      const ClockInfo* clock = detail::clock_at(schema_, c);
      put64(clock && clock->read ? static_cast<std::uint64_t>(clock->read()) : 0);
    }
  }

  void value(std::uint32_t t, const std::uint8_t* p) {
    const detail::TypeView type = detail::type_at(schema_, t);
    switch (type.kind) {
      case Kind::Bool: {
        const std::uint8_t b = *p != 0;
        return put(&b, 1);
      }
      case Kind::Pointer:
        return pointer(type, p);
      case Kind::Array: {
        const std::size_t stride = detail::type_at(schema_, type.element).size;
        for (std::size_t i = 0; i < type.count && result_ == Result::Ok; ++i) {
          value(type.element, p + i * stride);
        }
        return;
      }
      case Kind::Struct:
        for (std::uint32_t f = 0; f < type.field_count && result_ == Result::Ok; ++f) {
          const detail::FieldView field = detail::field_at(schema_, t, f);
          if (field.bit_width != 0) {
            bit_field(field, p + field.offset);
          } else {
            value(field.type, p + field.offset);
          }
        }
        return;
      default:  // Int, UInt, Enum, Float, Union: their bytes (little-endian in memory)
        return put(p, type.size);
    }
  }

  // The field's value as its type's width, sign-extended for signed types.
  void bit_field(const detail::FieldView& field, const std::uint8_t* unit) {
    const detail::TypeView type = detail::type_at(schema_, field.type);
    const Kind integer =
        type.kind == Kind::Enum ? detail::type_at(schema_, type.element).kind : type.kind;
    const unsigned bytes = (field.bit_offset + field.bit_width + 7u) / 8u;
    if (bytes > 8) {  // also a width above 64
      result_ = Result::Unsupported;
      return;
    }
    std::uint64_t raw = 0;
    std::memcpy(&raw, unit, bytes);
    std::uint64_t v = detail::bits_at(raw, field.bit_offset, field.bit_width, integer == Kind::Int);
    if (type.kind == Kind::Bool) v = v != 0;
    put(&v, type.size > 8 ? 8 : type.size);  // little-endian: its low bytes first
  }

  void pointer(const detail::TypeView& type, const std::uint8_t* p) {
    std::uintptr_t target;
    std::memcpy(&target, p, sizeof target);
    if (target == 0) return put32(format::kNullCode);
    std::uint32_t root = 0;
    if (!find_root(target, &root)) return put32(format::kOutsideCode);
    for (std::size_t i = 0; i < target_count_; ++i) {
      if (targets_[i].address == target && targets_[i].type == type.element) {
        return put32(format::kFirstReference + static_cast<std::uint32_t>(i));
      }
    }
    if (target_count_ == kMaxReferences) {
      result_ = Result::TooManyPointers;
      return;
    }
    targets_[target_count_] = Target{target, type.element, root};
    put32(format::kFirstReference + static_cast<std::uint32_t>(target_count_++));
  }

  bool find_root(std::uintptr_t target, std::uint32_t* root) const {
    for (std::uint32_t r = 0; r < schema_.root_count; ++r) {
      const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(schema_.roots[r].address);
      if (target >= start && target - start < detail::root_size(schema_, r)) {
        *root = r;
        return true;
      }
    }
    return false;
  }

  // The reference to targets_[i]: the root holding it, then fields and elements down to an
  // object of the pointee type at that address. A pointer into a union or at a bit-field has
  // no such path: the save is refused rather than the pointer silently lost.
  void reference(std::size_t i) {
    const Target& target = targets_[i];
    const std::uint32_t root = target.root;
    std::uint32_t steps[kMaxPathSteps];
    std::size_t step_count = 0;
    std::uint32_t t = schema_.roots[root].type;
    std::uintptr_t base = reinterpret_cast<std::uintptr_t>(schema_.roots[root].address);
    while (!(t == target.type && base == target.address)) {
      const detail::TypeView type = detail::type_at(schema_, t);
      std::uint32_t step = kNoType;
      if (type.kind == Kind::Struct) {
        const std::uint32_t struct_type = t;
        for (std::uint32_t f = 0; f < type.member_count && step == kNoType; ++f) {
          const detail::FieldView field = detail::field_at(schema_, struct_type, f);
          const std::uintptr_t start = base + field.offset;
          if (field.bit_width == 0 && target.address >= start &&
              target.address - start < detail::type_at(schema_, field.type).size) {
            step = f;
            base = start;
            t = field.type;
          }
        }
      } else if (type.kind == Kind::Array) {
        const std::size_t stride = detail::type_at(schema_, type.element).size;
        const std::uint64_t index = stride ? (target.address - base) / stride : type.count;
        if (index < type.count) {
          step = static_cast<std::uint32_t>(index);
          base += static_cast<std::uintptr_t>(index * stride);
          t = type.element;
        }
      }
      if (step == kNoType || step_count == kMaxPathSteps) {
        result_ = Result::Unsupported;
        return;
      }
      steps[step_count++] = step;
    }
    const std::uint8_t base_kind = format::kBaseObject;
    put(&base_kind, 1);
    put32(root);
    const std::uint16_t count = static_cast<std::uint16_t>(step_count);
    put(&count, 2);
    for (std::size_t s = 0; s < step_count; ++s) put32(steps[s]);
    put32(target.type);
  }

  const Schema& schema_;
  std::uint8_t* out_;
  std::size_t capacity_;
  std::size_t at_ = 0;
  Result result_ = Result::Ok;
  Target targets_[kMaxReferences];
  std::size_t target_count_ = 0;
};

}  // namespace

Result save(const Build& build, std::uint64_t sequence, std::uint8_t* out, std::size_t capacity,
            std::size_t* size) {
  if (build.schema == nullptr || out == nullptr || size == nullptr) return Result::Unsupported;
  const Schema& schema = *build.schema;
  if (detail::first_unheld_type(schema) != kNoType) return Result::Unsupported;
  if (capacity < format::kRecordHeaderSize) return Result::NoSpace;
  std::size_t record = 0;
  const Result result = Saver(schema, out, capacity).run(&record);
  if (result != Result::Ok) return result;
  format::RecordHeader header;
  header.format_version = format::kRecordFormatVersion;
  header.header_size = format::kRecordHeaderSize;
  header.flags = 0;  // the schema is referenced by its hash
  header.sequence = sequence;
  header.timestamp_ns = 0;  // no wall clock on a device
  header.schema_hash = build.schema_hash;
  header.payload_size = static_cast<std::uint32_t>(record - format::kRecordHeaderSize);
  header.program_id = format::program_id(schema.program);
  format::encode_record_header(header, out);  // its checksum 0 while the CRC is computed
  format::store32(out + format::kRecordChecksumOffset, format::crc32c_extend_small(0, out, record));
  *size = record;
  return Result::Ok;
}

}  // namespace device
}  // namespace symcr
