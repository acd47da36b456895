// v1 of scoped_renames: the patch renames them, writing the old names as they appear in the
// source (unqualified, as for a field); they resolve in the new name's scope.
#include <memory>

#include "check.hpp"

namespace robot {
struct SYMCR_RENAMED_FROM("Calibration") CalTable {
  int gain;
};
struct Log {
  int count;
};
struct Cal {
  CalTable* raw;
  std::shared_ptr<CalTable> shared;
};
struct Arm {
  struct SYMCR_RENAMED_FROM("Joint") Hinge {
    int angle;
  };
  Hinge elbow;
  Hinge* last = nullptr;
};
SYMCR_CHECKPOINT SYMCR_RENAMED_FROM("g_log") Log g_journal;
SYMCR_CHECKPOINT Cal g_cal;
SYMCR_CHECKPOINT Arm g_arm;
}  // namespace robot

int main(int argc, char** argv) {
  robot::g_journal.count = -1;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(robot::g_journal.count == 5);
  XV_CHECK(robot::g_cal.raw != nullptr && robot::g_cal.raw->gain == 77);
  XV_CHECK(robot::g_cal.shared != nullptr && robot::g_cal.shared->gain == 88);
  XV_CHECK(robot::g_arm.elbow.angle == 30);
  XV_CHECK(xv::decided(report, "robot::g_journal", symcr::Decision::Converted));
  return xv::verdict();
}
