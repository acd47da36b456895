// Helpers for the cross-version programs: v0 saves, v1 restores and checks every value and the
// report's decisions. v1's exit code is the test's verdict.
#ifndef SYMCR_TESTS_CROSSVERSION_CHECK_HPP
#define SYMCR_TESTS_CROSSVERSION_CHECK_HPP

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <symcr/device.hpp>
#include <symcr/symcr.hpp>

#include "report_file.h"

// embedded_plan_check.cpp, linked into the C++ v1 programs: the failures of checking the plan
// symcr-gen embedded for `checkpoint`'s schema.
extern "C" int xv_check_embedded_plan(const char* checkpoint) __attribute__((weak));
extern "C" int xv_restore_through_device_plan(const char* checkpoint) __attribute__((weak));

namespace xv {

// The number of failed checks (a function, not an inline variable: the helpers are C++11).
inline int& failures() {
  static int count = 0;
  return count;
}

#define XV_CHECK(condition)                                                        \
  do {                                                                             \
    if (!(condition)) {                                                            \
      std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
      ++xv::failures();                                                            \
    }                                                                              \
  } while (0)

// XV_STORE=1 (crossversion.<name>.store): v0 saves into a store at <checkpoint> and v1 opens
// it and restores its latest record, as a vehicle restarted with a patched build does. Opening
// another build's store prepares the first restore (the device profile's executor, for states
// of the kinds it holds).
inline bool in_store() { return std::getenv("XV_STORE") != nullptr; }

inline symcr::Report restore_latest(const char* path, bool strict) {
  symcr::Store store;
  const symcr::Status opened = symcr::Store::open(path, symcr::StoreOptions(), store);
  if (!opened.ok()) {
    std::fprintf(stderr, "opening %s failed: %s\n", path, opened.message());
    std::exit(1);
  }
  symcr::RestoreOptions options;
  options.strict = strict;
  return store.restore_latest(options);
}

inline symcr::Status save_in_store(const char* path) {
  symcr::Store store;
  symcr::Status status = symcr::Store::open(path, symcr::StoreOptions(), store);
  return status.ok() ? store.save() : status;
}

// Saves every root into `path`; v0's exit code.
inline int save(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <checkpoint>\n", argv[0]);
    return 2;
  }
  symcr::Status status = in_store() ? save_in_store(argv[1]) : symcr::checkpoint(argv[1]);
  if (!status.ok()) {
    std::fprintf(stderr, "checkpoint failed: %s\n", status.message());
    return 1;
  }
  // The live pairs (live/host.cpp): XV_LIVE_AT_SAVE holds the address of the host's function
  // that runs v1 on this build's state, here, while it is live; its verdict is v0's.
  if (const char* hook = std::getenv("XV_LIVE_AT_SAVE")) {
    using RunV1 = int (*)(const void* v0_schema);
    const RunV1 run_v1 =
        reinterpret_cast<RunV1>(static_cast<std::uintptr_t>(std::strtoull(hook, nullptr, 16)));
    return run_v1(symcr_program_schema());
  }
  return 0;
}

// For the convert tests (convert_pair.cmake), three environment variables: XV_INITIAL=<file>
// saves the state v1 restores into, before restoring; XV_RESAVE=<file> saves the restored
// state; XV_DEVICE=1 restores <checkpoint> through the device profile instead (a checkpoint
// `symcr convert` wrote), saves it (XV_RESAVE) and exits: the report's checks are the host
// restore's.
inline void save_if_asked(const char* variable) {
  const char* path = std::getenv(variable);
  if (path == nullptr) return;
  const symcr::Status status = symcr::checkpoint(path);
  if (!status.ok()) {
    std::fprintf(stderr, "%s: checkpoint failed: %s\n", variable, status.message());
    std::exit(1);
  }
}

inline void restore_through_device_and_exit(const char* path) {
  std::vector<std::uint8_t> record;
  if (std::FILE* file = std::fopen(path, "rb")) {
    std::uint8_t buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) != 0;)
      record.insert(record.end(), buffer, buffer + n);
    std::fclose(file);
  }
  const symcr::device::Build build = symcr::device::program_build();
  std::vector<std::uint8_t> scratch(build.schema ? symcr::device::scratch_size(*build.schema) : 0);
  const symcr::device::Result result = symcr::device::restore(
      build, record.data(), record.size(), scratch.data(), scratch.size());
  if (result != symcr::device::Result::Ok) {
    std::fprintf(stderr, "device restore of %s: %s\n", path, symcr::device::result_text(result));
    std::exit(1);
  }
  save_if_asked("XV_RESAVE");
  std::exit(0);
}

// XV_DEVICE_PLAN=1: restores v0's <checkpoint> through the device profile with the device plan
// image made for v0's schema (embedded_plan_check.cpp), saves it (XV_RESAVE) and exits.
inline void restore_through_device_plan_and_exit(const char* path) {
  if (xv_restore_through_device_plan == nullptr) {
    std::fprintf(stderr, "XV_DEVICE_PLAN: this program has no device plan check linked\n");
    std::exit(1);
  }
  if (xv_restore_through_device_plan(path) != 0) std::exit(1);
  save_if_asked("XV_RESAVE");
  std::exit(0);
}

// The live pairs (live/host.cpp): XV_LIVE_FROM holds the address of the v0 module's schema in
// this process, whose roots are transferred into this build's (from v0's live state, at v0's
// save point) instead of restoring a file.
inline const symcr::Schema* live_source() {
  const char* from = std::getenv("XV_LIVE_FROM");
  if (from == nullptr) return nullptr;
  return reinterpret_cast<const symcr::Schema*>(
      static_cast<std::uintptr_t>(std::strtoull(from, nullptr, 16)));
}

inline symcr::Report restore(int argc, char** argv, bool strict = false) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <checkpoint>\n", argv[0]);
    return symcr::restore("", symcr::RestoreOptions());  // fails: no such file
  }
  if (const symcr::Schema* source = live_source()) {
    symcr::RestoreOptions options;
    options.strict = strict;
    symcr::Report report = symcr::transfer(*source, *symcr_program_schema(), options);
    std::printf("%s\n", report.to_text().c_str());
    return report;
  }
  if (std::getenv("XV_DEVICE") != nullptr) restore_through_device_and_exit(argv[1]);
  if (std::getenv("XV_DEVICE_PLAN") != nullptr) restore_through_device_plan_and_exit(argv[1]);
  if (in_store()) {
    symcr::Report report = restore_latest(argv[1], strict);
    std::printf("%s\n", report.to_text().c_str());
    return report;
  }
  if (xv_check_embedded_plan != nullptr) failures() += xv_check_embedded_plan(argv[1]);
  save_if_asked("XV_INITIAL");
  struct Resave {
    ~Resave() { save_if_asked("XV_RESAVE"); }
  } resave;
  symcr::RestoreOptions options;
  options.strict = strict;
  symcr::Report report = symcr::restore(argv[1], options);
  std::printf("%s\n", report.to_text().c_str());
  xv_write_report(report.to_json().c_str());
  return report;
}

inline const symcr::ReportEntry* entry(const symcr::Report& report, const char* path) {
  for (const symcr::ReportEntry& e : report.entries())
    if (e.path == path) return &e;
  return nullptr;
}

// True when the report has an entry for `path` with `decision` (a path can have a plan-level
// entry, e.g. converted int64 -> int8, and a value-level one, e.g. rejected: out of range).
inline bool decided(const symcr::Report& report, const char* path, symcr::Decision decision) {
  bool any = false;
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path != path) continue;
    any = true;
    if (e.decision == decision) return true;
  }
  std::fprintf(stderr, any ? "'%s': no entry with decision %s\n" : "no report entry for '%s' (%s)\n",
               path, symcr::decision_name(decision));
  return false;
}

// A value restored plainly has no entry other than Restored ones.
inline bool restored(const symcr::Report& report, const char* path) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.decision != symcr::Decision::Restored) {
      std::fprintf(stderr, "'%s': decision %s, expected restored (%s)\n", path,
                   symcr::decision_name(e.decision), e.detail.c_str());
      return false;
    }
  }
  return true;
}

inline int verdict() {
  if (failures()) std::fprintf(stderr, "%d check(s) failed\n", failures());
  return failures() ? 1 : 0;
}

}  // namespace xv

#endif  // SYMCR_TESTS_CROSSVERSION_CHECK_HPP
