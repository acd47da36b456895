// A schema's tables in the device profile's compact form (generated.hpp's DeviceSchema), laid out
// as symcr-gen lays them out for PROFILE device: each struct's fields, then its reference
// members; the bit-fields, ranges, clock times and validators in their side tables. The tests run
// the device runtime over both forms of one schema and expect the same records and the same
// results.
#ifndef SYMCR_TESTS_DEVICE_COMPACT_SCHEMA_HPP
#define SYMCR_TESTS_DEVICE_COMPACT_SCHEMA_HPP

#include <cstdint>
#include <vector>

#include "symcr/generated.hpp"

namespace device_tests {

class CompactSchema {
 public:
  explicit CompactSchema(const symcr::Schema& from) {
    for (std::uint32_t t = 0; t < from.type_count; ++t) {
      const symcr::TypeInfo& type = from.types[t];
      symcr::DeviceTypeInfo entry{};
      entry.size = type.size;
      entry.kind = static_cast<std::uint8_t>(type.kind);
      entry.element = type.element == symcr::kNoType ? symcr::kDeviceNoType
                                                     : static_cast<std::uint16_t>(type.element);
      entry.count = static_cast<std::uint32_t>(type.count);
      if (type.kind == symcr::Kind::Struct) {
        entry.count = type.field_count | type.reference_member_count << 16;
        entry.first_field = static_cast<std::uint16_t>(offsets_.size());
        for (std::uint32_t f = 0; f < type.field_count; ++f) add(type.fields[f]);
        for (std::uint32_t m = 0; m < type.reference_member_count; ++m) {
          add(type.reference_members[m]);
        }
      }
      if (type.validate != nullptr) {
        validators_.push_back(type.validate);
        entry.validator = static_cast<std::uint8_t>(validators_.size());
      }
      types_.push_back(entry);
    }
    device_.schema =
        symcr::Schema{nullptr, from.type_count, from.roots, from.root_count, from.program};
    device_.types = types_.data();
    device_.field_offsets = offsets_.data();
    device_.field_types = field_types_.data();
    device_.validators = validators_.data();
    device_.bit_fields = bit_fields_.data();
    device_.bit_field_count = static_cast<std::uint32_t>(bit_fields_.size());
    device_.ranges = ranges_.data();
    device_.range_count = static_cast<std::uint32_t>(ranges_.size());
    device_.times = times_.data();
    device_.time_count = static_cast<std::uint32_t>(times_.size());
  }
  CompactSchema(const CompactSchema&) = delete;
  CompactSchema& operator=(const CompactSchema&) = delete;

  // What the device runtime is given: the Schema a DeviceSchema begins with.
  const symcr::Schema& schema() const { return device_.schema; }

 private:
  void add(const symcr::FieldInfo& field) {
    const std::uint32_t index = static_cast<std::uint32_t>(offsets_.size());
    offsets_.push_back(field.offset);
    field_types_.push_back(static_cast<std::uint16_t>(field.type));
    if (field.bit_width != 0) {
      bit_fields_.push_back(symcr::DeviceBitField{index,
                                                  static_cast<std::uint8_t>(field.bit_offset),
                                                  static_cast<std::uint8_t>(field.bit_width)});
    }
    if ((field.flags & symcr::kFieldHasRange) && field.range != nullptr) {
      ranges_.push_back(symcr::DeviceFieldRange{index, *field.range});
    }
    if ((field.flags & symcr::kFieldClockTime) && field.time != nullptr &&
        field.time->clock != nullptr) {
      times_.push_back(symcr::DeviceFieldTime{index, *field.time});
    }
  }

  std::vector<symcr::DeviceTypeInfo> types_;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint16_t> field_types_;
  std::vector<symcr::DeviceBitField> bit_fields_;
  std::vector<bool (*)(const void*)> validators_;
  std::vector<symcr::DeviceFieldRange> ranges_;
  std::vector<symcr::DeviceFieldTime> times_;
  symcr::DeviceSchema device_{};
};

}  // namespace device_tests

#endif  // SYMCR_TESTS_DEVICE_COMPACT_SCHEMA_HPP
