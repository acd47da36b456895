// Clocks (docs/resolution.md, "Clocks"): what identifies the process whose clocks a
// checkpoint's readings are of. Internal to the runtime.
#ifndef SYMCR_SRC_CLOCKS_HPP
#define SYMCR_SRC_CLOCKS_HPP

#include <cstdint>

namespace symcr::detail {

// A random, non-zero number drawn once per process: a checkpoint records it with its clock
// readings, and a restore into the process that wrote it (a live transfer, a rollback) moves no
// time. A child forked after the first draw shares it, as it shares the parent's clocks.
std::uint64_t process_epoch();

}  // namespace symcr::detail

#endif  // SYMCR_SRC_CLOCKS_HPP
