// A source symcr has nothing to do with: the wrapper compiles it with the original command.
#include "rover.hpp"

const char* banner() { return "rover v1"; }
