// v1: declares ranges (macro, pragma and sidecar forms) and validation hooks (a hidden friend,
// a function in the type's namespace, a global function). Values that fail them are rejected
// and keep v1's initial values; strict mode refuses the whole restore and writes nothing.
#include <vector>

#include <symcr/generated.hpp>  // the test inspects the generated tables

#include "check.hpp"

struct Motor {
  float rpm SYMCR_RANGE(0, 10000);
  int gear;
  float temp;  // range(Motor::temp, -40, 125) in v1.symcr
};
#pragma symcr range(Motor::gear, 1, 5)

namespace nav {
struct Leg {
  int from;
  int to;
  friend bool symcr_validate(const Leg& leg) { return leg.from != leg.to; }
};
struct Waypoint {
  double lat;
  double alt;
};
bool symcr_validate(const Waypoint& waypoint);
bool symcr_validate(const Waypoint& waypoint) { return waypoint.alt >= 0.0; }
}  // namespace nav

struct Battery {
  float volts;
  std::vector<int> cells;
};
bool symcr_validate(const Battery& battery);
bool symcr_validate(const Battery& battery) {
  return battery.volts > 0.0f && !battery.cells.empty();
}

SYMCR_CHECKPOINT Motor motor;
SYMCR_CHECKPOINT nav::Leg legs[3];
SYMCR_CHECKPOINT nav::Waypoint waypoint;
SYMCR_CHECKPOINT Battery battery;
SYMCR_CHECKPOINT Battery spare;

namespace {

void initialise() {
  motor = Motor{1000.0f, 2, 20.0f};
  legs[0] = nav::Leg{0, 1};
  legs[1] = nav::Leg{1, 2};
  legs[2] = nav::Leg{2, 3};
  waypoint = nav::Waypoint{1.0, 100.0};
  battery = Battery{12.0f, {1, 2}};
  spare = Battery{0.5f, {3}};
}

bool initial() {
  return motor.rpm == 1000.0f && motor.gear == 2 && motor.temp == 20.0f && legs[0].from == 0 &&
         legs[0].to == 1 && legs[1].from == 1 && legs[1].to == 2 && legs[2].from == 2 &&
         legs[2].to == 3 && waypoint.lat == 1.0 && waypoint.alt == 100.0 &&
         battery.volts == 12.0f && battery.cells == std::vector<int>{1, 2} &&
         spare.volts == 0.5f && spare.cells == std::vector<int>{3};
}

}  // namespace

int main(int argc, char** argv) {
  const symcr::Schema* schema = symcr_program_schema();
  XV_CHECK(schema != nullptr);
  for (std::uint32_t t = 0; schema && t < schema->type_count; ++t) {
    const symcr::TypeInfo& type = schema->types[t];
    const bool hooked = std::strcmp(type.name, "nav::Leg") == 0 ||
                        std::strcmp(type.name, "nav::Waypoint") == 0 ||
                        std::strcmp(type.name, "Battery") == 0;
    XV_CHECK(hooked == (type.validate != nullptr));
  }

  // Strict: any rejection fails the restore, and nothing is written.
  initialise();
  symcr::Report strict = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(!strict.ok());
  XV_CHECK(initial());

  initialise();
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(motor.rpm == 1000.0f);  // 20000 is outside SYMCR_RANGE(0, 10000)
  XV_CHECK(motor.gear == 3);       // inside range(Motor::gear, 1, 5)
  XV_CHECK(motor.temp == 20.0f);   // 200 is outside the sidecar's range(Motor::temp, -40, 125)
  XV_CHECK(xv::decided(report, "motor.rpm", symcr::Decision::Rejected));
  XV_CHECK(xv::decided(report, "motor.temp", symcr::Decision::Rejected));
  XV_CHECK(xv::restored(report, "motor.gear"));
  XV_CHECK(legs[0].from == 5 && legs[0].to == 6);
  XV_CHECK(legs[1].from == 1 && legs[1].to == 2);  // {7, 7} fails Leg's hook
  XV_CHECK(legs[2].from == 8 && legs[2].to == 9);
  XV_CHECK(xv::decided(report, "legs[1]", symcr::Decision::Rejected));
  XV_CHECK(waypoint.lat == 1.0 && waypoint.alt == 100.0);
  XV_CHECK(xv::decided(report, "waypoint", symcr::Decision::Rejected));
  XV_CHECK(battery.volts == 12.0f && (battery.cells == std::vector<int>{1, 2}));
  XV_CHECK(xv::decided(report, "battery", symcr::Decision::Rejected));
  XV_CHECK(spare.volts == 11.5f && (spare.cells == std::vector<int>{4, 5}));
  XV_CHECK(xv::restored(report, "spare"));
  return xv::verdict();
}
