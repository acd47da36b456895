// The device profile's queries: results as text, the program's build, what a schema needs.
#include "device_format.hpp"

namespace symcr {
namespace device {

const char* result_text(Result result) {
  // The texts in Result's order, each ended by its NUL: no table of pointers in flash.
  static const char kTexts[] =
      "ok\0"
      "buffer too small\0"
      "a type the device profile cannot hold\0"
      "record truncated\0"
      "record corrupt\0"
      "record from a newer format\0"
      "record of another build's schema\0"
      "record of another program\0"
      "a value refused by its range or validator\0"
      "more pointer targets than kMaxReferences\0"
      "no checkpoint saved yet\0"
      "sequence numbers used up";
  if (result > Result::SequenceExhausted) return "?";
  const char* text = kTexts;
  for (unsigned skip = static_cast<unsigned>(result); skip > 0; --skip) {
    while (*text++ != '\0') {
    }
  }
  return text;
}

Build program_build() {
  Build build;
  if (symcr_program_schema_hash == nullptr) return build;
  // The compact tables when the generated code is the device profile's: the program's
  // TypeInfo tables are then never linked. A host build's generated code has only those.
  if (symcr_program_device_schema != nullptr) {
    build.schema = &symcr_program_device_schema()->schema;
  } else if (symcr_program_schema != nullptr) {
    build.schema = symcr_program_schema();
  } else {
    return build;
  }
  build.schema_hash = symcr_program_schema_hash();
  // Set here, not through the constructor that links the executor: the generated code links
  // it when there are plans.
  if (symcr_program_plans != nullptr) build.plans = symcr_program_plans(&build.plan_count);
  return build;
}

Result check_schema(const Schema& schema, std::uint32_t* type) {
  const std::uint32_t unheld = detail::first_unheld_type(schema);
  if (type != nullptr) *type = unheld;
  return unheld == kNoType ? Result::Ok : Result::Unsupported;
}

std::size_t record_size(const Schema& schema) {
  std::size_t pointers = 0;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    pointers += detail::pointer_count(schema, schema.roots[r].type);
  }
  if (pointers > kMaxReferences) pointers = kMaxReferences;
  return format::kRecordHeaderSize + detail::values_size(schema) + format::kHeapCountSize +
         format::kReferenceCountSize + pointers * detail::kMaxReferenceSize +
         format::clock_readings_size(detail::clock_count(schema));
}

std::size_t scratch_size(const Schema& schema) {
  std::size_t total = 0;
  for (std::uint32_t r = 0; r < schema.root_count; ++r) {
    total += detail::stage_size(detail::root_size(schema, r));
  }
  return total + detail::kStageAlign;  // room to align the first copy
}

}  // namespace device
}  // namespace symcr
