#include <symcr/symcr.hpp>
int twice(int x);
SYMCR_CHECKPOINT int mode = 3;
int main() { return twice(mode) == 6 ? 0 : 1; }
