// Classifies addresses the save path finds in no checkpointed object: static storage (any
// PT_LOAD segment of any loaded object) and the calling thread's stack are "outside" the
// checkpointed state (docs/format.md §3); anything else is treated as heap.
#ifndef SYMCR_SRC_PROCESS_MEMORY_HPP
#define SYMCR_SRC_PROCESS_MEMORY_HPP

#include <cstdint>

namespace symcr::detail {

class ProcessMemory {
 public:
  // Re-reads the segment list only when objects were loaded or unloaded since the last call;
  // never allocates after the first call on a thread.
  void refresh();
  bool is_static_or_stack(std::uintptr_t address) const;

 private:
  static constexpr int kMaxRanges = 512;
  struct Range {
    std::uintptr_t begin, end;
  };
  Range ranges_[kMaxRanges];
  int range_count_ = 0;
  bool overflowed_ = false;  // more segments than kMaxRanges: the rest count as heap
  unsigned long long adds_ = ~0ull, subs_ = ~0ull;
  std::uintptr_t stack_begin_ = 0, stack_end_ = 0;
  bool stack_known_ = false;
  friend struct PhdrWalk;
};

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PROCESS_MEMORY_HPP
