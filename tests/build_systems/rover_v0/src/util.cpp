// A source symcr has nothing to do with: the wrapper compiles it with the original command.
#include "rover.hpp"

int clamp_steps(int steps) { return steps < 0 ? 0 : steps; }
