/* v0, in C: two typedef'd unnamed enums in one translation unit. */
#include <stdio.h>

#include <symcr/symcr.h>

typedef enum { LINK_NONE = 0, LINK_OK = 1, LINK_BAD = 2 } link_status_t;
typedef enum { MODE_IDLE = 0, MODE_RUN = 1 } run_mode_t;

struct State {
  link_status_t link;
  run_mode_t mode;
};

struct State state;
#pragma symcr checkpoint(state)

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  state.link = LINK_BAD;
  state.mode = MODE_RUN;
  if (symcr_checkpoint(argv[1]) != SYMCR_OK) {
    fprintf(stderr, "checkpoint failed: %s\n", symcr_last_error());
    return 1;
  }
  return 0;
}
