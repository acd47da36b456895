// v1 of the rover, a patched build that knows nothing of checkpointing either: members
// reordered, `heading_` renamed `yaw_` and widened to double, a waypoint field added. The
// annotation file v1.symcr restores `rover` at the exit of Rover::init; main prints what
// the rover holds afterwards.
#include <cstdio>
#include <string>
#include <vector>

struct Waypoint {
  double lon;
  double lat;
  float speed = 2.5f;  // new in v1: keeps this default
};

class Rover {
 public:
  void init();
  void print() const;

 private:
  unsigned steps_ = 0;
  std::vector<Waypoint> route_;
  double yaw_ = -1;
  int mode_ = 0;
  std::string name_ = "unnamed";
};

Rover rover;

void Rover::init() {
  route_.clear();
  mode_ = 0;
}

void Rover::print() const {
  std::printf("name=%s mode=%d yaw=%.2f steps=%u route=%zu\n", name_.c_str(), mode_, yaw_,
              steps_, route_.size());
  for (const Waypoint& w : route_) std::printf("  %.1f %.1f %.1f\n", w.lat, w.lon, w.speed);
}

int main() {
  rover.init();
  rover.print();
  return 0;
}
