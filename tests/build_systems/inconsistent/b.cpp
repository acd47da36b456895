// Checkpoints b_pos with the sidecar b.symcr, which keeps every member of Pos.
#include "pos.hpp"
Pos b_pos;
