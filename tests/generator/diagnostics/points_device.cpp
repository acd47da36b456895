// Program points in a device-profile build: the device has no store to save them into.
int value;
#pragma symcr checkpoint(value)
#pragma symcr store("vehicle.store")
#pragma symcr checkpoint_at(tick, exit)
void tick() { ++value; }
