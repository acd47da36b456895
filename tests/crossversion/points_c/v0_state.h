/* v0's state and its annotations, as pragmas in a header (C). */
#ifndef POINTS_C_V0_STATE_H
#define POINTS_C_V0_STATE_H

struct Tank {
  int level;
  double pressure;
  char label[8];
  int valves[3];
};

extern struct Tank tank;
int fill(int amount);

#pragma symcr checkpoint(tank)
#pragma symcr store("points_c.store", slots=3, slot_size=2048)
#pragma symcr checkpoint_at(fill, exit, every 2)

#endif
