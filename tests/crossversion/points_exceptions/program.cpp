// An exit point is left out when an exception leaves the function: `step` saves at its exit,
// but not when it throws. Run `save`, then `load` (which restores at the exit of load_state and
// prints what it got). The program is compiled as a copy with the points inserted; __FILE__ and
// __LINE__ still name this file and line (a #line directive), which `load` prints too.
#include <cstdio>
#include <cstring>
#include <stdexcept>

int level = 0;

void step(int to) {
  level = to;
  if (to < 0) throw std::runtime_error("negative level");
}

const char* load_file = "";
int load_line = 0;

void load_state() {
  level = -100;
  load_file = __FILE__;
  load_line = __LINE__;  // line 22 of this file
}

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "save") == 0) {
    step(7);  // saved: 7
    try {
      step(-5);  // throws: not saved, though `level` is -5 now
    } catch (const std::exception& error) {
      std::printf("caught: %s\n", error.what());
    }
    return 0;
  }
  load_state();
  const char* name = std::strrchr(load_file, '/');
  std::printf("level=%d at %s:%d\n", level, name != nullptr ? name + 1 : load_file, load_line);
  return 0;
}
