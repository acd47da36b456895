/* v1, in C: the enumerators renumbered; values come back by name. */
#include <stdio.h>

#include <symcr/symcr.h>

#include "report_file.h"

typedef enum { LINK_BAD = 10, LINK_OK = 11, LINK_NONE = 12 } link_status_t;
typedef enum { MODE_RUN = 20, MODE_IDLE = 21 } run_mode_t;

struct State {
  link_status_t link;
  run_mode_t mode;
};

struct State state;
#pragma symcr checkpoint(state)

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  symcr_report* report = NULL;
  const int status = symcr_restore(argv[1], 0, &report);
  xv_write_report(symcr_report_json(report));
  symcr_report_free(report);
  if (status != SYMCR_OK) {
    fprintf(stderr, "restore failed: %s\n", symcr_last_error());
    return 1;
  }
  if (state.link != LINK_BAD || state.mode != MODE_RUN) {
    fprintf(stderr, "wrong values: link %d mode %d\n", (int)state.link, (int)state.mode);
    return 1;
  }
  return 0;
}
