// Checkpoints a_pos with the sidecar a.symcr, which skips Pos::y.
#include "pos.hpp"
Pos a_pos;
int main() { return a_pos.x; }
