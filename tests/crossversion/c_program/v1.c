/* v1, in C: fields reordered, ticks widened to 64 bits, one field added. `ticks` is a root by
 * the sidecar file c_program/v1.symcr instead of a pragma. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <symcr/symcr.h>

#include "report_file.h"

typedef struct {
  double lon;
  double lat;
} Point;

struct Vehicle {
  char name[16];
  unsigned motors : 4;
  unsigned armed : 1;
  int battery;
  struct Vehicle* self;
  Point route[3];
  int mode;
};

static struct Vehicle vehicle;
#pragma symcr checkpoint(vehicle)
int64_t ticks;

static int failures;
#define CHECK(c) \
  do { \
    if (!(c)) { \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #c); \
      ++failures; \
    } \
  } while (0)

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  vehicle.battery = 80;
  symcr_report* report = NULL;
  int status = symcr_restore(argv[1], 0, &report);
  printf("%s\n", symcr_report_text(report));
  xv_write_report(symcr_report_json(report));
  CHECK(status == SYMCR_OK);
  CHECK(symcr_report_ok(report));
  symcr_report_free(report);
  CHECK(vehicle.mode == 2);
  CHECK(vehicle.route[2].lat == 3.0 && vehicle.route[2].lon == -3.0);
  CHECK(vehicle.armed == 1 && vehicle.motors == 6);
  CHECK(vehicle.self == &vehicle);
  CHECK(strcmp(vehicle.name, "c-copter") == 0);
  CHECK(vehicle.battery == 80);
  CHECK(ticks == 1234);
  return failures ? 1 : 0;
}
