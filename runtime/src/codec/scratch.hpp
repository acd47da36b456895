// The calling thread's scratch memory, for benchmarks and tools. Internal to the runtime.
#ifndef SYMCR_SRC_SCRATCH_HPP
#define SYMCR_SRC_SCRATCH_HPP

#include <cstddef>

namespace symcr::detail {

// The scratch memory of the calling thread's engine, in bytes of capacity: what its last
// checkpoint's memo tables, region index and reference and heap lists hold (kept between
// checkpoints for reuse), and what the decoding tables of its last restore that got as far as
// writing held (freed on return; 0 after the copy-only fast path).
// Rebuilt objects and the output buffer are not scratch.
struct ScratchBytes {
  std::size_t checkpoint = 0;
  std::size_t restore = 0;
};
ScratchBytes thread_scratch_bytes();  // restore.cpp
std::size_t encode_scratch_bytes();   // its checkpoint part (encode.cpp)

}  // namespace symcr::detail

#endif  // SYMCR_SRC_SCRATCH_HPP
