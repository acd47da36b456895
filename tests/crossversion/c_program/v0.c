/* v0, in C: annotated with pragmas (C has no attributes-based macros of its own). */
#include <stdio.h>
#include <string.h>

#include <symcr/symcr.h>

typedef struct {
  double lat;
  double lon;
} Point;

struct Vehicle {
  int mode;
  Point route[3];
  unsigned armed : 1;
  unsigned motors : 4;
  struct Vehicle* self;
  char name[16];
};

static struct Vehicle vehicle; /* internal linkage */
#pragma symcr checkpoint(vehicle)
int ticks;
#pragma symcr checkpoint(ticks)

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  vehicle.mode = 2;
  for (int i = 0; i < 3; ++i) {
    vehicle.route[i].lat = 1.0 + i;
    vehicle.route[i].lon = -1.0 - i;
  }
  vehicle.armed = 1;
  vehicle.motors = 6;
  vehicle.self = &vehicle;
  strcpy(vehicle.name, "c-copter");
  ticks = 1234;
  if (symcr_checkpoint(argv[1]) != SYMCR_OK) {
    fprintf(stderr, "%s\n", symcr_last_error());
    return 1;
  }
  return 0;
}
