// hello v0: a tiny "mission" that visits waypoints and checkpoints after each one.
//   ./hello_v0 hello.ckpt     flies three legs, checkpoints, and "crashes"
//   ./hello_v1 hello.ckpt     the patched build resumes from the checkpoint
#include <cstdio>
#include <string>
#include <vector>

#include <symcr/symcr.hpp>

struct Waypoint {
  double lat;
  double lon;
};

struct Mission {
  std::string name;
  std::vector<Waypoint> route;
  int next;           // index of the next waypoint
  float battery;      // percent
  int debug_counter;  // removed in v1
};

SYMCR_CHECKPOINT Mission mission;

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "hello.ckpt";
  mission.name = "ISTAR";
  mission.route = {{42.30, -71.10}, {42.31, -71.11}, {42.32, -71.12}, {42.33, -71.13}};
  mission.battery = 100.0f;
  for (mission.next = 0; mission.next < 3;) {
    std::printf("v0: reached waypoint %d (%.2f, %.2f)\n", mission.next,
                mission.route[mission.next].lat, mission.route[mission.next].lon);
    ++mission.next;
    mission.battery -= 7.5f;
    ++mission.debug_counter;
    symcr::Status status = symcr::checkpoint(path);
    if (!status.ok()) {
      std::fprintf(stderr, "checkpoint: %s\n", status.message());
      return 1;
    }
  }
  std::printf("v0: defect detected after waypoint 2; stopping\n");
  return 0;
}
