/* v0, in C: fills a tank; the pragmas of v0_state.h save it at the exit of fill() on every
 * second call, also on its early return. */
#include <stdio.h>
#include <string.h>

#include "v0_state.h"

struct Tank tank;

int fill(int amount) {
  if (amount <= 0) return tank.level; /* an early return: the exit point runs here too */
  tank.level += amount;
  tank.pressure = tank.level * 0.5;
  tank.valves[tank.level % 3] += 1;
  return tank.level;
}

int main(void) {
  int i;
  strcpy(tank.label, "T-7");
  for (i = 1; i <= 5; ++i) fill(i);
  fill(0); /* the 6th call, saved: level 15 */
  fill(100); /* the 7th, not saved */
  printf("v0: level %d\n", tank.level);
  return 0;
}
