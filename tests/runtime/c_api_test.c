/* The C API from C99: checkpoint and restore files and a store through the program's schema
 * (symcr_program_schema) and through an explicit schema handle, and error reporting.
 * Usage: symcr_c_api_test <scratch directory>. Exits non-zero on the first failed check. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <symcr/points.h>
#include <symcr/symcr.h>

#include "c_api_test_state.h"

struct c_vehicle c_vehicle_state;
uint32_t c_tick_count;

static int failures = 0;

#define CHECK(condition)                                                        \
  do {                                                                          \
    if (!(condition)) {                                                         \
      fprintf(stderr, "%s:%d: check failed: %s (last error: %s)\n", __FILE__, \
              __LINE__, #condition, symcr_last_error());                        \
      ++failures;                                                               \
    }                                                                           \
  } while (0)

static void fill(int seed) {
  c_vehicle_state.altitude_cm = 1200 + seed;
  c_vehicle_state.waypoint = (uint16_t)(seed % 7);
  c_vehicle_state.heading = 90.5 + seed;
  c_vehicle_state.trims[0] = (int16_t)-seed;
  c_vehicle_state.trims[1] = 0;
  c_vehicle_state.trims[2] = (int16_t)(seed * 3);
  c_tick_count = 40000u + (uint32_t)seed;
}

static void scramble(void) {
  memset(&c_vehicle_state, 0, sizeof c_vehicle_state);
  c_tick_count = 0;
}

static int holds(int seed) {
  return c_vehicle_state.altitude_cm == 1200 + seed &&
         c_vehicle_state.waypoint == (uint16_t)(seed % 7) &&
         c_vehicle_state.heading == 90.5 + seed && c_vehicle_state.trims[0] == -seed &&
         c_vehicle_state.trims[2] == seed * 3 && c_tick_count == 40000u + (uint32_t)seed;
}

static void file_round_trip(const char* directory) {
  char path[1024];
  symcr_report* report = NULL;
  struct stat info;
  snprintf(path, sizeof path, "%s/c.ckpt", directory);

  fill(1);
  CHECK(symcr_checkpoint(path) == SYMCR_OK);
  CHECK(stat(path, &info) == 0 && (info.st_mode & 0777) == 0600);
  scramble();
  CHECK(symcr_restore(path, 1, &report) == SYMCR_OK);
  CHECK(holds(1));
  CHECK(symcr_report_ok(report));
  CHECK(symcr_report_error(report) == SYMCR_OK);
  CHECK(symcr_report_count(report, SYMCR_REJECTED) == 0);
  CHECK(strlen(symcr_report_text(report)) > 0);
  CHECK(strstr(symcr_report_json(report), "\"ok\":true") != NULL);
  CHECK(symcr_report_lossless(report));
  CHECK(strcmp(symcr_report_losses_text(report), "") == 0);
  symcr_report_free(report);

  /* The same through an explicit schema handle, with fdatasync, and no report wanted. */
  fill(2);
  CHECK(symcr_checkpoint_with(symcr_program_schema(), path, 1) == SYMCR_OK);
  scramble();
  CHECK(symcr_restore_with(symcr_program_schema(), path, 0, NULL) == SYMCR_OK);
  CHECK(holds(2));
}

static void errors(const char* directory) {
  char path[1024];
  symcr_report* report = NULL;
  FILE* file;
  snprintf(path, sizeof path, "%s/missing.ckpt", directory);
  fill(3);
  CHECK(symcr_restore(path, 0, &report) == SYMCR_ERROR_IO);
  CHECK(!symcr_report_ok(report));
  CHECK(symcr_report_error(report) == SYMCR_ERROR_IO);
  CHECK(strstr(symcr_report_json(report), "\"ok\":false") != NULL);
  CHECK(!symcr_report_lossless(report));
  CHECK(strncmp(symcr_report_losses_text(report), "restore failed: Io: ", 20) == 0);
  symcr_report_free(report);
  CHECK(!symcr_report_lossless(NULL));
  CHECK(strcmp(symcr_report_losses_text(NULL), "") == 0);
  CHECK(strstr(symcr_last_error(), "missing.ckpt") != NULL);
  CHECK(holds(3));

  snprintf(path, sizeof path, "%s/text.ckpt", directory);
  file = fopen(path, "w");
  CHECK(file != NULL);
  if (file != NULL) {
    fputs("not a checkpoint, but long enough to hold a whole header......\n", file);
    fclose(file);
  }
  CHECK(symcr_restore(path, 0, NULL) == SYMCR_ERROR_NOT_A_CHECKPOINT);
  CHECK(holds(3));

  CHECK(strcmp(symcr_error_name(SYMCR_ERROR_CHECKSUM), "Checksum") == 0);
  CHECK(strcmp(symcr_error_name(SYMCR_ERROR_NO_VALID_SLOT), "NoValidSlot") == 0);
  CHECK(strcmp(symcr_error_name(-1), "Unknown") == 0);
  CHECK(strcmp(symcr_error_name(99), "Unknown") == 0);
  CHECK(symcr_checkpoint(NULL) == SYMCR_ERROR_IO);
  symcr_report_free(NULL);
  /* This program has no program points: there is no points' store to open. */
  CHECK(symcr_points_open_store() == SYMCR_ERROR_NO_SCHEMA);
  CHECK(strstr(symcr_last_error(), "no program points") != NULL);
}

/* Authenticated checkpoints: verified with the key they name, refused with another. */
static void authenticated(const char* directory) {
  static const uint8_t key[] = {1, 2, 3, 4, 5, 6, 7, 8};
  static const uint8_t other[] = {8, 7, 6, 5, 4, 3, 2, 1};
  const symcr_checkpoint_key signing = {3, key, sizeof key};
  const symcr_checkpoint_key wrong = {3, other, sizeof other};
  char path[1024];
  snprintf(path, sizeof path, "%s/authenticated.ckpt", directory);
  CHECK(symcr_set_checkpoint_keys(&signing, 1) == SYMCR_OK);
  fill(5);
  CHECK(symcr_checkpoint(path) == SYMCR_OK);
  scramble();
  CHECK(symcr_restore(path, 0, NULL) == SYMCR_OK);
  CHECK(holds(5));
  CHECK(symcr_set_checkpoint_keys(&wrong, 1) == SYMCR_OK);
  scramble();
  CHECK(symcr_restore(path, 0, NULL) == SYMCR_ERROR_UNAUTHENTICATED);
  CHECK(strstr(symcr_last_error(), "does not verify with key id 3") != NULL);
  CHECK(c_tick_count == 0);
  CHECK(strcmp(symcr_error_name(SYMCR_ERROR_UNAUTHENTICATED), "Unauthenticated") == 0);
  CHECK(strcmp(symcr_error_name(SYMCR_ERROR_STORE_FULL), "StoreFull") == 0);
  CHECK(symcr_set_checkpoint_keys(NULL, 1) == SYMCR_ERROR_UNSUPPORTED);
  CHECK(symcr_set_checkpoint_keys(NULL, 0) == SYMCR_OK);
}

static void store_round_trip(const char* directory) {
  char path[1024];
  symcr_store* store = NULL;
  symcr_store_options options;
  symcr_report* report = NULL;
  int seed;
  snprintf(path, sizeof path, "%s/c.store", directory);

  symcr_store_options_init(&options);
  CHECK(options.slots == 4 && options.slot_size == 65536 && options.fdatasync == 0 &&
        options.fallback_depth == 0);
  options.slots = 3;
  options.slot_size = 4096;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  CHECK(symcr_store_restore_latest(store, 0, NULL) == SYMCR_ERROR_NO_VALID_SLOT);
  for (seed = 10; seed < 15; ++seed) {
    fill(seed);
    CHECK(symcr_store_save(store) == SYMCR_OK);
  }
  CHECK(symcr_store_last_sequence(store) == 5);
  symcr_store_close(store);

  store = NULL;
  CHECK(symcr_store_open(path, symcr_program_schema(), &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  scramble();
  CHECK(symcr_store_restore_latest(store, 1, &report) == SYMCR_OK);
  CHECK(symcr_report_sequence(report) == 5);
  CHECK(holds(14));
  symcr_report_free(report);
  symcr_store_close(store);

  /* A second geometry for a store that holds checkpoints: its checkpoints still restore, and
     the first save rewrites it with the new geometry, carrying them over. */
  options.slots = 5;
  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  scramble();
  CHECK(symcr_store_restore_latest(store, 1, NULL) == SYMCR_OK);
  CHECK(holds(14));
  fill(15);
  CHECK(symcr_store_save(store) == SYMCR_OK);
  CHECK(symcr_store_last_sequence(store) == 6);
  symcr_store_close(store);
  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  scramble();
  CHECK(symcr_store_restore_latest(store, 1, NULL) == SYMCR_OK);
  CHECK(holds(15));
  symcr_store_close(store);
  symcr_store_close(NULL);
}

/* The crash-loop fallback: a start that restores and ends without confirming makes the next
   start restore the older checkpoint; once that one is confirmed, it is restored again and the
   one that crashed never is. */
static void crash_loop_fallback(const char* directory) {
  char path[1024];
  symcr_store* store = NULL;
  symcr_store_options options;
  symcr_report* report = NULL;
  int seed;
  snprintf(path, sizeof path, "%s/crash.store", directory);
  symcr_store_options_init(&options);
  options.fallback_depth = 1;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  for (seed = 1; seed <= 3; ++seed) {
    fill(seed);
    CHECK(symcr_store_save(store) == SYMCR_OK);
  }
  CHECK(symcr_store_restore_latest(store, 0, NULL) == SYMCR_OK);
  symcr_store_close(store); /* no symcr_store_confirm: a crash, as far as the store knows */

  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  scramble();
  CHECK(symcr_store_restore_latest(store, 0, &report) == SYMCR_OK);
  CHECK(symcr_report_sequence(report) == 2);
  CHECK(symcr_report_skipped(report) == 1);
  CHECK(strstr(symcr_report_text(report), "skipped slot") != NULL);
  CHECK(holds(2));
  symcr_report_free(report);
  CHECK(symcr_store_confirm(store) == SYMCR_OK);
  symcr_store_close(store);

  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  scramble();
  CHECK(symcr_store_restore_latest(store, 0, &report) == SYMCR_OK);
  /* 2 proved itself; 3, which crashed, is never restored again */
  CHECK(symcr_report_sequence(report) == 2);
  CHECK(symcr_report_skipped(report) == 1);
  CHECK(holds(2));
  symcr_report_free(report);
  symcr_store_close(store);
  CHECK(symcr_store_confirm(NULL) == SYMCR_ERROR_IO);
  CHECK(symcr_report_skipped(NULL) == 0);
}

/* The program's freshness counter through the C API: advanced by every save, a store older
   than it refused (SYMCR_ERROR_ROLLED_BACK), a counter that cannot be read refuses the
   restore with its own code, and a counter file at the path the options name. */
typedef struct test_counter {
  uint64_t value;
  int advances;
  int read_result;
} test_counter;

static int test_counter_read(void* context, uint64_t* value) {
  test_counter* counter = (test_counter*)context;
  if (counter->read_result != SYMCR_OK) return counter->read_result;
  *value = counter->value;
  return SYMCR_OK;
}

static int test_counter_advance(void* context, uint64_t value) {
  test_counter* counter = (test_counter*)context;
  if (value > counter->value) counter->value = value;
  ++counter->advances;
  return SYMCR_OK;
}

static int copy_file(const char* from, const char* to) {
  char buffer[4096];
  size_t got;
  FILE* in = fopen(from, "rb");
  FILE* out = in != NULL ? fopen(to, "wb") : NULL;
  int ok = out != NULL;
  while (ok && (got = fread(buffer, 1, sizeof buffer, in)) > 0) ok = fwrite(buffer, 1, got, out) == got;
  if (in != NULL) fclose(in);
  if (out != NULL && fclose(out) != 0) ok = 0;
  return ok;
}

static void freshness_counter(const char* directory) {
  static const uint8_t key[] = {9, 8, 7, 6, 5, 4, 3, 2};
  const symcr_checkpoint_key signing = {4, key, sizeof key};
  test_counter counter = {0, 0, SYMCR_OK};
  symcr_freshness_counter callbacks;
  symcr_store_options options;
  symcr_store* store = NULL;
  char path[1024], old_copy[1024], counter_path[1024];
  struct stat info;
  snprintf(path, sizeof path, "%s/fresh.store", directory);
  snprintf(old_copy, sizeof old_copy, "%s/fresh.store.old", directory);
  snprintf(counter_path, sizeof counter_path, "%s/elsewhere.fresh", directory);
  callbacks.context = &counter;
  callbacks.read = test_counter_read;
  callbacks.advance = test_counter_advance;

  symcr_store_options_init(&options);
  CHECK(options.freshness_counter == NULL && options.counter_path == NULL &&
        options.allow_unrecorded_restore == 0);
  CHECK(symcr_set_checkpoint_keys(&signing, 1) == SYMCR_OK);
  options.freshness_counter = &callbacks;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  fill(20);
  CHECK(symcr_store_save(store) == SYMCR_OK);
  CHECK(copy_file(path, old_copy));
  fill(21);
  CHECK(symcr_store_save(store) == SYMCR_OK);
  symcr_store_close(store);
  CHECK(counter.advances >= 2 && counter.value >= 2);
  /* no counter file next to the store: the program's counter was used */
  snprintf(path + strlen(path), sizeof path - strlen(path), ".fresh");
  CHECK(stat(path, &info) != 0);
  path[strlen(path) - strlen(".fresh")] = '\0';

  /* the older copy put back: refused, the state untouched */
  CHECK(copy_file(old_copy, path));
  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  fill(22);
  CHECK(symcr_store_restore_latest(store, 0, NULL) == SYMCR_ERROR_ROLLED_BACK);
  CHECK(holds(22));
  symcr_store_close(store);

  /* a counter that cannot be read: nothing restored, its code reported */
  counter.read_result = SYMCR_ERROR_IO;
  store = NULL;
  if (symcr_store_open(path, NULL, &options, &store) == SYMCR_OK && store != NULL) {
    CHECK(symcr_store_restore_latest(store, 0, NULL) == SYMCR_ERROR_IO);
    symcr_store_close(store);
  }
  CHECK(strstr(symcr_last_error(), "freshness counter: read failed with Io") != NULL);
  CHECK(holds(22));
  counter.read_result = SYMCR_OK;

  /* a counter without its functions is refused at open */
  callbacks.advance = NULL;
  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_ERROR_UNSUPPORTED);
  CHECK(store == NULL);

  /* no program counter: an authenticated file where counter_path says */
  options.freshness_counter = NULL;
  options.counter_path = counter_path;
  snprintf(path, sizeof path, "%s/fresh2.store", directory);
  store = NULL;
  CHECK(symcr_store_open(path, NULL, &options, &store) == SYMCR_OK);
  if (store == NULL) return;
  CHECK(symcr_store_save(store) == SYMCR_OK);
  symcr_store_close(store);
  CHECK(stat(counter_path, &info) == 0 && info.st_size > 0);
  CHECK(symcr_set_checkpoint_keys(NULL, 0) == SYMCR_OK);
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s <scratch directory>\n", argv[0]);
    return 2;
  }
  mkdir(argv[1], 0700);
  file_round_trip(argv[1]);
  errors(argv[1]);
  authenticated(argv[1]);
  store_round_trip(argv[1]);
  crash_loop_fallback(argv[1]);
  freshness_counter(argv[1]);
  if (failures == 0) printf("symcr C API: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
