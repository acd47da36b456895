// How restore hands a migration hook the checkpoint's value (<symcr/old_values.hpp>). Internal
// to the runtime.
#ifndef SYMCR_SRC_OLD_VALUES_VIEW_HPP
#define SYMCR_SRC_OLD_VALUES_VIEW_HPP

#include <cstddef>
#include <cstdint>

#include "symcr/generated.hpp"
#include "symcr/old_values.hpp"

namespace symcr::detail {

struct WireSizes;  // payload_grammar.hpp

// A view of a value of `writer.types[type]` whose payload encoding starts at `bytes`, with at
// most `size` bytes readable. `writer` must be a parsed (validated) schema and `sizes` its wire
// sizes.
OldValues old_values_view(const Schema& writer, const WireSizes& sizes, std::uint32_t type,
                          const std::uint8_t* bytes, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_OLD_VALUES_VIEW_HPP
