#include <cstdio>

#include <symcr/points.h>
#include <symcr/symcr.h>

#include "counter_v1.hpp"

namespace {
void on_restore(const symcr_point* point, symcr_report* report, void* context) {
  *static_cast<int*>(context) += 1;
  std::printf("hook: %s ok=%d checkpoint #%llu\n", point->directive, symcr_report_ok(report),
              static_cast<unsigned long long>(symcr_report_sequence(report)));
}
}  // namespace

int main() {
  int calls = 0;
  symcr_set_restore_hook(on_restore, &calls);
  // The store opened before the restore point (which then only restores).
  const int opened = symcr_points_open_store();
  if (opened != SYMCR_OK) std::printf("open failed: %s\n", symcr_last_error());
  counter.resume();
  counter.resume();  // a restore point restores once per process
  std::printf("hook calls: %d\n", calls);
  return 0;
}
