// v0: enumerators renamed the usual way, the new name added as an alias of the old value, in
// either declaration order; and an alias whose names part ways in v1.
#include "check.hpp"

enum class ModeA { Idle = 0, Loiter = 3, Hold = 3 };
enum class ModeB { Idle = 0, Hold = 3, Loiter = 3 };
enum class Split { Off = 0, Brake = 1, Stop = 1 };

struct State {
  ModeA a;
  ModeB b;
  Split split;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state.a = ModeA::Hold;
  state.b = ModeB::Hold;
  state.split = Split::Stop;
  return xv::save(argc, argv);
}
