// v1 of heap_modes: the mode classes are declared in another order, ModeGuided lists its bases
// the other way round (Mode now first), ModeAuto gains a member, ModeSport is gone and ModeBrake
// is new. Each heap object comes back as v1's class of the same name, reached through the same
// pointers; the pointer to a ModeSport cannot be restored and says so.
#include <cstring>
#include <vector>

#include "check.hpp"

struct Mode {
  virtual ~Mode() {}
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct Telemetry {
  virtual ~Telemetry() {}
  virtual void send() { ++sent; }
  int sent = 0;
};
struct ModeBrake : Mode {
  int number() const override { return 17; }
};
struct ModeGuided : Mode, Telemetry {
  int number() const override { return 4; }
  double target_alt_m = 0;
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int loops = 1;  // new
  int next_waypoint = 0;
};

struct Vehicle {
  Mode* current = nullptr;
  Mode* same_as_current = nullptr;
  std::vector<Mode*> history;
  Mode* sport = nullptr;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.status().ok());
  Mode* current = vehicle.current;
  XV_CHECK(current != nullptr && current->number() == 4);
  if (current && current->number() == 4) {
    ModeGuided* guided = static_cast<ModeGuided*>(current);
    XV_CHECK(guided->target_alt_m == 42.5 && guided->sent == 9 && guided->entered_ms == 200);
    guided->send();  // its vtable is v1's own
    XV_CHECK(guided->sent == 10);
  }
  XV_CHECK(vehicle.same_as_current == current);  // one object, as saved
  XV_CHECK(vehicle.history.size() == 4);
  if (vehicle.history.size() == 4) {
    Mode* first = vehicle.history[0];
    XV_CHECK(first != nullptr && first->number() == 3);
    if (first && first->number() == 3) {
      ModeAuto* auto_mode = static_cast<ModeAuto*>(first);
      XV_CHECK(auto_mode->next_waypoint == 7 && auto_mode->entered_ms == 100);
      XV_CHECK(auto_mode->loops == 1);  // new member: v1's default
    }
    Mode* second = vehicle.history[1];
    XV_CHECK(second != nullptr && second->number() == 5);
    if (second && second->number() == 5) {
      XV_CHECK(static_cast<ModeLoiter*>(second)->radius_m == 12.5f);
    }
    XV_CHECK(vehicle.history[2] == current);
    XV_CHECK(vehicle.history[3] == nullptr);
  }
  XV_CHECK(xv::restored(report, "vehicle.current"));
  const symcr::ReportEntry* entry = xv::entry(report, "vehicle.current");
  XV_CHECK(entry != nullptr &&
           entry->detail == "reference to the object at the same path, or a heap object "
                            "rebuilt as its dynamic type");
  // No class ModeSport here: the pointer keeps v1's value, and the report says why.
  XV_CHECK(vehicle.sport == nullptr);
  XV_CHECK(xv::decided(report, "vehicle.sport", symcr::Decision::Rejected));
  const symcr::ReportEntry* sport = nullptr;
  for (const symcr::ReportEntry& e : report.entries())
    if (e.path == "vehicle.sport" && e.decision == symcr::Decision::Rejected) sport = &e;
  XV_CHECK(sport != nullptr && sport->detail.find("ModeSport") != std::string::npos);

  if (vehicle.history.size() == 4) {
    delete vehicle.history[0];
    delete vehicle.history[1];
  }
  delete current;
  return xv::verdict();
}
