// A rename of a field that does not exist.
struct Copter {
  int mode;
};
#pragma symcr renamed(Copter::flight_mode, mode)
