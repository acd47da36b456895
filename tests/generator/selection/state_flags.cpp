// State flags (boolean and enum members) of classes that leave members out: --report warns
// about each, naming what its class leaves out, unless the flag is declared to restore alone
// (here by the macro and the pragma; state_flags.symcr adds the annotation-file form).
#include <symcr/symcr.hpp>

#include <cstdint>

enum class EkfCore : std::uint8_t { None, Ekf2, Ekf3 };

struct EkfBackend {
  float states[24];
};

struct Ahrs {
  bool ekf3_started = false;                     // says ekf3 exists, which is skipped
  EkfCore active_core = EkfCore::None;           // an enum flag
  bool armed_once SYMCR_RESTORES_ALONE = false;  // silenced by the macro
  bool home_set = false;                         // silenced by the pragma below
  bool fence_ok = false;                         // silenced only by state_flags.symcr
  int counter = 0;                               // not a flag
  EkfBackend ekf3 SYMCR_SKIP;
  EkfBackend* ekf2 = nullptr;                    // skipped by the pragma below
};
#pragma symcr skip(Ahrs::ekf2)
#pragma symcr restores_alone(Ahrs::home_set)

struct Radio {
  int fd = -1;
};

// A shallow root selects plain members only: `radio` is left out, so `link_up` is suspect.
struct Telemetry {
  bool link_up = false;
  Radio radio;
};

// Leaves nothing out: its flag is not suspect.
struct Vehicle {
  Ahrs ahrs;
  bool flying = false;
};

SYMCR_CHECKPOINT Vehicle vehicle;
Telemetry telemetry;
#pragma symcr checkpoint(telemetry, shallow)

int main() { return vehicle.flying ? 1 : 0; }
