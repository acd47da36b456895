// Periodic checkpoints of the vehicle's critical state and their restoration at start-up.
//
// Methods:
//   none       no checkpoints
//   raw-image  the bytes of the root object (`copter`), as whole-memory checkpointers keep
//              them, restored with memcpy: correct only if the new build's layout is the same
//   symcr      symcr's checkpoint store: saved by schema, restored by source-level names
//              (available when the build ran symcr_add_checkpointing on this target)
//   symcr-points
//              the same store, with no symcr call in the autopilot: the annotation file
//              points.symcr puts a checkpoint at the exit of points_save() and a restore at the
//              exit of points_restore(), the places where the vehicle's state is consistent
//              (after a loop; before the first loop). The store's path reaches symcr through
//              the SYMCR_STORE environment variable; init() opens the store (one call, as the
//              symcr method opens its store there).
//
// Every save and restore is reported to the world as a SIM_CHECKPOINT frame (duration, size),
// so the experiment measures the cost inside the vehicle's loop.
#ifndef AUTOPILOT_AP_CHECKPOINT_HPP
#define AUTOPILOT_AP_CHECKPOINT_HPP

#include <cstdint>

class AP_Checkpoint {
 public:
  enum class Method : std::uint8_t { None, RawImage, Symcr, SymcrPoints };

  static bool parse_method(const char* name, Method& out);
  static bool symcr_available();

  // symcr: the store's crash-loop fallback (0: off), and the loops after a restore that
  // confirm it. Before init().
  void set_crash_loop_fallback(std::uint32_t depth, std::uint32_t confirm_after_loops) {
    _fallback_depth = depth;
    _confirm_after = confirm_after_loops == 0 ? 1 : confirm_after_loops;
  }
  // Opens (creating if needed) the checkpoint file. False with a message on stderr.
  bool init(Method method, const char* path, std::uint32_t every_loops);
  // Restores the latest checkpoint into `copter`. False (and `copter` untouched for symcr)
  // when nothing valid could be restored.
  bool restore();
  // Scheduler task: saves when due.
  static void save_task();

 private:
  bool save();
  void measure_bytes();
  bool raw_save();
  bool raw_restore();
  bool symcr_open();
  bool symcr_save();
  bool symcr_restore();
  void symcr_confirm();
  static bool points_open();
  bool points_restored();
  static void points_save();
  static void points_restore();
  void report(std::uint8_t event, std::uint64_t nanos);

  Method _method = Method::None;
  const char* _path = nullptr;
  std::uint32_t _every_loops = 10;
  std::uint32_t _loops = 0;
  std::uint32_t _sequence = 0;
  std::uint32_t _bytes = 0;
  std::uint32_t _fallback_depth = 0;
  std::uint32_t _confirm_after = 1;
  std::uint32_t _loops_until_confirmed = 0;  // after a restore, with a fallback depth
  int _fd = -1;
};

extern AP_Checkpoint checkpointing;

#endif  // AUTOPILOT_AP_CHECKPOINT_HPP
