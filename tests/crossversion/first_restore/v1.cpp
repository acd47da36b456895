// v1: restores v0's checkpoint with README's first restore pattern, which must surface what
// did not come back: the double 12.5 the int `speed` cannot hold, the enumerator this build
// lacks, and `heading`, renamed to `yaw` without its annotation (dropped + kept, with a hint).
#include <string>

#include "check.hpp"

enum class Mode { Manual, Auto };

struct Vehicle {
  int id = -1;
  int speed = -1;
  Mode mode = Mode::Manual;
  float yaw = -1.0f;  // was `heading`: SYMCR_RENAMED_FROM("heading") forgotten
};

SYMCR_CHECKPOINT Vehicle vehicle;

namespace {

bool contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return true;
  std::fprintf(stderr, "expected '%s' in:\n%s\n", part.c_str(), text.c_str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  // README's pattern: the restore was applied, yet it lost data, and the one call says what.
  XV_CHECK(report.ok());
  XV_CHECK(!report.lossless());
  const std::string losses = report.losses_to_text();
  XV_CHECK(contains(losses, "vehicle.speed  rejected: 12.5 is not an integer for int32\n"));
  XV_CHECK(contains(losses, "vehicle.mode  rejected: enum Sport not in this build\n"));
  XV_CHECK(contains(losses,
                    "vehicle.heading  dropped: field removed in this build; did you mean "
                    "SYMCR_RENAMED_FROM(\"heading\") on yaw / renamed(Vehicle::yaw, heading)?\n"));
  XV_CHECK(contains(losses, "3 lossy decisions: "));
  // Only the losses: neither the restored `id` nor the kept `yaw` (not lossy) is listed.
  XV_CHECK(losses.find("vehicle.id") == std::string::npos);
  XV_CHECK(losses.find("vehicle.yaw") == std::string::npos);
  XV_CHECK(losses.find("status") == std::string::npos);
  // The kept field carries the hint too, in the full report.
  const symcr::ReportEntry* yaw = xv::entry(report, "vehicle.yaw");
  XV_CHECK(yaw && yaw->decision == symcr::Decision::Kept && !yaw->lossy &&
           yaw->detail ==
               "field added in this build; did you mean SYMCR_RENAMED_FROM(\"heading\") on yaw "
               "/ renamed(Vehicle::yaw, heading)?");
  // The rejected values keep this build's; the rest is restored.
  XV_CHECK(vehicle.id == 7);
  XV_CHECK(vehicle.speed == -1);
  XV_CHECK(vehicle.mode == Mode::Manual);
  XV_CHECK(vehicle.yaw == -1.0f);

  // A failed restore: the failure leads the text, and it is not lossless either.
  symcr::Report missing = symcr::restore("/nonexistent/first_restore.ckpt");
  XV_CHECK(!missing.ok() && !missing.lossless());
  XV_CHECK(contains(missing.losses_to_text(), "restore failed: Io: "));
  return xv::verdict();
}
