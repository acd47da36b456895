// Flight modes that restore cannot create on the heap: one binds references in its constructor,
// one holds a mutex (a tentative walk into it fails, which must not fail generation), one is
// abstract. The pointer is still saved as a reference to a member; generation succeeds with a
// note saying that heap objects behind it would be refused.
#include <mutex>
#include <symcr/symcr.hpp>

struct Copter;
struct Mode {
  virtual ~Mode() {}
  virtual int number() const = 0;
  int entered_ms = 0;
};
struct ModeBound : Mode {
  explicit ModeBound(Copter& copter) : copter(copter) {}
  int number() const override { return 1; }
  Copter& copter;
};
struct ModeLocked : Mode {
  int number() const override { return 2; }
  std::mutex lock;
};
struct ModeAbstractHelper : Mode {
  virtual void helper() = 0;
};

struct Copter {
  ModeBound bound{*this};
  Mode* flightmode = &bound;
};

SYMCR_CHECKPOINT Copter copter;
