// Fixed-width little-endian loads and stores for the file formats (docs/format.md): the device
// profile's, which both runtimes share.
#ifndef SYMCR_SRC_LITTLE_ENDIAN_HPP
#define SYMCR_SRC_LITTLE_ENDIAN_HPP

#include "device_format.hpp"

namespace symcr::detail::le {

using device::detail::load16;
using device::detail::load32;
using device::detail::load64;
using device::detail::store16;
using device::detail::store32;
using device::detail::store64;

}  // namespace symcr::detail::le

#endif  // SYMCR_SRC_LITTLE_ENDIAN_HPP
