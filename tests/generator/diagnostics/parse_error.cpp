// Clang cannot parse this source: the failure is counted, Clang's error shown, and the root
// the annotation file names (defined here) is not reported as matching nothing.
struct State {
  int mode;
};
State state;
int broken = undeclared_name + 1;
