// The crash-loop fallback at program points, with a seeded defect: `run V` restores at the exit
// of start() and crashes when the restored level is V (`run any`: when anything was restored),
// as a value no validator caught would crash a real program; otherwise it takes five steps
// (`run V S`: S steps), each saved at step()'s exit, which confirm the restore after the store
// directive's confirm_after of them. `save N` saves levels 1 to N. Its three builds differ in
// their store directive only: an explicit fallback, the default one, and fallback_depth=0.
#include <cstdio>
#include <cstdlib>
#include <cstring>

int level = 0;

void step(int to) { level = to; }

void start() {}

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "save") == 0) {
    for (int to = 1; to <= std::atoi(argv[2]); ++to) step(to);
    return 0;
  }
  if ((argc != 3 && argc != 4) || std::strcmp(argv[1], "run") != 0) {
    std::fprintf(stderr, "usage: %s save N | run V|any [STEPS]\n", argv[0]);
    return 2;
  }
  start();
  std::printf("restored level=%d\n", level);
  std::fflush(stdout);
  const bool any = std::strcmp(argv[2], "any") == 0;
  if ((any && level != 0) || (!any && level == std::atoi(argv[2]))) std::abort();
  const int from = level;
  const int steps = argc == 4 ? std::atoi(argv[3]) : 5;
  for (int to = from + 1; to <= from + steps; ++to) step(to);
  std::printf("ran to level=%d\n", level);
  return 0;
}
