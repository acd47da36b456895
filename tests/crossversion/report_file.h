/* The restore report a cross-version v1 writes for plan_restore_pair.cmake, which checks that
 * `symcr plan` foresees the same entries: the JSON of the process's first restore goes into
 * the file the environment variable XV_REPORT names (nothing when it is unset). C and C++. */
#ifndef SYMCR_TESTS_CROSSVERSION_REPORT_FILE_H
#define SYMCR_TESTS_CROSSVERSION_REPORT_FILE_H

#include <stdio.h>
#include <stdlib.h>

static inline void xv_write_report(const char* json) {
  static int written = 0;
  const char* path = getenv("XV_REPORT");
  FILE* file = NULL;
  if (path == NULL || written) return;
  written = 1;
  file = fopen(path, "w");
  if (file == NULL || fputs(json, file) < 0 || fclose(file) != 0) {
    fprintf(stderr, "XV_REPORT: cannot write %s\n", path);
    exit(1);
  }
}

#endif /* SYMCR_TESTS_CROSSVERSION_REPORT_FILE_H */
