// With inconsistent_b.cpp: a skip pragma visible in one TU only changes the type there.
#include "inconsistent.hpp"

#pragma symcr skip(Shared::scratch)
SYMCR_CHECKPOINT Shared first;
