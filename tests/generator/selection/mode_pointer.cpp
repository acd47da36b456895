// A shallow root holding its modes as members, one selected; the current-mode pointer may point
// at any of them (a reference member when unselected).
#include <cstdio>
#include <cstring>
#include <symcr/symcr.hpp>
struct Mode {
  virtual ~Mode() {}
  virtual const char* name() const = 0;
  unsigned entered_ms = 0;
};
struct ModeAuto : Mode { const char* name() const override { return "AUTO"; } int wp_index = 0; };
struct ModeLoiter : Mode { const char* name() const override { return "LOITER"; } float radius = 0; };
struct Vehicle {
  int ticks = 0;
  ModeAuto mode_auto;
  ModeLoiter mode_loiter;
  Mode* flightmode = &mode_auto;
};
Vehicle vehicle;
int main(int argc, char** argv) {
  if (argc > 1 && !std::strcmp(argv[1], "save")) {
    vehicle.ticks = 42;
    vehicle.flightmode = argc > 2 ? static_cast<Mode*>(&vehicle.mode_loiter) : &vehicle.mode_auto;
    std::printf("save: flightmode=%s points at member: %d\n", vehicle.flightmode->name(),
                vehicle.flightmode == &vehicle.mode_loiter || vehicle.flightmode == &vehicle.mode_auto);
    symcr::Status s = symcr::checkpoint("v.ckpt");
    std::printf("checkpoint ok=%d %s: %s\n", s.ok(), symcr::error_name(s.error()), s.message());
  } else {
    symcr::Report r = symcr::restore("v.ckpt");
    std::printf("%s", r.to_text().c_str());
    std::printf("restore: ticks=%d flightmode=%s ==&mode_auto:%d ==&mode_loiter:%d\n", vehicle.ticks,
                vehicle.flightmode->name(), vehicle.flightmode == &vehicle.mode_auto,
                vehicle.flightmode == &vehicle.mode_loiter);
  }
}
