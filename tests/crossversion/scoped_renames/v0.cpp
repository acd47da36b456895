// v0: a root and a type inside a namespace, and a nested class, under their first names.
#include <memory>

#include "check.hpp"

namespace robot {
struct Calibration {
  int gain;
};
struct Log {
  int count;
};
struct Cal {
  Calibration* raw;
  std::shared_ptr<Calibration> shared;
};
struct Arm {
  struct Joint {
    int angle;
  };
  Joint elbow;
};
SYMCR_CHECKPOINT Log g_log;
SYMCR_CHECKPOINT Cal g_cal;
SYMCR_CHECKPOINT Arm g_arm;
}  // namespace robot

int main(int argc, char** argv) {
  robot::g_log.count = 5;
  robot::g_cal.raw = new robot::Calibration{77};
  robot::g_cal.shared = std::make_shared<robot::Calibration>(robot::Calibration{88});
  robot::g_arm.elbow.angle = 30;
  return xv::save(argc, argv);
}
