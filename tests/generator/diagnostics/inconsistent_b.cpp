#include "inconsistent.hpp"

SYMCR_CHECKPOINT Shared second;
