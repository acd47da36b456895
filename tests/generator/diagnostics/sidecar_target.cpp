// Annotated only by bad.symcr, whose second directive names nothing.
struct Copter {
  int mode;
};
Copter copter;
