// Migration hooks with wrong signatures or in a namespace ADL does not search; a template
// named symcr_migrate is not a hook and not an error.
#include <symcr/symcr.hpp>
namespace nav {
struct Leg { int from; int to; };
}  // namespace nav
namespace fixes {
void symcr_migrate(nav::Leg& leg, const symcr::OldValues& old);
}  // namespace fixes
struct Motor { int gear; };
void symcr_migrate(const Motor& motor, const symcr::OldValues& old);
struct Pump { int rate; };
void symcr_migrate(Pump& pump, symcr::OldValues& old);
struct Fan { int speed; };
bool symcr_migrate(Fan& fan, const symcr::OldValues& old);
template <typename T>
void symcr_migrate(T& any, const symcr::OldValues& old);
SYMCR_CHECKPOINT nav::Leg leg;
SYMCR_CHECKPOINT Motor motor;
SYMCR_CHECKPOINT Pump pump;
SYMCR_CHECKPOINT Fan fan;
