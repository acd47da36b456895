// A plan's image: the compact form in which symcr-gen embeds the plans it resolved at build time
// (a previous build's schema against the program's: symcr_add_checkpointing's PREVIOUS_SCHEMA).
// Restoring a checkpoint of that previous build then decodes the image, a linear read, instead
// of planning, which in a freshly started process is most of a cross-version restore.
// Internal to the runtime and symcr-gen; not a file format: an image is only ever read by the
// runtime of the build that embedded it, and is keyed by both schemas' hashes.
#ifndef SYMCR_SRC_PLAN_IMAGE_HPP
#define SYMCR_SRC_PLAN_IMAGE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "plan.hpp"

namespace symcr::detail {

// The image's layout, shared by its encoder (plan_image_encode.cpp) and decoder
// (plan_image.cpp): fixed-width little-endian fields in the order of the Plan and PlanNode
// members; node references are indices into the plan's nodes (0: none, else index + 1); names
// are references into the writer schema, whose strings the plan points into.
namespace plan_image {

constexpr std::uint8_t kImageMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'P', 'L', 'N'};
constexpr std::uint32_t kImageVersion = 1;

// Where a name the plan points at lives in the writer schema.
enum class NameKind : std::uint8_t { Null, TypeName, FieldName, EnumeratorName, RootName, Text };

enum NodeBits : std::uint8_t {
  kLossy = 1u << 0,
  kIdentical = 1u << 1,
  kValidated = 1u << 2,
  kMigrates = 1u << 3,
  kFlatReader = 1u << 4,
  kCopyOnly = 1u << 5,
};

}  // namespace plan_image

// Appends `plan`'s image to `bytes` (cleared first). `writer_hash` and `reader_hash` are the
// serialised schemas' hashes, checked again when the image is decoded.
void encode_plan_image(const Plan& plan, std::uint64_t writer_hash, std::uint64_t reader_hash,
                       std::vector<std::uint8_t>& bytes);

// Fills `plan`, whose writer and reader are set, from an image of a plan between those schemas.
// False when the image was made for other schemas or is damaged; `plan` is then to be dropped.
bool decode_plan_image(const std::uint8_t* image, std::size_t size, std::uint64_t writer_hash,
                       std::uint64_t reader_hash, Plan& plan);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PLAN_IMAGE_HPP
