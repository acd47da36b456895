// The process epoch of clock readings, and how a restore moves the times of the clocks it
// reads (docs/resolution.md, "Clocks").
#include "clocks.hpp"

#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <string>

#include "report_access.hpp"
#include "restorer.hpp"
#include "symcr/format/payload.hpp"

namespace symcr::detail {

std::uint64_t process_epoch() {
  static const std::uint64_t kEpoch = [] {
    std::uint64_t value = 0;
    if (getrandom(&value, sizeof value, 0) != static_cast<ssize_t>(sizeof value)) {
      // No entropy source: the start time and the pid still tell processes apart.
      timespec now{};
      clock_gettime(CLOCK_REALTIME, &now);
      value = (static_cast<std::uint64_t>(now.tv_sec) * 1000000000u +
               static_cast<std::uint64_t>(now.tv_nsec)) ^
              (static_cast<std::uint64_t>(getpid()) << 40);
    }
    return value != 0 ? value : 1;
  }();
  return kEpoch;
}

namespace restoring {

void Restorer::decide_clock_deltas(const ClockReadings& readings) {
  const std::vector<const ClockInfo*>& clocks = plan_.reader_clocks;
  clock_deltas_.assign(clocks.size(), 0);
  rebasing_ = false;
  if (clocks.empty() || readings.count == 0) return;
  // The writing process's own clocks: its times are still right.
  const bool same_process = readings.epoch != 0 && readings.epoch == process_epoch();
  if (same_process) {
    ReportAccess::remove(report_, Decision::Rebased);
    return;
  }
  for (std::size_t c = 0; c < clocks.size(); ++c) {
    const std::uint32_t w = plan_.writer_clock_of[c];
    if (!clocks[c] || w == kNoType || w >= readings.count) continue;
    const std::int64_t saved = readings.reading(w);
    const std::string path = std::string("(clock ") + clocks[c]->name + ")";
    char detail[160];
    if (!clocks[c]->read) {  // a schema without code (symcr plan): nothing to read now
      std::snprintf(detail, sizeof detail,
                    "read %" PRId64 " at the checkpoint: its times move by its advance since",
                    saved);
      ReportAccess::add(report_, path, Decision::Rebased, detail, false);
      continue;
    }
    const std::int64_t now = clocks[c]->read();
    clock_deltas_[c] = static_cast<std::int64_t>(static_cast<std::uint64_t>(now) -
                                                 static_cast<std::uint64_t>(saved));
    rebasing_ = true;
    std::snprintf(detail, sizeof detail,
                  "read %" PRId64 " at the checkpoint and %" PRId64
                  " now: its times moved by %" PRId64,
                  saved, now, clock_deltas_[c]);
    ReportAccess::add(report_, path, Decision::Rebased, detail, false);
  }
}

void Restorer::rebase(std::uint8_t* dst, const TypeInfo& type, const FieldTime& time) const {
  if (!rebasing_) return;
  if (type.kind != Kind::Int && type.kind != Kind::UInt) return;
  format::rebase_time(dst, type.size, time.never,
                      static_cast<std::uint64_t>(clock_deltas_[time.clock->index]));
}

}  // namespace restoring
}  // namespace symcr::detail
