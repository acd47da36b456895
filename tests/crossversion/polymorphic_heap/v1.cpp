// v1 of polymorphic_heap: every class behind a Behavior pointer changed its members (added,
// removed, widened, renamed, narrowed). The heap objects come back as v1's classes, and the
// report lists each class's changes field by field, as it does a root's: `(Orbit).laps` is
// dropped (lossy), so strict mode refuses the restore and writes nothing.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "check.hpp"

struct Behavior {
  virtual ~Behavior() {}
  virtual int kind() const = 0;
  std::int32_t ticks = 0;
};
struct Land : Behavior {
  int kind() const override { return 4; }
  float descent_mps = 0;
};
struct Orbit : Behavior {
  int kind() const override { return 1; }
  double radius_m = 0;
  float bank_deg = 30;  // new
};
struct Climb : Behavior {
  int kind() const override { return 2; }
  std::int32_t rate = 0;
  float target_alt_m SYMCR_RENAMED_FROM("target_m") = 0;
};
struct Hover : Behavior {
  int kind() const override { return 3; }
  float hold_s = 0;
};

struct Pilot {
  Behavior* active = nullptr;
  std::vector<Behavior*> queue;
};

SYMCR_CHECKPOINT Pilot pilot;

namespace {

bool entry_is(const symcr::Report& report, const char* path, symcr::Decision decision,
              bool lossy, const char* detail) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.decision == decision && e.lossy == lossy &&
        e.detail.find(detail) != std::string::npos) {
      return true;
    }
  }
  std::fprintf(stderr, "no entry %s %s%s '%s'\n", path, symcr::decision_name(decision),
               lossy ? " *" : "", detail);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  // Strict: dropping Orbit::laps (and rounding Hover::hold_s) is refused, nothing written.
  const symcr::Report strict = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(strict.status().error() == symcr::Error::Strict);
  XV_CHECK(pilot.active == nullptr && pilot.queue.empty());

  const symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  for (const symcr::Report* r : {&strict, &report}) {
    XV_CHECK(entry_is(*r, "(Orbit).bank_deg", symcr::Decision::Kept, false, "added"));
    XV_CHECK(entry_is(*r, "(Orbit).laps", symcr::Decision::Dropped, true, "removed"));
    XV_CHECK(entry_is(*r, "(Orbit).radius_m", symcr::Decision::Restored, false, ""));
    XV_CHECK(entry_is(*r, "(Climb).rate", symcr::Decision::Converted, false, "int16 -> int32"));
    XV_CHECK(entry_is(*r, "(Climb).target_alt_m", symcr::Decision::Converted, false,
                      "renamed from target_m"));
    XV_CHECK(entry_is(*r, "(Hover).hold_s", symcr::Decision::Converted, true, "float64 -> float32"));
    XV_CHECK(entry_is(*r, "(Land).descent_mps", symcr::Decision::Restored, false, ""));
  }

  Behavior* active = pilot.active;
  XV_CHECK(active != nullptr && active->kind() == 1);
  if (active && active->kind() == 1) {
    const Orbit* orbit = static_cast<const Orbit*>(active);
    XV_CHECK(orbit->ticks == 20 && orbit->radius_m == 150.5);
    XV_CHECK(orbit->bank_deg == 30.0f);  // v1's default: the checkpoint has none
  }
  XV_CHECK(pilot.queue.size() == 4);
  if (pilot.queue.size() == 4) {
    Behavior* first = pilot.queue[0];
    XV_CHECK(first != nullptr && first->kind() == 2);
    if (first && first->kind() == 2) {
      const Climb* climb = static_cast<const Climb*>(first);
      XV_CHECK(climb->ticks == 5 && climb->rate == -120 && climb->target_alt_m == 42.25f);
    }
    Behavior* second = pilot.queue[1];
    XV_CHECK(second != nullptr && second->kind() == 3);
    if (second && second->kind() == 3) {
      const Hover* hover = static_cast<const Hover*>(second);
      XV_CHECK(hover->ticks == 7 && hover->hold_s == 2.5f);
    }
    XV_CHECK(pilot.queue[2] == active);  // one object, as saved
    Behavior* last = pilot.queue[3];
    XV_CHECK(last != nullptr && last->kind() == 4);
    if (last && last->kind() == 4) XV_CHECK(static_cast<const Land*>(last)->descent_mps == 0.75f);
    for (std::size_t i = 0; i < pilot.queue.size(); ++i) {
      if (i != 2) delete pilot.queue[i];
    }
  }
  delete active;
  return xv::verdict();
}
