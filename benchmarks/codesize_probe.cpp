// Code-size probe (target: runtime + generated code <= 12 KB of .text). One small
// program that keeps the critical state (critical_state.hpp), checkpoints it periodically and
// restores it at start-up, built twice:
//   PROBE_WITH_SYMCR=1  with symcr: a Store, save() per tick, restore_latest() at start, the
//                       hand-written schema tables standing for the generated code;
//   PROBE_WITH_SYMCR=0  the same program saving the raw bytes with memcpy + pwrite.
// `size` of the two, linked statically against libsymcr.a as a user's program is, gives the
// .text the runtime (and the tables' code, none) adds. benchmarks/run uses it while the
// specimen has no symcr-linked build, and reports the specimen's own numbers once it has.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "critical_state.hpp"
#if PROBE_WITH_SYMCR
#include "symcr/symcr.hpp"
#endif

using namespace critical;

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "/tmp/symcr-codesize-probe";
  const int ticks = argc > 2 ? std::atoi(argv[2]) : 3;
#if PROBE_WITH_SYMCR
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path, schema, symcr::StoreOptions{}, store);
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.message());
    return 1;
  }
  const symcr::Report report = store.restore_latest();
  std::printf("restore: %s\n", report.ok() ? "ok" : report.status().message());
  for (int tick = 0; tick < ticks; ++tick) {
    fill_state(static_cast<std::uint32_t>(tick));
    status = store.save();
    if (!status.ok()) {
      std::fprintf(stderr, "%s\n", status.message());
      return 1;
    }
  }
  store.close();
#else
  const int fd = ::open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  if (fd < 0) return 1;
  unsigned char buffer[sizeof(Copter) + sizeof(Ahrs) + sizeof(Mission) + sizeof(Telemetry)];
  if (::pread(fd, buffer, sizeof buffer, 0) == static_cast<ssize_t>(sizeof buffer)) {
    unsigned char* p = buffer;
    std::memcpy(&copter, p, sizeof copter);
    p += sizeof copter;
    std::memcpy(&ahrs, p, sizeof ahrs);
    p += sizeof ahrs;
    std::memcpy(&mission, p, sizeof mission);
    p += sizeof mission;
    std::memcpy(&telemetry, p, sizeof telemetry);
    std::printf("restore: ok\n");
  }
  for (int tick = 0; tick < ticks; ++tick) {
    fill_state(static_cast<std::uint32_t>(tick));
    unsigned char* p = buffer;
    std::memcpy(p, &copter, sizeof copter);
    p += sizeof copter;
    std::memcpy(p, &ahrs, sizeof ahrs);
    p += sizeof ahrs;
    std::memcpy(p, &mission, sizeof mission);
    p += sizeof mission;
    std::memcpy(p, &telemetry, sizeof telemetry);
    if (::pwrite(fd, buffer, sizeof buffer, 0) != static_cast<ssize_t>(sizeof buffer)) return 1;
  }
  ::close(fd);
#endif
  std::printf("ticks %u\n", copter.ticks);
  return 0;
}
