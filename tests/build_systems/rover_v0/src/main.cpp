// The program: defines the root. Ten steps; the point saves after steps 3, 6 and 9.
#include <cstdio>

#include "rover.hpp"

Rover rover;

int main() {
  rover.start("rv-1");
  int done = 0;
  for (int i = 0; i < 10; ++i) done = clamp_steps(rover.step());
  std::printf("v0 ran %d steps\n", done);
  return 0;
}
