// A skip of a type that does not exist.
struct Copter {
  int mode;
};
#pragma symcr skip(Coptre)
