// v0: flight modes created on the heap and held through pointers to their polymorphic base.
// Each is saved as its dynamic class, recognised by its vtable (the programs are built without
// RTTI); a mode of a class restore could not create is refused when saving.
#include <cstring>
#include <vector>

#include "check.hpp"

struct Mode {
  virtual ~Mode() {}
  virtual int number() const = 0;
  unsigned entered_ms = 0;
};
struct ModeAuto : Mode {
  int number() const override { return 3; }
  int next_waypoint = 0;
};
struct ModeLoiter : Mode {
  int number() const override { return 5; }
  float radius_m = 2;
};
// Mode is its second base: a Mode* points into the middle of the object.
struct Telemetry {
  virtual ~Telemetry() {}
  virtual void send() { ++sent; }
  int sent = 0;
};
struct ModeGuided : Telemetry, Mode {
  int number() const override { return 4; }
  double target_alt_m = 0;
};
// Gone in v1: a checkpoint's object of this class cannot be rebuilt there.
struct ModeSport : Mode {
  int number() const override { return 13; }
  float rate_dps = 0;
};
// No default constructor: restore could not create one, so saving refuses it.
struct ModeFlip : Mode {
  explicit ModeFlip(int rolls) : rolls(rolls) {}
  int number() const override { return 14; }
  int rolls;
};

struct Vehicle {
  Mode* current = nullptr;
  Mode* same_as_current = nullptr;
  std::vector<Mode*> history;
  Mode* sport = nullptr;
};

SYMCR_CHECKPOINT Vehicle vehicle;

int main(int argc, char** argv) {
  vehicle.current = new ModeFlip(2);
  std::vector<std::uint8_t> bytes;
  const symcr::Status refused = symcr::checkpoint_to_buffer(*symcr_program_schema(), bytes);
  XV_CHECK(refused.error() == symcr::Error::Unsupported);
  XV_CHECK(std::strstr(refused.message(), "polymorphic class Mode") != nullptr);
  XV_CHECK(std::strstr(refused.message(), "ModeGuided") != nullptr);
  delete vehicle.current;

  ModeAuto* auto_mode = new ModeAuto();
  auto_mode->next_waypoint = 7;
  auto_mode->entered_ms = 100;
  ModeLoiter* loiter = new ModeLoiter();
  loiter->radius_m = 12.5f;
  ModeGuided* guided = new ModeGuided();
  guided->target_alt_m = 42.5;
  guided->sent = 9;
  guided->entered_ms = 200;
  ModeSport* sport = new ModeSport();
  sport->rate_dps = 90;
  vehicle.current = guided;
  vehicle.same_as_current = guided;
  vehicle.history = {auto_mode, loiter, guided, nullptr};
  vehicle.sport = sport;
  const int saved = xv::save(argc, argv);
  delete auto_mode;
  delete loiter;
  delete guided;
  delete sport;
  return xv::failures() ? 1 : saved;
}
