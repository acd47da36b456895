// v1: the base Vehicle gained a field, a base Logger was added, the base Tracker removed.
#include "check.hpp"

struct Vehicle {
  int serial = 5;
  int id;
};
struct Logger {
  int level = 2;
};
struct Copter : Logger, Vehicle {
  int motors;
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  copter = Copter{};
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(copter.id == 7);
  XV_CHECK(copter.serial == 5);
  XV_CHECK(copter.level == 2);
  XV_CHECK(copter.motors == 4);
  XV_CHECK(xv::decided(report, "copter.Vehicle.serial", symcr::Decision::Kept));
  XV_CHECK(xv::decided(report, "copter.Tracker", symcr::Decision::Dropped));
  XV_CHECK(xv::decided(report, "copter.Logger", symcr::Decision::Kept));
  return xv::verdict();
}
