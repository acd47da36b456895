// The firmware's AP_Checkpoint (the SITL autopilot's is autopilot/AP_Checkpoint.cpp, over files):
// with symcr, checkpoints of `copter` in a ring of slots in backup RAM, through the device
// profile; without, none. Same class, same scheduler task, same calls from the vehicle.
#include "AP_Checkpoint.hpp"

#include <cstdio>
#include <cstring>

#if SPECIMEN_WITH_SYMCR
#include "backup_ring.hpp"
#endif

AP_Checkpoint checkpointing;

bool AP_Checkpoint::parse_method(const char* name, Method& out) {
  if (std::strcmp(name, "none") == 0) {
    out = Method::None;
  } else if (std::strcmp(name, "symcr") == 0) {
    out = Method::Symcr;
  } else {
    return false;
  }
  return true;
}

bool AP_Checkpoint::symcr_available() { return SPECIMEN_WITH_SYMCR != 0; }

bool AP_Checkpoint::init(Method method, const char* path, std::uint32_t every_loops) {
  (void)path;  // the ring's place is the board's backup RAM
  _method = method;
  _every_loops = every_loops == 0 ? 1 : every_loops;
  if (method == Method::None) return true;
  return method == Method::Symcr && symcr_open();
}

void AP_Checkpoint::save_task() { checkpointing.save(); }

bool AP_Checkpoint::save() {
  if (_method == Method::None || ++_loops < _every_loops) return true;
  _loops = 0;
  return symcr_save();
}

bool AP_Checkpoint::restore() { return _method == Method::Symcr && symcr_restore(); }

#if SPECIMEN_WITH_SYMCR

bool AP_Checkpoint::symcr_open() { return firmware::open_backup_ring(); }

bool AP_Checkpoint::symcr_save() {
  const symcr::device::Result saved = firmware::backup_ring().save(
      symcr::device::program_build(), firmware::record_buffer(), firmware::record_capacity());
  if (saved != symcr::device::Result::Ok) {
    std::printf("checkpoint: not saved: %s\n", symcr::device::result_text(saved));
    return false;
  }
  ++_sequence;
  return true;
}

bool AP_Checkpoint::symcr_restore() {
  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  const symcr::device::Result restored = firmware::backup_ring().restore_latest(
      symcr::device::program_build(), firmware::record_buffer(), firmware::record_capacity(),
      firmware::scratch_buffer(), firmware::scratch_capacity(), &sequence, nullptr, &skipped);
  if (restored != symcr::device::Result::Ok) {
    std::printf("checkpoint: nothing restored: %s\n", symcr::device::result_text(restored));
    return false;
  }
  std::printf("checkpoint: restored #%u (%u newer slot(s) skipped)\n",
              static_cast<unsigned>(sequence), static_cast<unsigned>(skipped));
  return true;
}

#else

bool AP_Checkpoint::symcr_open() { return false; }
bool AP_Checkpoint::symcr_save() { return false; }
bool AP_Checkpoint::symcr_restore() { return false; }

#endif
