// Roots must be writable and process-wide.
#include <symcr/symcr.hpp>

SYMCR_CHECKPOINT const int limit = 3;
SYMCR_CHECKPOINT thread_local int per_thread = 0;
