/* v1, in C: restores at the exit of start() and prints the tank. */
#include <stdio.h>
#include <string.h>

#include <symcr/points.h>
#include <symcr/symcr.h>

#include "v1_state.h"

struct Tank tank;

void start(void) {
  strcpy(tank.label, "new");
  tank.alarms = 2;
  tank.level = -1;
}

/* Found by the runtime (a weak reference) when no hook is registered. */
void symcr_on_restore_point(const struct symcr_point* point, struct symcr_report* report) {
  printf("hook: %s ok=%d\n", point->directive, symcr_report_ok(report));
}

int main(void) {
  start();
  printf("label=%s level=%lld pressure=%.1f valves=%d,%d,%d alarms=%d\n", tank.label,
         tank.level, tank.pressure, tank.valves[0], tank.valves[1], tank.valves[2],
         tank.alarms);
  return 0;
}
