// hello save <file> | hello restore <file>
#include <cstdio>
#include <cstring>

#include "state.hpp"

Greeting greeting;  // a root by hello.symcr

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  if (std::strcmp(argv[1], "save") == 0) {
    greeting.text = "hello, patched world";
    greeting.counts = {1, 2, 3};
    return symcr::checkpoint(argv[2]).ok() ? 0 : 1;
  }
  symcr::Report report = symcr::restore(argv[2]);
  std::printf("%s\n", report.to_text().c_str());
  bool ok = report.ok() && greeting.text == "hello, patched world" && greeting.counts.size() == 3;
  return ok ? 0 : 1;
}
