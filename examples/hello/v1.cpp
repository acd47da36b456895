// hello v1, the patched build: fields reordered, `next` renamed, battery widened to double,
// the debug counter removed and a retry counter added. It restores v0's checkpoint by names
// and resumes the mission where v0 stopped.
#include <cstdio>
#include <string>
#include <vector>

#include <symcr/symcr.hpp>

struct Waypoint {
  double lat;
  double lon;
};

struct Mission {
  double battery;  // was float
  std::vector<Waypoint> route;
  std::string name;
  int next_waypoint SYMCR_RENAMED_FROM("next");
  int retries = 3;  // new in v1: keeps this build's initial value
};

SYMCR_CHECKPOINT Mission mission;

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "hello.ckpt";
  symcr::Report report = symcr::restore(path);
  // What the patch lost says so (here: the debug counter v1 removed); the rest goes on.
  if (!report.lossless()) std::fputs(report.losses_to_text().c_str(), stderr);
  if (!report.ok()) return 1;
  std::printf("v1: resuming mission %s at waypoint %d, battery %.1f%%\n", mission.name.c_str(),
              mission.next_waypoint, mission.battery);
  for (; mission.next_waypoint < static_cast<int>(mission.route.size()); ++mission.next_waypoint)
    std::printf("v1: reached waypoint %d (%.2f, %.2f)\n", mission.next_waypoint,
                mission.route[mission.next_waypoint].lat,
                mission.route[mission.next_waypoint].lon);
  bool resumed = mission.name == "ISTAR" && mission.route.size() == 4 &&
                 mission.battery == 77.5 && mission.retries == 3;
  std::printf("v1: mission %s\n", resumed ? "completed" : "NOT resumed correctly");
  return resumed ? 0 : 1;
}
