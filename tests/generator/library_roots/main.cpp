#include <symcr/symcr.hpp>
namespace nav {
void advance();
}
SYMCR_CHECKPOINT int mode = 3;
int main() {
  nav::advance();
  return symcr::checkpoint("/dev/null/never").ok() ? 0 : 1;
}
