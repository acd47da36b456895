// The program: defines the root, restores it at Rover::init's exit and prints it.
#include <cstdio>

#include "rover.hpp"

Rover rover;

int main() {
  std::printf("%s\n", banner());
  rover.init();
  rover.print();
  return 0;
}
