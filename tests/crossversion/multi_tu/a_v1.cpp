#include "shared_v1.hpp"

SYMCR_CHECKPOINT Fleet fleet;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(fleet.route.size() == 2);
  if (fleet.route.size() == 2) {
    XV_CHECK(fleet.route[1].lat == 3 && fleet.route[1].lon == 4);
    XV_CHECK(fleet.route[1].speed == 8.0f);
  }
  XV_CHECK(fleet.scratch == -1);
  XV_CHECK(log_route().size() == 1 && log_route()[0].lat == 5 && log_route()[0].lon == 6);
  XV_CHECK(log_note() == "b.cpp");
  return xv::verdict();
}
