/* symcr program points: checkpoints and restores at function entries and exits chosen by
 * checkpoint_at(...) and restore_at(...) directives (macro, pragma or annotation file).
 *
 * symcr-gen inserts the calls into a copy of the source it compiles; a program never calls
 * symcr_point_reached itself. What a program may use is the restore hook:
 *
 *   static void on_restore(const struct symcr_point* point, struct symcr_report* report,
 *                          void* context) {
 *     if (!symcr_report_ok(report)) refuse_to_arm(symcr_report_text(report));
 *   }
 *   symcr_set_restore_hook(on_restore, NULL);
 *
 * or, without touching the program's code, a function of this name in a source of its own:
 *
 *   void symcr_on_restore_point(const struct symcr_point* point, struct symcr_report* report)
 *
 * This header includes nothing (the copy of a source includes it before the source's first
 * line, where a system header would pre-empt the source's feature macros), compiles as C99
 * and C++11, and is the same for C and C++. */
#ifndef SYMCR_POINTS_H
#define SYMCR_POINTS_H

/* The point directives as macros, at namespace (file) scope and without a semicolon:
 *   SYMCR_STORE("copter.store", slots=4)
 *   SYMCR_CHECKPOINT_AT(Copter::fast_loop, exit, every 10)
 *   SYMCR_RESTORE_AT(Copter::init_ardupilot, exit, on_failure=stop)
 * For symcr-gen they are the `#pragma symcr` directives of the same name; for a compiler they
 * are nothing (no unknown-pragma warning). */
#if defined(SYMCR_GENERATOR)
#define SYMCR_POINT_PRAGMA_(text) _Pragma(#text)
#define SYMCR_STORE(...) SYMCR_POINT_PRAGMA_(symcr store(__VA_ARGS__))
#define SYMCR_CHECKPOINT_AT(...) SYMCR_POINT_PRAGMA_(symcr checkpoint_at(__VA_ARGS__))
#define SYMCR_RESTORE_AT(...) SYMCR_POINT_PRAGMA_(symcr restore_at(__VA_ARGS__))
#else
#define SYMCR_STORE(...)
#define SYMCR_CHECKPOINT_AT(...)
#define SYMCR_RESTORE_AT(...)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The store the points of a program use: store(path, slots=, slot_size=, durability=,
 * fallback_depth=, confirm_after=), with symcr-gen's defaults filled in. The environment
 * variable SYMCR_STORE, when set, replaces `path` at run time. The crash-loop fallback of
 * symcr::StoreOptions is on unless the directive says fallback_depth=0 (symcr-gen's default:
 * depth 2, or what an explicit `slots` leaves room for, and confirm_after 10): the restore
 * point's restore is confirmed once `confirm_after` checkpoint points were reached after it
 * (saved, or refused because the fallback keeps every slot until then), or when the program
 * calls symcr_points_confirm(); without `slots`, the store then has fallback_depth + 2 slots
 * (4 at least), so that checkpoints are saved before the confirmation too. */
struct symcr_point_store {
  const char* path;
  unsigned slots;
  unsigned slot_size;
  int fdatasync; /* durability=fdatasync */
  unsigned fallback_depth;
  unsigned confirm_after;
};

#define SYMCR_POINT_CHECKPOINT 0
#define SYMCR_POINT_RESTORE 1
/* What a failed restore does: carry on with the initial state (the report is logged), or
 * stop the program (exit status 1). */
#define SYMCR_POINT_CONTINUE 0
#define SYMCR_POINT_STOP 1

struct symcr_point {
  const char* directive;   /* "checkpoint_at(Copter::loop, exit, every 10)", as written */
  const char* inserted_at; /* "Copter.cpp:57: Copter::loop, exit" */
  int kind;                /* SYMCR_POINT_CHECKPOINT or SYMCR_POINT_RESTORE */
  int on_failure;          /* SYMCR_POINT_CONTINUE or SYMCR_POINT_STOP (restore points) */
  int restore_flags;       /* SYMCR_RESTORE_* of <symcr/symcr.h> (restore points) */
  unsigned every;          /* a checkpoint point saves on every `every`-th pass */
  const struct symcr_point_store* store;
  unsigned long long passes; /* how often the point was reached; kept by the runtime */
};

/* The restore's report (<symcr/symcr.h>'s symcr_report), owned by the runtime for the
 * duration of the call. */
struct symcr_report;
typedef void (*symcr_restore_hook)(const struct symcr_point* point, struct symcr_report* report,
                                   void* context);
/* Called at every restore point with the restore's report (also when it failed; not when the
 * store holds no checkpoint yet). NULL removes the hook. Replaces symcr_on_restore_point.
 * Without a hook (or symcr_on_restore_point) the runtime logs every restore's outcome on stderr;
 * with one, a successful restore is the hook's to report and only failures are logged. */
void symcr_set_restore_hook(symcr_restore_hook hook, void* context);
/* Defined by the program (optional): called at every restore point when no hook is set. */
void symcr_on_restore_point(const struct symcr_point* point, struct symcr_report* report);

/* Opens the store of the program's points now (creating it if needed, locking it and reading
 * its slots), so that no point pays for that: call it during initialisation when the first
 * point is in a time-critical path, such as a restore point in a control loop's set-up. The
 * path is SYMCR_STORE's when set, as at a point. Optional: without it, the first point that
 * needs the store opens it. Returns SYMCR_OK (0) or an error code of <symcr/symcr.h>, with the
 * message in symcr_last_error(); SYMCR_ERROR_NO_SCHEMA when the program has no points. */
int symcr_points_open_store(void);
/* Crash-loop fallback: the state the restore point restored has proven itself, before the
 * store's confirm_after checkpoints did so. SYMCR_OK also when nothing waits for it. */
int symcr_points_confirm(void);

/* The store of the store(...) directive, defined by symcr-gen's schema source. */
extern const struct symcr_point_store symcr_program_point_store;

/* Inserted code: a point was reached. A checkpoint point saves on every `every`-th pass; a
 * restore point restores the store's newest valid checkpoint on its first pass. Thread-safe. */
void symcr_point_reached(struct symcr_point* point);
/* Inserted code: how many exceptions are in flight, so that an exit point is left out when the
 * function is left by an exception (0 in C and without exceptions). */
int symcr_point_exceptions_in_flight(void);
/* Inserted C code: the cleanup function of an exit point's guard variable. */
void symcr_point_at_scope_exit(struct symcr_point** point);

#ifdef __cplusplus
} /* extern "C" */

namespace symcr {
namespace generated {
/* Inserted C++ code: reaches an exit point on every return path, but not when an exception
 * leaves the function. */
class PointAtExit {
 public:
  explicit PointAtExit(symcr_point* point)
      : point_(point), in_flight_(symcr_point_exceptions_in_flight()) {}
  ~PointAtExit() {
    if (symcr_point_exceptions_in_flight() <= in_flight_) symcr_point_reached(point_);
  }
  PointAtExit(const PointAtExit&) = delete;
  PointAtExit& operator=(const PointAtExit&) = delete;

 private:
  symcr_point* point_;
  int in_flight_;
};
}  // namespace generated
}  // namespace symcr
#endif

#endif /* SYMCR_POINTS_H */
