// Validation hooks with the wrong signature or in a namespace ADL does not search.
#include <symcr/symcr.hpp>
namespace nav {
struct Leg { int from; int to; };
}  // namespace nav
namespace checks {
bool symcr_validate(const nav::Leg& leg);
}  // namespace checks
struct Motor { int gear; };
bool symcr_validate(Motor& motor);
SYMCR_CHECKPOINT nav::Leg leg;
SYMCR_CHECKPOINT Motor motor;
