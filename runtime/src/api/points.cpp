// Program points (<symcr/points.h>): what the calls symcr-gen inserts at checkpoint_at and
// restore_at points do. All points of a program share one store, opened at the first point
// that needs it (or by symcr_points_open_store) and kept open; a mutex serialises the points of
// all threads.
#include "symcr/points.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <mutex>
#include <string>

#include "c_handles.hpp"
#include "report_access.hpp"
#include "symcr/symcr.hpp"

// NOLINTNEXTLINE(readability-redundant-declaration): redeclared to make it weak
extern "C" void symcr_on_restore_point(const struct symcr_point* point, struct symcr_report* report)
    __attribute__((weak));
// Weak here: a program without points (none defines it) may still call symcr_points_open_store.
// NOLINTNEXTLINE(readability-redundant-declaration): redeclared to make it weak
extern "C" const struct symcr_point_store symcr_program_point_store __attribute__((weak));

namespace {

struct PointState {
  std::mutex lock;
  symcr::Store store;
  std::string path;             // of the open store
  std::string last_save_error;  // logged once until a save succeeds again
  symcr_restore_hook hook = nullptr;
  void* hook_context = nullptr;
  // Crash-loop fallback: checkpoint points still to reach before the restore is confirmed (0:
  // none pending).
  unsigned saves_until_confirmed = 0;
};

// Never destroyed: a point reached while static objects are destroyed still finds it.
PointState& state() {
  static PointState* const kInstance = new PointState;
  return *kInstance;
}

const char* store_path(const symcr_point_store& store) {
  const char* from_environment = std::getenv("SYMCR_STORE");
  return from_environment != nullptr && *from_environment != '\0' ? from_environment : store.path;
}

// One line on stderr, in one write(2): lines of several threads do not mix, and the line of a
// restore point costs no cold stdio (its first formatted print in a freshly started process
// faults in tens of microseconds of code, inside the restore's time).
void log_line(std::initializer_list<const char*> parts, bool newline = true) {
  std::string line = "symcr: ";
  for (const char* part : parts) line += part;
  if (newline) line += '\n';
  const char* data = line.data();
  std::size_t left = line.size();
  while (left != 0) {
    const ssize_t written = ::write(STDERR_FILENO, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return;  // nowhere to log to: the outcome still reaches the hook
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

bool is_open_at(const PointState& s, const char* path) {
  return s.store.is_open() && s.path == path;
}

// Opens the store once; a checkpoint point then reaches save() without allocating.
symcr::Status open_store(PointState& s, const symcr_point_store& where) {
  const char* path = store_path(where);
  if (is_open_at(s, path)) return symcr::Status();
  s.store.close();
  symcr::StoreOptions options;
  if (where.slots != 0) {
    options.slots = where.slots;
  } else if (where.fallback_depth != 0) {
    // Room for the checkpoints the fallback keeps until confirm() and one to save into.
    options.slots = std::max(options.slots, where.fallback_depth + 2);
  }
  if (where.slot_size != 0) options.slot_size = where.slot_size;
  options.durability =
      where.fdatasync != 0 ? symcr::Durability::Fdatasync : symcr::Durability::PageCache;
  options.fallback_depth = where.fallback_depth;
  symcr::Status status = symcr::Store::open(path, options, s.store);
  if (status.ok()) s.path = path;
  return status;
}

void checkpoint(PointState& s, symcr_point& point) {
  const unsigned every = point.every == 0 ? 1 : point.every;
  if (point.passes % every != 0) return;
  symcr::Status status = open_store(s, *point.store);
  if (status.ok()) status = s.store.save();
  // The points reached confirm the restore, saved or not: a save the fallback refuses until
  // then (StoreFull, a store with few slots) must not keep it unconfirmed for ever.
  if (s.store.is_open() && s.saves_until_confirmed != 0 && --s.saves_until_confirmed == 0) {
    const symcr::Status confirmed = s.store.confirm();
    if (!confirmed.ok()) {
      log_line({point.inserted_at, ": cannot confirm the restore: ", confirmed.message()});
      return;
    }
  }
  if (status.ok()) {
    s.last_save_error.clear();
    return;
  }
  // A failing save at every loop would flood the log: say it once until it recovers.
  if (status.message() == s.last_save_error) return;
  s.last_save_error = status.message();
  log_line({point.inserted_at, ": checkpoint failed: ", status.message()});
}

[[noreturn]] void stop(const symcr_point& point) {
  log_line({point.inserted_at, ": stopping the program (", point.directive,
            " asks for on_failure=stop)"});
  std::exit(EXIT_FAILURE);
}

// Restores on the point's first pass; true when `report` holds a restore's outcome for the
// program's hook (false: not the first pass, or nothing to restore yet).
bool restore(PointState& s, symcr_point& point, symcr_report& report) {
  if (point.passes != 1) return false;  // a restore point restores once per process
  const char* path = store_path(*point.store);
  struct stat info;
  if (!is_open_at(s, path) && ::stat(path, &info) != 0 && errno == ENOENT) {
    log_line({point.inserted_at, ": no store at ", path, " yet; starting from the initial state"});
    return false;
  }
  const symcr::Status opened = open_store(s, *point.store);
  if (opened.ok() && !s.store.holds_checkpoints()) {
    log_line({point.inserted_at, ": ", path,
              " holds no checkpoint yet; starting from the initial state"});
    return false;
  }
  if (opened.ok()) {
    symcr::RestoreOptions options;
    options.strict = (point.restore_flags & SYMCR_RESTORE_STRICT) != 0;
    options.accept_other_program = (point.restore_flags & SYMCR_RESTORE_ACCEPT_OTHER_PROGRAM) != 0;
    report.report = s.store.restore_latest(options);
    if (report.report.ok()) s.saves_until_confirmed = point.store->confirm_after;
  } else {
    symcr::detail::ReportAccess::set_status(report.report, opened);
  }
  // A success is the hook's to report when there is one (the runtime's line would be a second,
  // written inside the restore point's time); a failure is always logged.
  const bool hooked = s.hook != nullptr || symcr_on_restore_point != nullptr;
  // Checkpoints passed over on the way to the one restored (a crash-loop fallback, a torn
  // slot) are always said; a failure's report lists them itself.
  for (const symcr::SkippedCheckpoint& skipped : report.report.skipped()) {
    if (!report.report.ok()) break;
    const std::string slot = std::to_string(skipped.slot);
    const std::string sequence = std::to_string(skipped.sequence);
    log_line({point.inserted_at, ": passed over slot ", slot.c_str(), " (checkpoint #",
              sequence.c_str(), "): ", skipped.reason.c_str()});
  }
  for (const std::string& warning : report.report.warnings()) {
    log_line({point.inserted_at, ": warning: ", warning.c_str()});
  }
  if (report.report.ok() && !hooked) {
    const std::string sequence = std::to_string(report.report.sequence());
    log_line({point.inserted_at, ": restored checkpoint #", sequence.c_str(), " of ", path});
  } else if (!report.report.ok()) {
    const std::string text = report.report.to_text();
    log_line(
        {point.inserted_at, ": restore failed; ",
         point.on_failure == SYMCR_POINT_STOP ? "stopping" : "carrying on from the initial state",
         ":\n", text.c_str()},
        /*newline=*/false);
  }
  return true;
}

}  // namespace

extern "C" {

void symcr_set_restore_hook(symcr_restore_hook hook, void* context) {
  PointState& s = state();
  std::lock_guard<std::mutex> guard(s.lock);
  s.hook = hook;
  s.hook_context = context;
}

int symcr_points_open_store(void) {
  if (&symcr_program_point_store == nullptr) {
    return symcr::detail::record_c_error(symcr::Status(
        symcr::Error::NoSchema, "the program has no program points (no store directive)"));
  }
  PointState& s = state();
  std::lock_guard<std::mutex> guard(s.lock);
  return symcr::detail::record_c_error(open_store(s, symcr_program_point_store));
}

int symcr_points_confirm(void) {
  PointState& s = state();
  std::lock_guard<std::mutex> guard(s.lock);
  s.saves_until_confirmed = 0;
  if (!s.store.is_open()) return SYMCR_OK;
  return symcr::detail::record_c_error(s.store.confirm());
}

void symcr_point_reached(struct symcr_point* point) {
  if (point == nullptr || point->store == nullptr) return;
  PointState& s = state();
  if (point->kind != SYMCR_POINT_RESTORE) {
    std::lock_guard<std::mutex> guard(s.lock);
    ++point->passes;
    checkpoint(s, *point);
    return;
  }
  symcr_report report;
  symcr_restore_hook hook = nullptr;
  void* hook_context = nullptr;
  {
    std::lock_guard<std::mutex> guard(s.lock);
    ++point->passes;
    if (!restore(s, *point, report)) return;
    hook = s.hook;
    hook_context = s.hook_context;
  }
  // The program's hook runs unlocked: it may reach a point or set another hook.
  if (hook != nullptr) {
    hook(point, &report, hook_context);
  } else if (symcr_on_restore_point != nullptr) {
    symcr_on_restore_point(point, &report);
  }
  if (!report.report.ok() && point->on_failure == SYMCR_POINT_STOP) stop(*point);
}

int symcr_point_exceptions_in_flight(void) { return std::uncaught_exceptions(); }

void symcr_point_at_scope_exit(struct symcr_point** point) {
  if (point != nullptr) symcr_point_reached(*point);
}

}  // extern "C"
