// v1 of flight_modes: a patch adds a mode and reorders the mode members. The current mode comes
// back as a pointer to v1's own mode object of the same name, whatever its new place; a
// pointer to a mode object outside the state, of a class restore cannot create, is refused
// when saving.
#include <cstdio>
#include <cstring>

#include "check.hpp"

struct Mode {
  virtual ~Mode() = default;
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct ModeRTL : Mode {
  int number() const override { return 6; }
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};
struct ModeStabilize : Mode {
  int number() const override { return 0; }
};
struct ModeFlip : Mode {
  explicit ModeFlip(int rolls) : rolls(rolls) {}
  int number() const override { return 14; }
  int rolls;
};

struct Copter {
  ModeRTL mode_rtl;  // new
  ModeLoiter mode_loiter;
  ModeAuto mode_auto;
  ModeStabilize mode_stabilize;
  Mode* flightmode = &mode_stabilize;
  Mode* previous = nullptr;
  // A callback bound to the vehicle itself: its object is a reference to the root.
  struct Callback {
    Copter* object;
    void (Copter::*method)();
  } on_mode_change{this, &Copter::announce};
  void announce() {}
};

SYMCR_CHECKPOINT Copter copter;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(copter.flightmode == &copter.mode_auto);
  XV_CHECK(copter.flightmode != nullptr && copter.flightmode->number() == 3);
  XV_CHECK(copter.mode_auto.next_waypoint == 4 && copter.mode_auto.entered_ms == 1234);
  XV_CHECK(copter.previous == &copter.mode_loiter && copter.mode_loiter.radius_m == 7.5f);
  XV_CHECK(xv::restored(report, "copter.flightmode"));
  // The report says how the pointer came back.
  const symcr::ReportEntry* current = xv::entry(report, "copter.flightmode");
  XV_CHECK(current != nullptr &&
           current->detail == "reference to the object at the same path, or a heap object "
                              "rebuilt as its dynamic type");
  // The callback's object is the root again, and the root's fields are listed once, under
  // the root, not a second time as the pointee of that callback.
  XV_CHECK(copter.on_mode_change.object == &copter);
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path.compare(0, 8, "(Copter)") == 0) {
      std::fprintf(stderr, "the root's type is listed again as a pointee: %s\n", e.path.c_str());
      ++xv::failures();
    }
  }

  // A mode object outside the state, of a class restore cannot create (no default
  // constructor): saving refuses it, naming the classes it could save.
  ModeFlip* loose = new ModeFlip(3);
  copter.flightmode = loose;
  std::vector<std::uint8_t> bytes;
  const symcr::Status saved = symcr::checkpoint_to_buffer(*symcr_program_schema(), bytes);
  XV_CHECK(saved.error() == symcr::Error::Unsupported);
  XV_CHECK(std::strstr(saved.message(), "polymorphic class Mode") != nullptr);
  XV_CHECK(std::strstr(saved.message(), "ModeLoiter") != nullptr);
  delete loose;
  return xv::verdict();
}
