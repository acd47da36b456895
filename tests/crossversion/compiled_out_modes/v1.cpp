// v1 of compiled_out_modes: ModeSport is still declared, but compiled out of this build (its
// functions are in a source the build leaves out, as a disabled mode's are), so its vtable does
// not exist. The build links: no generated code names that vtable; ModeSport is not creatable,
// and the pointer to v0's heap ModeSport is rejected, naming the class. Everything else comes
// back, and this build saves.
#include <cstring>
#include <new>
#include <vector>

#include "check.hpp"

struct Mode {
  virtual const char* name() const;
  unsigned entered_ms = 0;
};
struct ModeAuto : Mode {
  const char* name() const override;
  int next_waypoint = 0;
};
struct ModeSport : Mode {
  const char* name() const override;  // defined in no source of this build
  float rate_dps = 0;
};
const char* Mode::name() const { return "MODE"; }
const char* ModeAuto::name() const { return "AUTO"; }

struct Vehicle {
  ModeAuto mode_auto;
  Mode* flightmode = nullptr;
  Mode* planned = nullptr;
  Mode* sport = nullptr;
  int ticks = 0;
};

SYMCR_CHECKPOINT Vehicle vehicle;

template <typename T>
void destroy(T* object) {
  object->~T();
  ::operator delete(object);
}

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.status().ok());
  XV_CHECK(vehicle.ticks == 12);
  XV_CHECK(vehicle.flightmode == &vehicle.mode_auto);
  XV_CHECK(vehicle.mode_auto.next_waypoint == 3);
  Mode* planned = vehicle.planned;
  XV_CHECK(planned != nullptr && std::strcmp(planned->name(), "AUTO") == 0);
  if (planned != nullptr && std::strcmp(planned->name(), "AUTO") == 0) {
    XV_CHECK(static_cast<ModeAuto*>(planned)->next_waypoint == 9);
    XV_CHECK(planned->entered_ms == 40);
  }
  XV_CHECK(vehicle.sport == nullptr);
  XV_CHECK(xv::decided(report, "vehicle.sport", symcr::Decision::Rejected));
  const symcr::ReportEntry* sport = nullptr;
  for (const symcr::ReportEntry& e : report.entries())
    if (e.path == "vehicle.sport" && e.decision == symcr::Decision::Rejected) sport = &e;
  XV_CHECK(sport != nullptr && sport->detail.find("ModeSport") != std::string::npos);

  // This build's own saves work: its heap ModeAuto is of a class it can create.
  std::vector<std::uint8_t> bytes;
  const symcr::Status saved = symcr::checkpoint_to_buffer(*symcr_program_schema(), bytes);
  XV_CHECK(saved.ok());

  if (planned != nullptr && std::strcmp(planned->name(), "AUTO") == 0)
    destroy(static_cast<ModeAuto*>(planned));
  return xv::verdict();
}
