// v0 of a rover that knows nothing of checkpointing: no include, no macro, no call. The
// annotation file v0.symcr selects `rover` and saves it at the exit of Rover::step, every
// third step.
#include <cstdio>
#include <string>
#include <vector>

struct Waypoint {
  double lat;
  double lon;
};

class Rover {
 public:
  void start(const char* name);
  int step();

 private:
  std::string name_;
  int mode_ = 0;
  float heading_ = 0;
  std::vector<Waypoint> route_;
  unsigned steps_ = 0;
};

Rover rover;

void Rover::start(const char* name) {
  name_ = name;
  mode_ = 1;
  for (int i = 0; i < 3; ++i) route_.push_back(Waypoint{10.0 + i, -20.0 - i});
}

int Rover::step() {
  ++steps_;
  heading_ += 1.5f;
  if (steps_ == 5) mode_ = 3;
  if (steps_ % 4 == 0) {
    route_.push_back(Waypoint{50.0 + steps_, 60.0});
    return static_cast<int>(steps_);  // an early return: the exit point is reached here too
  }
  return static_cast<int>(steps_);
}

int main() {
  rover.start("rv-1");
  int done = 0;
  // Ten steps: the point saves after steps 3, 6 and 9; step 10 is never saved.
  for (int i = 0; i < 10; ++i) done = rover.step();
  std::printf("v0 ran %d steps\n", done);
  return 0;
}
