// A point without a store directive.
int value;
#pragma symcr checkpoint(value)
#pragma symcr checkpoint_at(tick, exit)
void tick() { ++value; }
