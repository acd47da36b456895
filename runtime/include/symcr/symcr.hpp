// symcr: selective, symbolic checkpoint/restore. The whole public C++ API.
//
//   SYMCR_CHECKPOINT Copter copter;                     // a root: saved with all it reaches
//   symcr::checkpoint("copter.ckpt");                   // at a known-good point
//   symcr::Report r = symcr::restore("copter.ckpt");    // in a patched build, by names
//   if (!r.lossless()) fputs(r.losses_to_text().c_str(), stderr);  // failed, or lost data
//
// Builds with -fno-exceptions -fno-rtti. Errors are values (Status, Report), never throws.
#ifndef SYMCR_SYMCR_HPP
#define SYMCR_SYMCR_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

// symcr::Schema (the tables describing a program's checkpointed state, which programs only
// pass around) and symcr_program_schema(), the program's, which the argument-less
// checkpoint()/restore() use.
#include "symcr/generated.h"
#include "symcr/old_values.hpp"

// ---------------------------------------------------------------------------------------------
// Annotations (generator/README.md). For an ordinary compiler they expand to nothing; symcr-gen
// defines SYMCR_GENERATOR and reads them as Clang `annotate` attributes. Place them where a
// GNU attribute goes: `SYMCR_CHECKPOINT Copter copter;`, `int raw SYMCR_SKIP;`,
// `struct SYMCR_SKIP Buffer {...};`, `float yaw SYMCR_RENAMED_FROM("heading");`,
// `uint32_t last_ms SYMCR_TIME(millis);`, `typedef uint32_t time_ms SYMCR_TIME(millis);`,
// `bool armed_once SYMCR_RESTORES_ALONE;` (a state flag that describes only restored state).
// SYMCR_CLOCK(millis) (a clock and its reading function) stands at namespace scope.
#if defined(SYMCR_GENERATOR)
#define SYMCR_CHECKPOINT __attribute__((annotate("symcr::checkpoint")))
#define SYMCR_CHECKPOINT_SHALLOW __attribute__((annotate("symcr::checkpoint_shallow")))
#define SYMCR_INCLUDE __attribute__((annotate("symcr::include")))
#define SYMCR_SKIP __attribute__((annotate("symcr::skip")))
#define SYMCR_RENAMED_FROM(old_name) __attribute__((annotate("symcr::renamed_from:" old_name)))
#define SYMCR_RANGE(lo, hi) __attribute__((annotate("symcr::range:" #lo ":" #hi)))
#define SYMCR_NOT_OWNER __attribute__((annotate("symcr::not_owner")))
#define SYMCR_RESTORES_ALONE __attribute__((annotate("symcr::restores_alone")))
#define SYMCR_TIME(...) __attribute__((annotate("symcr::time:" #__VA_ARGS__)))
#define SYMCR_CLOCK_PRAGMA_(text) _Pragma(#text)
#define SYMCR_CLOCK(...) SYMCR_CLOCK_PRAGMA_(symcr clock(__VA_ARGS__))
#else
#define SYMCR_CHECKPOINT
#define SYMCR_CHECKPOINT_SHALLOW
#define SYMCR_INCLUDE
#define SYMCR_SKIP
#define SYMCR_RENAMED_FROM(old_name)
#define SYMCR_RANGE(lo, hi)
#define SYMCR_NOT_OWNER
#define SYMCR_RESTORES_ALONE
#define SYMCR_TIME(...)
#define SYMCR_CLOCK(...)
#endif

namespace symcr {

// ---------------------------------------------------------------------------------------------
// Errors.
enum class Error : std::uint8_t {
  None = 0,
  NoSchema,         // no generated schema linked into the program
  Io,               // open/read/write/rename failed (message has errno text)
  NotACheckpoint,   // bad magic
  FutureVersion,    // written by a newer format version
  Truncated,        // shorter than its header says
  Checksum,         // checksum mismatch
  Corrupt,          // structurally invalid (bad schema, bad lengths, bad references)
  SchemaUnknown,    // references a schema by hash that is not available
  Incompatible,     // a root cannot be restored at all (e.g. struct <-> int)
  Strict,           // strict mode refused a lossy decision
  Unsupported,      // a state the runtime cannot save (e.g. overlapping heap objects)
  NoValidSlot,      // store: no slot holds a valid checkpoint
  TooLarge,         // checkpoint larger than a store slot or a format limit
  Unauthenticated,  // keys are set and the checkpoint's MAC is missing or does not verify
  // store: every slot holds a checkpoint the crash-loop fallback needs until confirm()
  StoreFull,
  // store, keys set: its newest authenticated checkpoint and journal are older than the store's
  // freshness counter (an older copy of the file, or its newest checkpoints damaged or
  // removed), or the counter is missing, forged or of another store: nothing restored
  RolledBack,
};

const char* error_name(Error error);

// The outcome of an operation that returns no data. Fixed size: no allocation.
class Status {
 public:
  // A message longer than this, less one, is cut and ends in "...".
  static constexpr std::size_t kMessageCapacity = 240;
  Status() = default;
  Status(Error error, const char* format, ...) __attribute__((format(printf, 3, 4)));
  bool ok() const { return error_ == Error::None; }
  Error error() const { return error_; }
  const char* message() const { return message_; }

 private:
  Error error_ = Error::None;
  char message_[kMessageCapacity] = {};
};

// ---------------------------------------------------------------------------------------------
// The restore report (docs/resolution.md): one entry per root and field (by path), plus value-level
// rejections with their concrete paths ("mission.items[3].alt").
enum class Decision : std::uint8_t {
  Restored,   // plain restore
  Kept,       // field or root added: kept the new build's initial value
  Dropped,    // field or root removed: skipped
  Converted,  // converted between types (detail: "int16 -> int32"); also renames, enum remaps
  Rejected,   // could not be restored; kept the new build's value (detail: why)
  Rebased,    // a time of a clock, restored in another process: moved by the clock's advance
};

const char* decision_name(Decision decision);

struct ReportEntry {
  std::string path;  // "copter.mission.items[].lat"; roots are their own names
  Decision decision;
  std::string detail;  // for anything but Restored: what and why
  bool lossy;          // refused in strict mode (data lost or value not restored)
};

// A store slot that restore_latest() passed over: torn or corrupt, unauthenticated, rejected
// by the restore, or suspected by the crash-loop fallback (StoreOptions::fallback_depth).
struct SkippedCheckpoint {
  std::uint32_t slot;
  std::uint64_t sequence;  // 0 when the slot's record could not be read
  std::string reason;
};

namespace detail {
struct ReportAccess;
struct ReportSource;
}  // namespace detail

class Report {
 public:
  // Out of line: the shared entries' control block is the runtime's (built without RTTI), so
  // it is released in the runtime, never in code built with RTTI and -fsanitize=vptr.
  Report() = default;
  ~Report();
  Report(const Report& other);
  Report(Report&& other) noexcept;
  Report& operator=(const Report& other);
  Report& operator=(Report&& other) noexcept;

  // True when the restore was applied. A report can be ok() and still hold Rejected entries
  // in default mode; strict mode turns every lossy entry into a failure.
  bool ok() const { return status_.ok(); }
  // True when the restore was applied and lost nothing: no entry is lossy (no value rejected,
  // no field or root dropped, no array shrunk, no float rounded). Fields this build added
  // (kept) and values handed to a migration hook are not losses.
  bool lossless() const;
  // What a program should print after a restore: the failure, if any, and each lossy entry,
  // then a count ("" when lossless()). Skipped store slots and warnings are in to_text().
  std::string losses_to_text() const;
  const Status& status() const { return status_; }
  // The schema-level entries are written when first asked for, not during the restore.
  const std::vector<ReportEntry>& entries() const;
  std::size_t count(Decision decision) const;
  std::uint64_t sequence() const { return sequence_; }  // of the checkpoint restored
  // Store restores: the slots passed over on the way to the one restored (suspect, rejected,
  // unauthenticated) and those whose record is unusable (torn, corrupt, unknown schema).
  const std::vector<SkippedCheckpoint>& skipped() const { return skipped_; }
  // What the program should know although the restore went through: e.g. a store that cannot
  // record the restore, so the crash-loop fallback is disarmed for it.
  const std::vector<std::string>& warnings() const { return warnings_; }

  std::string to_text() const;  // aligned table, one line per entry, status last
  std::string to_json() const;  // {"ok":..,"error":..,"sequence":..,"entries":[{...}]}

  void clear() { *this = Report(); }

 private:
  friend struct detail::ReportAccess;  // the runtime and symcr's tools fill reports

  Status status_;
  std::vector<ReportEntry> entries_;
  std::shared_ptr<const detail::ReportSource> source_;  // when set: it holds the entries
  std::vector<SkippedCheckpoint> skipped_;
  std::vector<std::string> warnings_;
  std::uint64_t sequence_ = 0;
};

struct RestoreOptions {
  bool strict = false;  // refuse any lossy decision: nothing is written if one exists
  // Restore a checkpoint written by another program (another Schema::program) instead of
  // refusing it (Error::Incompatible): for a program renamed on purpose.
  bool accept_other_program = false;
};

enum class Durability : std::uint8_t {
  PageCache,  // write into the page cache; survives a process crash, not a power cut
  Fdatasync,  // fdatasync after each checkpoint
};

struct CheckpointOptions {
  Durability durability = Durability::PageCache;
};

// Authenticated checkpoints (docs/threat-model.md). After set_checkpoint_keys, every checkpoint
// this process writes (single files, buffers, store slots) carries an HMAC-SHA-256 of its
// header, schema and payload, bound to its store and slot and to its schema's SHA-256, made
// with keys[0] and naming that key's id; every restore refuses (Error::Unauthenticated) a
// checkpoint without a MAC, with a key id not among `keys`, or whose MAC does not verify, and a
// store counts such a slot for nothing. A store also keeps a freshness counter and refuses
// (Error::RolledBack) a store older than it (FreshnessCounter, below). The keys are copied,
// never written anywhere, and wiped once nothing uses them (an open Store keeps the set its last
// operation took). Several keys allow
// rotation: the new one first signs, the old ones still verify. A count of 0 turns
// authentication off. Against an attacker who can write the checkpoint file; the CRC stays for
// accidental damage. Keys may be set, rotated or cleared while other threads checkpoint and
// restore: each save and restore reads one consistent set.
struct CheckpointKey {
  std::uint32_t id;
  const std::uint8_t* bytes;
  std::size_t size;
};
Status set_checkpoint_keys(const CheckpointKey* keys, std::size_t count);

// ---------------------------------------------------------------------------------------------
// Single-file checkpoints: written atomically (exclusive temp file + rename), mode 0600,
// never following symlinks; the schema is inline, so any later build and the CLI can read it.
// The argument-less-schema forms use the program's generated schema.
Status checkpoint(const char* path, const CheckpointOptions& options = {});
Report restore(const char* path, const RestoreOptions& options = {});
Status checkpoint(const Schema& schema, const char* path, const CheckpointOptions& options = {});
Report restore(const Schema& schema, const char* path, const RestoreOptions& options = {});

// In-memory checkpoints (same bytes as a single-file checkpoint), e.g. to send elsewhere.
// `out` keeps its capacity between calls: no allocation after the first of a steady state.
// Its contents are replaced by the checkpoint, written over what it held (large values are
// copied over the previous checkpoint and checksummed in the same pass).
Status checkpoint_to_buffer(const Schema& schema, std::vector<std::uint8_t>& out,
                            std::uint64_t sequence = 0);
Report restore_from_buffer(const Schema& schema, const std::uint8_t* data, std::size_t size,
                           const RestoreOptions& options = {});

// Live update: moves the roots of `from` (one build's schema, loaded in this process, e.g. the
// running module) into the roots of `to` (another build loaded beside it), by the rules, report
// and strict mode of a restore, with no file. All or nothing as a restore is: a refused
// transfer (Incompatible, Strict, an unsavable state) writes nothing into `to`, and `from` is
// only read. Call it where both builds are quiescent (no thread inside either).
// prepare_transfer() resolves the plan beforehand (right after loading `to`), so that the
// transfer itself only encodes and writes; transfer() does it too when it was not done.
Status prepare_transfer(const Schema& from, const Schema& to);
Report transfer(const Schema& from, const Schema& to, const RestoreOptions& options = {});

// ---------------------------------------------------------------------------------------------
// Freshness (docs/threat-model.md). With keys set, a Store keeps the newest freshness value it
// has written (a save's sequence, or a restore journal's) in a counter outside the store file,
// and restore_latest() refuses (Error::RolledBack, nothing written) a store whose newest
// authenticated checkpoint and journal are both older: an older copy of the file, or its
// newest checkpoints damaged or removed. The counter is advanced after every save and every
// journal write. By default it is a small authenticated file (StoreOptions::counter_path);
// a program whose storage an attacker may reset implements this interface over a counter he
// cannot (a TPM NV counter, eMMC RPMB, a microcontroller's backup register), one per store.
class FreshnessCounter {
 public:
  virtual ~FreshnessCounter() = default;
  // The highest value advanced to, 0 when never advanced. A failure means the value cannot be
  // known: a store holding authenticated checkpoints then restores nothing.
  virtual Status read(std::uint64_t& value) = 0;
  // Raises the counter to `value` when it is lower, never lowers it; durable once it returns.
  virtual Status advance(std::uint64_t value) = 0;
};

// The checkpoint store (docs/format.md §4): one preallocated file with a ring of slots.
struct StoreOptions {
  std::uint32_t slots = 4;
  std::uint32_t slot_size = 64 * 1024;  // bytes per slot, header included
  Durability durability = Durability::PageCache;
  // Crash-loop fallback; 0 turns it off. restore_latest() records in the store which checkpoint
  // it restored, and Store::confirm() marks that restore good once the program has run long
  // enough. A start that finds the last restore unconfirmed (the restored state may have
  // crashed the program) passes over that checkpoint and every one saved after it, and
  // restores the newest older one that validates; after `fallback_depth` such fallbacks in a
  // row, it restores nothing (Error::NoValidSlot, the state stays initial) and the program
  // starts afresh. Report::skipped() says which checkpoints were passed over and why.
  //
  // While a restore waits for confirm(), save() never overwrites the restored checkpoint nor the
  // older ones the fallback may still restore (one per fallback the depth still allows); a
  // save that finds no other slot returns Error::StoreFull and writes nothing. With `slots` at
  // least fallback_depth + 2, saves go on before confirm().
  std::uint32_t fallback_depth = 0;
  // A store opened for writing that turns out read-only (a read-only file or file system)
  // cannot record a restore, so the fallback could not notice a crash the restored state
  // causes: restore_latest() then refuses (Error::Io) unless this is set, in which case it
  // restores without the fallback and says so in Report::warnings().
  bool allow_unrecorded_restore = false;
  // Freshness, with keys set (FreshnessCounter): the counter to use, owned by the caller and
  // outliving the Store; when null, an authenticated file at `counter_path`, or when that is
  // null too, at the store's path with ".fresh" appended. Put that file where whoever may
  // write the store cannot (another owner, another partition): with both, an attacker can
  // copy an old store and its old counter back together. open() refuses (Unsupported) a
  // counter_path naming the store file itself, or an existing entry that is not a regular
  // file, and (Io) one whose folder does not exist; an empty counter_path means the default.
  FreshnessCounter* freshness_counter = nullptr;
  const char* counter_path = nullptr;
};

class Store {
 public:
  Store() = default;
  ~Store();
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;
  Store(Store&& other) noexcept;
  Store& operator=(Store&& other) noexcept;

  // Opens `path`, creating and preallocating it if absent. An existing store written by
  // another build keeps its checkpoints (and their schema) until this build saves. An existing
  // store is never reinitialised while it holds a valid checkpoint:
  //   - its own geometry is used for reading; one other than `options` asks for takes effect
  //     at the first save(), which rewrites the store (a new file renamed over it) carrying
  //     its newest checkpoints over;
  //   - a store that cannot be opened for writing (a read-only file or file system) opens
  //     read-only: restore_latest() works, save() returns Error::Io;
  //   - a store whose header is damaged is recovered from its slots: its header is rewritten
  //     when `options`' geometry places every checkpoint found, and otherwise the store opens
  //     restore-only (save() refuses, nothing is written);
  //   - a truncated store keeps the slots still whole (it is extended again for writing).
  static Status open(const char* path, const Schema& schema, const StoreOptions& options,
                     Store& out);
  static Status open(const char* path, const StoreOptions& options, Store& out);  // program's
  // Opens an existing store for restoring only: never creates, locks or writes it, and takes
  // its geometry from the file (or from its slots, when its header is damaged).
  static Status open_readonly(const char* path, const Schema& schema, Store& out);
  static Status open_readonly(const char* path, Store& out);  // program's

  // Saves every root into the oldest slot with one positioned write.
  Status save();
  // Restores the newest slot that validates, falling back past torn or corrupt ones (and,
  // with a fallback_depth, past the checkpoints suspected of a crash loop).
  Report restore_latest(const RestoreOptions& options = {});
  // Crash-loop fallback: the state restored by this start has proven itself (call it after
  // enough good loops, or a time). Cheap when there is nothing to confirm: it writes only
  // after a restore, once. Returns Error::Io if the store could not record it.
  Status confirm();

  bool is_open() const { return fd_ >= 0; }
  // True when save() refuses: opened read-only, or a damaged store recovered for restoring.
  bool read_only() const;
  // False when every slot is empty (a new store): a restore then has nothing to restore. A
  // slot that is torn, corrupt or of an unknown schema counts as holding a checkpoint.
  bool holds_checkpoints() const;
  std::uint64_t last_sequence() const { return last_sequence_; }
  const StoreOptions& options() const { return options_; }  // the geometry in use
  void close();

 private:
  struct Impl;  // and how a store is opened
  int fd_ = -1;
  const Schema* schema_ = nullptr;
  StoreOptions options_;
  std::uint64_t last_sequence_ = 0;
  Impl* impl_ = nullptr;  // buffers and cached plans, allocated on open
};

}  // namespace symcr

#endif  // SYMCR_SYMCR_HPP
