// range(...) directives: bounds must be numbers with lo <= hi, and the member must exist.
#include <symcr/symcr.hpp>
struct Motor { float rpm; int gear; };
SYMCR_CHECKPOINT Motor motor;
#pragma symcr range(Motor::rpm, 0, 1e4x)
#pragma symcr range(Motor::gear, 5, 1)
#pragma symcr range(Motor::gera, 1, 5)
