// v1 of enum_aliases: the old names dropped and the values renumbered. A value known by a name
// v1 still has restores whatever the alias order in v0; a value whose v0 names mean different
// values in v1 is ambiguous, so it is rejected, not guessed.
#include "check.hpp"

enum class ModeA { Idle = 10, Hold = 40 };
enum class ModeB { Idle = 10, Hold = 40 };
enum class Split { Off = 0, Brake = 5, Stop = 6 };

struct State {
  ModeA a;
  ModeB b;
  Split split;
};

SYMCR_CHECKPOINT State state;

int main(int argc, char** argv) {
  state.a = ModeA::Idle;
  state.b = ModeB::Idle;
  state.split = Split::Off;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(state.a == ModeA::Hold);
  XV_CHECK(state.b == ModeB::Hold);
  XV_CHECK(xv::restored(report, "state.a") || xv::decided(report, "state.a", symcr::Decision::Converted));
  XV_CHECK(state.split == Split::Off);
  XV_CHECK(xv::decided(report, "state.split", symcr::Decision::Rejected));
  // Said so: v1 has both names, which is not the same as a name v1 lacks.
  bool said = false;
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == "state.split" && e.decision == symcr::Decision::Rejected) {
      said = e.detail.find("aliases name different values in this build") != std::string::npos &&
             e.detail.find("not in this build") == std::string::npos;
      if (!said) std::fprintf(stderr, "state.split: %s\n", e.detail.c_str());
    }
  }
  XV_CHECK(said);
  return xv::verdict();
}
