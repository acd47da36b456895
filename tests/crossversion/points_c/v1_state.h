/* v1's state: fields reordered, `level` widened to long long, a field added. The restore runs
 * at the exit of start(); a weak-linked symcr_on_restore_point (main's file) sees the report. */
#ifndef POINTS_C_V1_STATE_H
#define POINTS_C_V1_STATE_H

struct Tank {
  char label[8];
  int valves[3];
  double pressure;
  long long level;
  int alarms; /* new in v1 */
};

extern struct Tank tank;
void start(void);

#pragma symcr checkpoint(tank)
#pragma symcr store("points_c.store", slots=3, slot_size=2048)
#pragma symcr restore_at(start, exit)

#endif
