// Static-storage and stack bounds of the running process (see process_memory.hpp).
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "process_memory.hpp"

#include <link.h>
#include <stddef.h>
#include <pthread.h>

namespace symcr::detail {

struct PhdrWalk {
  ProcessMemory* memory;
  bool first = true;
  bool unchanged = false;

  static int callback(dl_phdr_info* info, size_t size, void* context) {
    auto* walk = static_cast<PhdrWalk*>(context);
    ProcessMemory& memory = *walk->memory;
    if (walk->first) {
      walk->first = false;
      // dlpi_adds/dlpi_subs count loads and unloads: unchanged counts, unchanged segments.
      if (size >= offsetof(dl_phdr_info, dlpi_subs) + sizeof(info->dlpi_subs)) {
        if (info->dlpi_adds == memory.adds_ && info->dlpi_subs == memory.subs_) {
          walk->unchanged = true;
          return 1;
        }
        memory.adds_ = info->dlpi_adds;
        memory.subs_ = info->dlpi_subs;
      }
      memory.range_count_ = 0;
      memory.overflowed_ = false;
    }
    for (int i = 0; i < info->dlpi_phnum; ++i) {
      const ElfW(Phdr)& header = info->dlpi_phdr[i];
      if (header.p_type != PT_LOAD) continue;
      if (memory.range_count_ == ProcessMemory::kMaxRanges) {
        memory.overflowed_ = true;
        return 0;
      }
      const std::uintptr_t begin = info->dlpi_addr + header.p_vaddr;
      memory.ranges_[memory.range_count_++] = {begin, begin + header.p_memsz};
    }
    return 0;
  }
};

void ProcessMemory::refresh() {
  PhdrWalk walk{this};
  dl_iterate_phdr(&PhdrWalk::callback, &walk);
  if (!stack_known_) {
    // Cached per thread: pthread_getattr_np reads /proc/self/maps for the main thread.
    pthread_attr_t attributes;
    if (pthread_getattr_np(pthread_self(), &attributes) == 0) {
      void* stack = nullptr;
      size_t stack_size = 0;
      if (pthread_attr_getstack(&attributes, &stack, &stack_size) == 0) {
        stack_begin_ = reinterpret_cast<std::uintptr_t>(stack);
        stack_end_ = stack_begin_ + stack_size;
      }
      pthread_attr_destroy(&attributes);
    }
    stack_known_ = true;
  }
}

bool ProcessMemory::is_static_or_stack(std::uintptr_t address) const {
  if (address >= stack_begin_ && address < stack_end_) return true;
  for (int i = 0; i < range_count_; ++i) {
    if (address >= ranges_[i].begin && address < ranges_[i].end) return true;
  }
  return false;
}

}  // namespace symcr::detail
