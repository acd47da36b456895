#include "AP_Checkpoint.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "Copter.hpp"
#include "messages.hpp"

#if SPECIMEN_WITH_SYMCR || SPECIMEN_WITH_POINTS
#include <symcr/symcr.hpp>
#endif
#if SPECIMEN_WITH_POINTS
#include <symcr/points.h>
#include <symcr/symcr.h>
#endif

AP_Checkpoint checkpointing;

namespace {
// Raw image file: this header, then sizeof(Copter) bytes of the writer build.
struct RawImageHeader {
  char magic[8];
  std::uint32_t size;
  std::uint32_t sequence;
};
constexpr char kRawMagic[8] = {'R', 'A', 'W', 'I', 'M', 'G', '0', '1'};

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

#if SPECIMEN_WITH_SYMCR
symcr::Store g_store;
// The symcr restore's report: rendered as text after the restore was timed (the restore is
// the state written; reading its report is the program's choice, after it).
symcr::Report g_restore_report;
#endif
// What the restore decided, printed after the restore was timed.
std::string g_restore_log;

#if SPECIMEN_WITH_POINTS
// The restore point's outcome, as its hook saw it.
bool g_points_restored = false;
std::uint64_t g_points_sequence = 0;

void on_points_restore(const symcr_point*, symcr_report* report, void*) {
  g_points_restored = symcr_report_ok(report) != 0;
  g_points_sequence = symcr_report_sequence(report);
  // A failure is logged by the runtime; its text is rendered only then, outside the timed path.
}
#endif
}  // namespace

bool AP_Checkpoint::parse_method(const char* name, Method& out) {
  if (std::strcmp(name, "none") == 0 || std::strcmp(name, "baseline") == 0) {
    out = Method::None;
  } else if (std::strcmp(name, "raw-image") == 0) {
    out = Method::RawImage;
  } else if (std::strcmp(name, "symcr") == 0) {
    out = Method::Symcr;
  } else if (std::strcmp(name, "symcr-points") == 0) {
    out = Method::SymcrPoints;
  } else {
    return false;
  }
  return true;
}

bool AP_Checkpoint::symcr_available() { return SPECIMEN_WITH_SYMCR != 0; }

bool AP_Checkpoint::init(Method method, const char* path, std::uint32_t every_loops) {
  _method = method;
  _path = path;
  _every_loops = every_loops == 0 ? 1 : every_loops;
  switch (method) {
    case Method::None:
      return true;
    case Method::RawImage:
      _fd = ::open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0600);
      if (_fd < 0) {
        std::perror(path);
        return false;
      }
      _bytes = static_cast<std::uint32_t>(sizeof(RawImageHeader) + sizeof(Copter));
      return true;
    case Method::Symcr:
      return symcr_open();
    case Method::SymcrPoints:
      return ::setenv("SYMCR_STORE", path, 1) == 0 && points_open();
  }
  return false;
}

void AP_Checkpoint::save_task() {
  AP_Checkpoint& self = checkpointing;
  if (self._loops_until_confirmed != 0 && --self._loops_until_confirmed == 0) self.symcr_confirm();
  if (self._method == Method::None || !copter.armed()) return;
  if (++self._loops % self._every_loops != 0) return;
  self.save();
}

bool AP_Checkpoint::save() {
  const std::uint64_t start = now_ns();
  bool ok = true;
  switch (_method) {
    case Method::None: ok = false; break;
    case Method::RawImage: ok = raw_save(); break;
    case Method::Symcr: ok = symcr_save(); break;
    case Method::SymcrPoints: points_save(), ++_sequence; break;
  }
  const std::uint64_t elapsed = now_ns() - start;
  if (ok && _bytes == 0) measure_bytes();
  if (ok) report(mav::CKPT_SAVED, elapsed);
  return ok;
}

bool AP_Checkpoint::restore() {
  const std::uint64_t start = now_ns();
  bool ok = false;
  switch (_method) {
    case Method::None: ok = false; break;
    case Method::RawImage: ok = raw_restore(); break;
    case Method::Symcr: ok = symcr_restore(); break;
    case Method::SymcrPoints:
      points_restore();
      ok = points_restored();
      break;
  }
  const std::uint64_t elapsed = now_ns() - start;
  if (_method == Method::SymcrPoints && ok) {
    g_restore_log = "symcr-points: restored checkpoint #" + std::to_string(_sequence);
  }
#if SPECIMEN_WITH_SYMCR
  if (_method == Method::Symcr && ok) g_restore_log = g_restore_report.to_text();
#endif
  if (!g_restore_log.empty()) std::fprintf(stderr, "%s\n", g_restore_log.c_str());
  report(ok ? mav::CKPT_RESTORED : mav::CKPT_RESTORE_FAILED, elapsed);
  return ok;
}

void AP_Checkpoint::report(std::uint8_t event, std::uint64_t nanos) {
  mav::SimCheckpoint msg{};
  msg.event = event;
  msg.sequence = _sequence;
  msg.nanos = nanos > 0xFFFFFFFFu ? 0xFFFFFFFFu : static_cast<std::uint32_t>(nanos);
  msg.micros = static_cast<std::uint32_t>(nanos / 1000);
  msg.bytes = _bytes;
  hal.sim.send(mav::make_frame(mav::SIM_CHECKPOINT, msg));
}

// --- raw image -------------------------------------------------------------------------------

bool AP_Checkpoint::raw_save() {
  RawImageHeader header{};
  std::memcpy(header.magic, kRawMagic, sizeof(kRawMagic));
  header.size = static_cast<std::uint32_t>(sizeof(Copter));
  header.sequence = ++_sequence;
  // One positioned write of header and image, into the page cache (as the symcr store does).
  static std::uint8_t buffer[sizeof(RawImageHeader) + sizeof(Copter)];
  std::memcpy(buffer, &header, sizeof(header));
  std::memcpy(buffer + sizeof(header), static_cast<const void*>(&copter), sizeof(Copter));
  return ::pwrite(_fd, buffer, sizeof(buffer), 0) == static_cast<ssize_t>(sizeof(buffer));
}

bool AP_Checkpoint::raw_restore() {
  RawImageHeader header{};
  if (::pread(_fd, &header, sizeof(header), 0) != static_cast<ssize_t>(sizeof(header)) ||
      std::memcmp(header.magic, kRawMagic, sizeof(kRawMagic)) != 0) {
    std::fprintf(stderr, "raw-image: %s holds no image\n", _path);
    return false;
  }
  std::vector<std::uint8_t> image(header.size);
  if (::pread(_fd, image.data(), image.size(), sizeof(header)) !=
      static_cast<ssize_t>(image.size())) {
    std::fprintf(stderr, "raw-image: %s is truncated\n", _path);
    return false;
  }
  // What a whole-memory restore does: the old bytes go back where the object is, whatever
  // the new build's layout. A size mismatch is reported, then the common prefix is copied.
  if (header.size != sizeof(Copter)) {
    char note[128];
    std::snprintf(note, sizeof(note), "raw-image: image of %u bytes, this build's Copter is %zu bytes",
                  header.size, sizeof(Copter));
    g_restore_log = note;  // printed after the restore was timed
  }
  const std::size_t n = header.size < sizeof(Copter) ? header.size : sizeof(Copter);
  std::memcpy(static_cast<void*>(&copter), image.data(), n);
  _sequence = header.sequence;
  return true;
}

// One checkpoint in the store is its record header plus the payload (the schema is shared by
// the store), measured from an in-memory record of the same state. After the first save: the
// measurement runs the checkpoint code over the whole state, which would warm a restore after
// it that a freshly started build does not have warm.
void AP_Checkpoint::measure_bytes() {
#if SPECIMEN_WITH_SYMCR || SPECIMEN_WITH_POINTS
  std::vector<std::uint8_t> record;
  if (symcr_program_schema != nullptr && symcr_program_schema() != nullptr &&
      symcr::checkpoint_to_buffer(*symcr_program_schema(), record).ok() && record.size() >= 48) {
    std::uint32_t header_size = 0, payload_size = 0;
    std::memcpy(&header_size, record.data() + 10, 2);
    std::memcpy(&payload_size, record.data() + 44, 4);
    _bytes = (header_size & 0xFFFFu) + payload_size;
  }
#endif
}

// --- symcr-points ----------------------------------------------------------------------------

// The points of points.symcr are inserted at the exits of these two functions by symcr-gen.
void AP_Checkpoint::points_save() {}
void AP_Checkpoint::points_restore() {}

// As the symcr method opens its store at start-up, before the flight's loops: the points' store
// is opened here, so that the restore point only restores. The hook takes the restore's outcome
// (the runtime then logs only failures, and this build logs the success after timing it).
bool AP_Checkpoint::points_open() {
#if SPECIMEN_WITH_POINTS
  symcr_set_restore_hook(on_points_restore, nullptr);
  if (symcr_points_open_store() != SYMCR_OK) {
    std::fprintf(stderr, "symcr: %s\n", symcr_last_error());
    return false;
  }
#endif
  return true;
}

bool AP_Checkpoint::points_restored() {
#if SPECIMEN_WITH_POINTS
  _sequence = static_cast<std::uint32_t>(g_points_sequence);
  return g_points_restored;
#else
  return false;
#endif
}

// --- symcr -----------------------------------------------------------------------------------

#if SPECIMEN_WITH_SYMCR
bool AP_Checkpoint::symcr_open() {
  symcr::StoreOptions options;
  options.fallback_depth = _fallback_depth;
  const symcr::Status opened = symcr::Store::open(_path, options, g_store);
  if (!opened.ok()) {
    std::fprintf(stderr, "symcr: %s\n", opened.message());
    return false;
  }
  return true;
}

bool AP_Checkpoint::symcr_save() {
  const symcr::Status saved = g_store.save();
  if (!saved.ok()) {
    std::fprintf(stderr, "symcr: save failed: %s\n", saved.message());
    return false;
  }
  _sequence = static_cast<std::uint32_t>(g_store.last_sequence());
  return true;
}

bool AP_Checkpoint::symcr_restore() {
  g_restore_report = g_store.restore_latest();
  if (!g_restore_report.ok()) {
    std::fprintf(stderr, "symcr: restore failed: %s\n", g_restore_report.status().message());
    return false;
  }
  _sequence = static_cast<std::uint32_t>(g_restore_report.sequence());
  if (_fallback_depth != 0) _loops_until_confirmed = _confirm_after;
  return true;
}

// The restored state flew `_confirm_after` loops: the store may trust it again.
void AP_Checkpoint::symcr_confirm() {
  const symcr::Status confirmed = g_store.confirm();
  if (confirmed.ok()) {
    std::fprintf(stderr, "symcr: the restored state flew %u loops: its restore is confirmed\n",
                 static_cast<unsigned>(_confirm_after));
  } else {
    std::fprintf(stderr, "symcr: cannot confirm the restore: %s\n", confirmed.message());
  }
}
#else
bool AP_Checkpoint::symcr_open() {
  std::fprintf(stderr, "symcr: this build has no generated checkpointing code\n");
  return false;
}
bool AP_Checkpoint::symcr_save() { return false; }
bool AP_Checkpoint::symcr_restore() { return false; }
void AP_Checkpoint::symcr_confirm() {}
#endif
