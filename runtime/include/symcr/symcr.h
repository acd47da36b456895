/* symcr C API: checkpoints, restores and the checkpoint store from C (C99) or C++.
 *
 *   if (symcr_checkpoint("copter.ckpt") != SYMCR_OK) fprintf(stderr, "%s\n", symcr_last_error());
 *
 *   symcr_report* report = NULL;
 *   symcr_restore("copter.ckpt", 0, &report);
 *   if (!symcr_report_lossless(report))
 *     fputs(symcr_report_losses_text(report), stderr);
 *   symcr_report_free(report);
 *
 * Functions taking a `const symcr_schema*` use the program's generated schema when it is NULL.
 * Every function returns SYMCR_OK (0) or an error code; the message of the calling thread's
 * last failure is symcr_last_error(). Nothing here throws or aborts on bad input. */
#ifndef SYMCR_SYMCR_H
#define SYMCR_SYMCR_H

#include <stddef.h>
#include <stdint.h>

#include "symcr/generated.h" /* symcr_schema, symcr_program_schema() */

#ifdef __cplusplus
extern "C" {
#endif

/* Error codes: the values of symcr::Error. */
enum {
  SYMCR_OK = 0,
  SYMCR_ERROR_NO_SCHEMA = 1,
  SYMCR_ERROR_IO = 2,
  SYMCR_ERROR_NOT_A_CHECKPOINT = 3,
  SYMCR_ERROR_FUTURE_VERSION = 4,
  SYMCR_ERROR_TRUNCATED = 5,
  SYMCR_ERROR_CHECKSUM = 6,
  SYMCR_ERROR_CORRUPT = 7,
  SYMCR_ERROR_SCHEMA_UNKNOWN = 8,
  SYMCR_ERROR_INCOMPATIBLE = 9,
  SYMCR_ERROR_STRICT = 10,
  SYMCR_ERROR_UNSUPPORTED = 11,
  SYMCR_ERROR_NO_VALID_SLOT = 12,
  SYMCR_ERROR_TOO_LARGE = 13,
  SYMCR_ERROR_UNAUTHENTICATED = 14,
  SYMCR_ERROR_STORE_FULL = 15,
  SYMCR_ERROR_ROLLED_BACK = 16
};

/* Restore decisions: the values of symcr::Decision. */
enum {
  SYMCR_RESTORED = 0,
  SYMCR_KEPT = 1,
  SYMCR_DROPPED = 2,
  SYMCR_CONVERTED = 3,
  SYMCR_REJECTED = 4,
  SYMCR_REBASED = 5
};

/* "Io", "Checksum", ...; "Unknown" for a value that is not an error code. */
const char* symcr_error_name(int error);
/* The message of this thread's last failed call ("" if none failed yet). */
const char* symcr_last_error(void);

/* Authenticated checkpoints (symcr::set_checkpoint_keys): keys[0] signs every checkpoint this
 * process writes; a restore refuses (SYMCR_ERROR_UNAUTHENTICATED) one without a MAC, with a key
 * id not among `keys`, or whose MAC does not verify, and a store older than its freshness
 * counter (SYMCR_ERROR_ROLLED_BACK; docs/threat-model.md). The keys are copied; count 0 turns
 * it off. */
typedef struct symcr_checkpoint_key {
  uint32_t id;
  const uint8_t* bytes;
  size_t size;
} symcr_checkpoint_key;
int symcr_set_checkpoint_keys(const symcr_checkpoint_key* keys, size_t count);

/* Single-file checkpoints (atomic replace, mode 0600, symlinks never followed). */
int symcr_checkpoint(const char* path);
int symcr_checkpoint_with(const symcr_schema* schema, const char* path, int fdatasync);

/* The restore report: opaque, owned by the caller, freed with symcr_report_free. */
typedef struct symcr_report symcr_report;

/* Restore options, or-ed into the `flags` of the restore functions: SYMCR_RESTORE_STRICT
 * refuses any lossy decision (RestoreOptions::strict); SYMCR_RESTORE_ACCEPT_OTHER_PROGRAM
 * restores a checkpoint written by another program (RestoreOptions::accept_other_program). */
#define SYMCR_RESTORE_STRICT 1
#define SYMCR_RESTORE_ACCEPT_OTHER_PROGRAM 2

/* Restores `path` with `flags` (SYMCR_RESTORE_*, 0 for none). When `report` is not NULL it
 * receives a report (also on failure) to free with symcr_report_free. */
int symcr_restore(const char* path, int flags, symcr_report** report);
int symcr_restore_with(const symcr_schema* schema, const char* path, int flags,
                       symcr_report** report);

int symcr_report_ok(const symcr_report* report);
/* 1 when the restore was applied and lost nothing (Report::lossless): no value rejected, no
 * field or root dropped; symcr_report_losses_text then is "". */
int symcr_report_lossless(const symcr_report* report);
int symcr_report_error(const symcr_report* report);
uint64_t symcr_report_sequence(const symcr_report* report);
size_t symcr_report_count(const symcr_report* report, int decision);
/* Store restores: how many slots were passed over (Report::skipped; the text and JSON say
 * which and why). */
size_t symcr_report_skipped(const symcr_report* report);
/* Text and JSON renderings, owned by the report, valid until symcr_report_free. */
const char* symcr_report_text(symcr_report* report);
const char* symcr_report_json(symcr_report* report);
/* The failure and the lossy entries only (Report::losses_to_text), "" when lossless. */
const char* symcr_report_losses_text(symcr_report* report);
void symcr_report_free(symcr_report* report);

/* A store's freshness counter (symcr::FreshnessCounter), implemented by the program over a
 * counter an attacker cannot reset (a TPM NV counter, eMMC RPMB, a backup register). `read`
 * sets *value to the highest value advanced to (0 when never advanced); `advance` raises the
 * counter to `value` when it is lower, never lowers it, and is durable once it returns. Each
 * returns SYMCR_OK or an error code (any other value counts as SYMCR_ERROR_IO); a failed read
 * means a store holding authenticated checkpoints restores nothing. */
typedef struct symcr_freshness_counter {
  void* context; /* passed to both functions */
  int (*read)(void* context, uint64_t* value);
  int (*advance)(void* context, uint64_t value);
} symcr_freshness_counter;

/* The checkpoint store: a preallocated ring of slots in one file. */
typedef struct symcr_store symcr_store;
typedef struct symcr_store_options {
  uint32_t slots;     /* default 4 */
  uint32_t slot_size; /* bytes per slot, header included; default 65536 */
  int fdatasync;      /* non-zero: fdatasync after each save */
  /* Crash-loop fallback (StoreOptions::fallback_depth): 0 (the default) turns it off. */
  uint32_t fallback_depth;
  /* Non-zero: a store opened for writing that turns out read-only restores anyway, without
   * the fallback, and says so in the report (StoreOptions::allow_unrecorded_restore). */
  int allow_unrecorded_restore;
  /* Freshness, with keys set (StoreOptions::freshness_counter, counter_path): the program's
   * counter, copied at open (its context must outlive the store), or when NULL an
   * authenticated file at `counter_path`, or when that is NULL too, at the store's path with
   * ".fresh" appended. Both default to NULL. */
  const symcr_freshness_counter* freshness_counter;
  const char* counter_path;
} symcr_store_options;

void symcr_store_options_init(symcr_store_options* options);
/* `options` NULL means the defaults. On success *store receives a handle for
 * symcr_store_close. */
int symcr_store_open(const char* path, const symcr_schema* schema,
                     const symcr_store_options* options, symcr_store** store);
int symcr_store_save(symcr_store* store);
int symcr_store_restore_latest(symcr_store* store, int flags, symcr_report** report);
/* Crash-loop fallback: the state this start restored has proven itself (Store::confirm). */
int symcr_store_confirm(symcr_store* store);
uint64_t symcr_store_last_sequence(const symcr_store* store);
void symcr_store_close(symcr_store* store);

#ifdef __cplusplus
}
#endif

#endif /* SYMCR_SYMCR_H */
