// A skip of a member that does not exist.
struct Copter {
  int mode;
};
Copter copter;
#pragma symcr checkpoint(copter)
#pragma symcr skip(Copter::mdoe)
