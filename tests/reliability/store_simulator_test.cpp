// The store's crash simulator: random, seeded, reproducible sequences of what a program and
// its environment do to a store — starts (each restoring, some with another geometry or a
// read-only file system), saves, confirm(), a second writer, a damaged byte, and a crash at any
// mutating file call with a write torn at any byte — run by the real Store over an in-memory
// file system (simulated_file_system.hpp), and checked after every step against a small model
// of the guarantees docs/format.md §4 numbers S1–S9. Every other sequence runs with keys set,
// so that the freshness counter (a file beside the store, written through the same file system)
// is crashed and torn too: S9, a restore refuses (RolledBack) exactly when the store is older
// than its counter, and a crash never makes it so.
//
// SYMCR_SIM_SEQUENCES runs more sequences than the suite's default; SYMCR_SIM_SEED replays one
// (a failure prints its seed and steps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "freshness.hpp"
#include "record.hpp"
#include "restore_journal.hpp"
#include "schema_tables.hpp"
#include "simulated_file_system.hpp"
#include "store_layout.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

using namespace schema_tables;

// The program's state: a counter no two saves share, and bytes to give records some size.
struct State {
  std::int64_t counter;
  std::uint8_t pad[300];
};
State state;
enum : std::uint32_t { kI64, kU8, kPad, kState, kTypeCount };
const FieldInfo state_fields[] = {
    field("counter", kI64, offsetof(State, counter)),
    field("pad", kPad, offsetof(State, pad)),
};
const TypeInfo types[] = {
    scalar("int64", Kind::Int, 8),
    scalar("uint8", Kind::UInt, 1),
    array("uint8[300]", kU8, 300, 300, 1),
    record("State", sizeof(State), alignof(State), state_fields, 2),
};
const symcr::RootInfo roots[] = {{"state", kState, &state, 0, nullptr}};
const symcr::Schema schema{types, kTypeCount, roots, 1, "simulated"};

void set_state(std::int64_t counter) {
  state.counter = counter;
  std::memset(state.pad, static_cast<int>(counter & 0xFF), sizeof state.pad);
}
bool state_holds(std::int64_t counter) {
  if (state.counter != counter) return false;
  for (std::uint8_t b : state.pad)
    if (b != static_cast<std::uint8_t>(counter & 0xFF)) return false;
  return true;
}

// What the file holds, read outside the store's code: per intact record (its CRC holds and a
// schema area with its hash is intact), sequence -> counter.
std::map<std::uint64_t, std::int64_t> intact_checkpoints(const std::vector<std::uint8_t>& file,
                                                         std::uint64_t* newest_journal = nullptr) {
  std::map<std::uint64_t, std::int64_t> found;
  symcr::detail::StoreGeometry g;
  if (file.size() < symcr::format::kStoreHeaderSize ||
      !symcr::detail::decode_store_header(file.data(), file.size(), "store", g).ok()) {
    return found;
  }
  std::set<std::uint64_t> area_hashes;
  for (int i = 0; i < 2; ++i) {
    const std::uint64_t at = g.area_offset(i);
    if (at + symcr::format::kStoreAreaHeaderSize > file.size()) continue;
    const std::uint8_t* head = file.data() + at;
    const std::uint32_t size = symcr::format::load32(head + 8);
    if (size == 0 || at + symcr::format::kStoreAreaHeaderSize + size > file.size()) continue;
    const std::uint32_t crc = symcr::detail::crc32c_extend(
        symcr::detail::crc32c(head, 12), head + symcr::format::kStoreAreaHeaderSize, size);
    if (crc == symcr::format::load32(head + 12)) area_hashes.insert(symcr::format::load64(head));
  }
  for (std::uint32_t i = 0; i < g.slot_count; ++i) {
    const std::uint64_t at = g.slot_offset(i);
    if (at >= file.size()) break;
    const std::size_t room = static_cast<std::size_t>(
        std::min<std::uint64_t>(g.slot_size, file.size() - at));
    symcr::detail::RecordView view;
    if (!symcr::detail::parse_record(file.data() + at, room, view).ok()) continue;
    if (area_hashes.count(view.header.schema_hash) == 0 || view.payload_size < 8) continue;
    found[view.header.sequence] = static_cast<std::int64_t>(symcr::format::load64(view.payload));
    if (newest_journal != nullptr && view.header.sequence == found.rbegin()->first) {
      *newest_journal = view.header.journal_freshness;
    }
  }
  return found;
}

// The crash-loop fallback's documented rules (docs/format.md §4), over sequence ranges.
struct Range {
  std::uint64_t low = 0, high = 0;  // high 0: empty
  bool holds(std::uint64_t s) const { return high != 0 && s >= low && s <= high; }
};
struct Model {
  std::uint64_t unconfirmed = 0;
  std::uint32_t fallbacks = 0;
  Range suspect, crashed;
  std::uint64_t given_up_through = 0;
  // What the fallback may still restore while `unconfirmed` waits (S4).
  std::set<std::uint64_t> needed;
  // Saves that returned Ok after a restore that crashed before confirm(): passed over (S2),
  // whether the store still holds them or not.
  std::set<std::uint64_t> abandoned;

  bool excludes(std::uint64_t s) const {
    return s <= given_up_through || suspect.holds(s) || crashed.holds(s);
  }
  std::uint64_t highest() const {
    return std::max({unconfirmed, suspect.high, crashed.high, given_up_through});
  }
  void give_up(std::uint64_t newest) {
    given_up_through = std::max({given_up_through, suspect.high, crashed.high, newest});
    unconfirmed = 0;
    suspect = crashed = Range();
    fallbacks = 0;
    needed.clear();
  }
  bool operator<(const Model& o) const {
    return std::tie(unconfirmed, fallbacks, suspect.low, suspect.high, crashed.low, crashed.high,
                    given_up_through, needed, abandoned) <
           std::tie(o.unconfirmed, o.fallbacks, o.suspect.low, o.suspect.high, o.crashed.low,
                    o.crashed.high, o.given_up_through, o.needed, o.abandoned);
  }
  bool operator==(const Model& o) const { return !(*this < o) && !(o < *this); }
};

struct Counts {
  std::uint64_t sequences = 0, steps = 0, crashes = 0, restores = 0, fallbacks = 0,
                refused_saves = 0, rolled_back = 0;
};

class Simulation {
 public:
  Simulation(std::uint64_t seed, Counts& counts)
      : seed_(seed), random_(seed), fs_("/sim"), installed_(fs_), counts_(counts) {}

  // Runs one sequence; returns an empty string, or what broke and the steps that led there.
  std::string run(int steps) {
    keyed_ = seed_ % 2 == 0;
    static const std::uint8_t key[] = "simulated-key-0123456789";
    const symcr::CheckpointKey keys{3, key, sizeof key - 1};
    if (!symcr::set_checkpoint_keys(&keys, keyed_ ? 1 : 0).ok()) return "cannot set keys";
    depth_ = pick(0, 3);
    options_.slots = static_cast<std::uint32_t>(pick(2, 6));
    options_.slot_size = 4096;
    options_.fallback_depth = static_cast<std::uint32_t>(depth_);
    models_ = {Model()};
    start(/*may_change_geometry=*/false);
    for (int step = 0; step < steps && failure_.empty(); ++step) {
      ++counts_.steps;
      const int what = pick(0, 99);
      if (!running_ || what < 12) {
        restart();
      } else if (what < 72) {
        save();
      } else if (what < 82) {
        confirm();
      } else if (what < 88) {
        if (!read_only_) second_writer();
      } else if (what < 92) {
        // Bit rot, or a torn sector, found by the next start: a running store's view of its
        // slots is its own, and a save relies on it.
        fs_.kill_process();
        store_.reset();
        running_ = false;
        damage();
        start(/*may_change_geometry=*/false);
      } else if (what < 95) {
        log_ << "restore again\n";
        restore(read_only_);  // after a soft fault, say: no sign of a crash
      } else {
        restart();
      }
      if (failure_.empty()) check_invariants();
    }
    store_.reset();
    fs_.kill_process();
    (void)symcr::set_checkpoint_keys(nullptr, 0);
    if (failure_.empty()) return std::string();
    std::ostringstream out;
    out << "seed " << seed_ << " (replay: SYMCR_SIM_SEED=" << seed_
        << " SYMCR_SIM_SEQUENCES=1): " << failure_ << "\nsteps:\n" << log_.str();
    return out.str();
  }

 private:
  int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }

  void fail(const std::string& what) {
    if (failure_.empty()) failure_ = what;
  }
  std::map<std::uint64_t, std::int64_t> on_disk() { return intact_checkpoints(fs_.view(path_)); }

  // Maybe arms a crash for the next operation: before or after one of its next few mutating
  // calls, or in the middle of a write.
  void maybe_plan_crash() {
    if (pick(0, 99) >= 18) return;
    SimulatedFileSystem::CrashPlan plan;
    plan.at = static_cast<std::uint64_t>(pick(1, 8));
    const int how = pick(0, 2);
    plan.torn_bytes = how == 0 ? 0 : how == 1 ? static_cast<std::size_t>(pick(1, 700)) : 1u << 30;
    fs_.plan_crash(plan);
    log_ << "  (crash planned at call +" << plan.at << ", " << plan.torn_bytes << " bytes)\n";
  }
  // True when the operation just run was ended by the planned crash: the process is gone.
  bool crashed_now() {
    fs_.plan_crash(SimulatedFileSystem::CrashPlan());
    if (!fs_.crashed()) return false;
    ++counts_.crashes;
    log_ << "  -> crash\n";
    store_.reset();
    fs_.kill_process();
    running_ = false;
    return true;
  }

  void restart() {
    if (running_) {
      if (pick(0, 1) == 0) {
        log_ << "stop (clean close)\n";
        store_.reset();
      } else {
        log_ << "kill\n";
      }
      fs_.kill_process();
      store_.reset();
      running_ = false;
    }
    start(/*may_change_geometry=*/true);
  }

  // A new process opens the store and restores, as a program does at start-up.
  void start(bool may_change_geometry) {
    fs_.start_process();
    running_ = true;
    restored_here_ = false;
    if (may_change_geometry && pick(0, 9) == 0) {
      options_.slots = static_cast<std::uint32_t>(pick(2, 6));
    }
    const bool read_only = pick(0, 19) == 0;
    read_only_ = read_only;
    fs_.set_read_only(read_only);
    log_ << "start (slots " << options_.slots << ", depth " << depth_
         << (read_only ? ", read-only" : "") << ")\n";
    const std::vector<std::uint8_t> before = fs_.contents(path_);
    maybe_plan_crash();
    store_ = std::make_unique<symcr::Store>();
    const symcr::Status opened = symcr::Store::open(path_.c_str(), schema, options_, *store_);
    if (crashed_now()) return;
    if (!opened.ok()) {
      // Only a read-only file system where no store was initialised yet may refuse the open.
      if (!(read_only && intact_checkpoints(before).empty())) {
        fail(std::string("open failed: ") + opened.message());
      }
      store_.reset();
      fs_.kill_process();
      running_ = false;
      return;
    }
    // S6: whatever earlier crashes left, nothing but the store (and its counter) remains once
    // it is open.
    if (!read_only && fs_.names() != expected_names()) {
      std::string names;
      for (const std::string& n : fs_.names()) names += " " + n;
      fail("S6: files left behind after open:" + names);
      return;
    }
    restore(read_only);
  }

  std::vector<std::string> expected_names() const {
    if (keyed_) return {"copter.store", "copter.store.fresh"};
    return {"copter.store"};
  }

  // S9 (keys set): whether the store is older than its counter, judged from the files alone by
  // the documented rule (docs/format.md §4 "Freshness").
  bool older_than_counter() {
    if (!keyed_) return false;
    const std::vector<std::uint8_t> file = fs_.contents(path_);
    std::uint64_t saved_under = 0;
    const auto disk = intact_checkpoints(file, &saved_under);
    const std::uint64_t newest = disk.empty() ? 0 : disk.rbegin()->first;
    std::uint8_t id[symcr::detail::kStoreIdSize];
    symcr::detail::read_store_id(file.data(), file.size(), id);
    const symcr::detail::KeySnapshot keys = symcr::detail::current_keys();
    symcr::detail::JournalSeal seal;
    seal.keys = keys.get();
    seal.store_id = id;
    symcr::detail::RestoreJournal journal =
        symcr::detail::read_restore_journal(file.data(), file.size(), &seal);
    if (journal.freshness < saved_under) {  // stale: read as empty, at the checkpoint's floor
      journal = symcr::detail::RestoreJournal();
      journal.freshness = saved_under;
    }
    const std::vector<std::uint8_t> counter = fs_.contents(path_ + ".fresh");
    std::uint64_t counted = 0;
    if (!symcr::detail::decode_counter_file(counter.data(), counter.size(), id, *keys, counted)
             .ok()) {
      return newest != 0 || journal.freshness != 0;
    }
    std::vector<std::uint64_t> sequences;
    for (const auto& [sequence, value] : disk) {
      (void)value;
      sequences.push_back(sequence);
    }
    return !symcr::detail::freshness_verdict("store", newest,
                                             symcr::detail::newest_allowed(sequences, journal),
                                             journal, counted)
                .ok();
  }

  void restore(bool read_only) {
    const std::map<std::uint64_t, std::int64_t> disk = on_disk();
    const bool stale = older_than_counter();
    stale_ = stale;
    maybe_plan_crash();
    set_state(-1);
    const symcr::Report report = store_->restore_latest();
    const bool crashed = crashed_now();
    ++counts_.restores;
    if (stale) {
      // S9: refused before anything is written; a save makes the store fresh again.
      log_ << "restore -> " << symcr::error_name(report.status().error()) << " (stale)\n";
      if (!damaged_since_save_) {
        fail("S9: crashes alone (no damage) left the store older than its counter");
      } else if (crashed) {
        fail("S9: a restore of a stale store crashed: it wrote something");
      } else if (report.status().error() != symcr::Error::RolledBack || !state_holds(-1)) {
        fail(std::string("S9: a store older than its counter was not refused: ") +
             (report.ok() ? "restored #" + std::to_string(report.sequence())
                          : report.status().message()));
      }
      ++counts_.rolled_back;
      return;
    }
    if (report.status().error() == symcr::Error::RolledBack) {
      fail(std::string("S9: a fresh store was refused as rolled back: ") +
           report.status().message());
      return;
    }
    // Each candidate model says what this start must do; keep those the store agrees with.
    std::vector<Model> next;
    for (const Model& candidate : models_) {
      Model m = candidate;
      m.needed.clear();
      const bool recording = depth_ > 0 && !read_only;
      if (depth_ > 0 && read_only) {
        // S8: a restore that cannot be recorded is refused, the state untouched.
        if (!crashed && report.status().error() == symcr::Error::Io && state_holds(-1))
          next.push_back(m);
        continue;
      }
      // What the store numbers below: its records and the sequences its journal names.
      const std::uint64_t newest =
          std::max(disk.empty() ? 0 : disk.rbegin()->first, candidate.highest());
      // A restore of this process still unconfirmed stays the one a crash is blamed on.
      const std::uint64_t pending = restored_here_ ? m.unconfirmed : 0;
      bool found_crash = false;
      if (recording && !restored_here_ && m.unconfirmed != 0) {
        found_crash = true;
        for (const std::uint64_t sequence : ok_saves_)
          if (sequence >= m.unconfirmed) m.abandoned.insert(sequence);
        m.suspect.low = m.suspect.high == 0 ? m.unconfirmed : std::min(m.suspect.low, m.unconfirmed);
        m.suspect.high = std::max({m.suspect.high, m.unconfirmed, newest});
        m.unconfirmed = 0;
        if (++m.fallbacks > static_cast<std::uint32_t>(depth_)) m.give_up(newest);
      }
      std::optional<std::uint64_t> expected;
      for (const auto& [sequence, counter] : disk) {
        (void)counter;
        if (!m.excludes(sequence)) expected = sequence;  // ascending: the last is the newest
      }
      if (!expected) {
        if (found_crash) m.give_up(newest);
        if (recording) m.unconfirmed = pending;
      } else if (recording) {
        m.unconfirmed = pending != 0 ? std::min(pending, *expected) : *expected;
        m.needed.insert(m.unconfirmed);
        std::uint64_t below = m.unconfirmed;
        for (std::uint32_t level = m.fallbacks; level < static_cast<std::uint32_t>(depth_);
             ++level) {
          std::optional<std::uint64_t> older;
          for (const auto& [sequence, counter] : disk) {
            (void)counter;
            if (sequence < below && !m.excludes(sequence)) older = sequence;
          }
          if (!older) break;
          m.needed.insert(*older);
          below = *older;
        }
      }
      if (crashed) {
        // The journal's write may or may not have landed: both futures stay possible.
        next.push_back(candidate);
        next.push_back(m);
        continue;
      }
      // S1, S2, S3: the newest checkpoint not passed over, exactly as saved, or nothing.
      const bool agrees =
          expected ? report.ok() && report.sequence() == *expected &&
                         state_holds(disk.at(*expected))
                   : report.status().error() == symcr::Error::NoValidSlot && state_holds(-1);
      if (agrees) next.push_back(m);
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    log_ << "restore -> " << (crashed ? std::string("(crashed)")
                                      : report.ok() ? "#" + std::to_string(report.sequence())
                                                    : symcr::error_name(report.status().error()))
         << "\n";
    if (next.empty()) {
      std::string on_file;
      for (const auto& [sequence, counter] : disk)
        on_file += " #" + std::to_string(sequence) + "=" + std::to_string(counter);
      fail("S1-S3, S8: the restore did not do what the documented rules say (" +
           std::string(report.ok() ? "restored #" + std::to_string(report.sequence())
                                   : report.status().message()) +
           "; intact on disk:" + on_file + ")");
      return;
    }
    if (report.ok() && report.sequence() != 0 && !report.skipped().empty()) ++counts_.fallbacks;
    // A restore recorded by this process is the one its confirm() vouches for.
    if (report.ok() && depth_ > 0 && !read_only) restored_here_ = true;
    models_ = std::move(next);
  }

  void save() {
    const std::int64_t counter = ++counter_;
    set_state(counter);
    log_ << "save " << counter << "\n";
    const auto before = on_disk();
    std::uint64_t floor = before.empty() ? 0 : before.rbegin()->first;
    std::uint64_t journal_floor = UINT64_MAX;
    for (const Model& m : models_) journal_floor = std::min(journal_floor, m.highest());
    floor = std::max(floor, journal_floor);
    maybe_plan_crash();
    const symcr::Status saved = store_->save();
    if (crashed_now()) {
      // A save into a stale store forgets its journal; the crash may have come before or after.
      if (stale_) models_.push_back(Model());
      return;
    }
    if (read_only_) {
      if (saved.error() != symcr::Error::Io) fail("a save into a read-only store did not fail");
      return;
    }
    if (saved.ok()) {
      const std::uint64_t sequence = store_->last_sequence();
      const auto disk = on_disk();
      auto found = disk.find(sequence);
      if (found == disk.end() || found->second != counter) {
        fail("S1: save " + std::to_string(counter) + " returned Ok, but its record is not there");
        return;
      }
      // S5: numbered above everything the store holds and its journal names.
      if (sequence <= floor) {
        fail("S5: save numbered #" + std::to_string(sequence) + ", not above #" +
             std::to_string(floor));
      }
      if (stale_) {
        // S9: the save into a store older than its counter made it fresh again, and forgot the
        // journal it did not trust.
        models_ = {Model()};
        stale_ = false;
      }
      damaged_since_save_ = false;
      damaged_.erase(sequence);
      gone_.erase(sequence);
      for (Model& m : models_) m.abandoned.erase(sequence);  // a number reused for a new save
      ok_saves_.insert(sequence);
      log_ << "  -> #" << sequence << "\n";
    } else if (saved.error() == symcr::Error::StoreFull) {
      ++counts_.refused_saves;
      log_ << "  -> StoreFull\n";
    } else {
      fail(std::string("save failed: ") + saved.message());
    }
  }

  void confirm() {
    log_ << "confirm\n";
    maybe_plan_crash();
    const symcr::Status confirmed = store_->confirm();
    const bool crashed = crashed_now();
    if (!crashed && !confirmed.ok()) {
      fail(std::string("confirm failed: ") + confirmed.message());
      return;
    }
    std::vector<Model> next;
    for (const Model& candidate : models_) {
      Model m = candidate;
      if (restored_here_ && m.unconfirmed != 0) {
        if (m.suspect.high != 0) {
          if (m.crashed.high == 0) {
            m.crashed = m.suspect;
          } else if (m.crashed.high > m.unconfirmed) {
            m.crashed.low = std::min(m.crashed.low, m.suspect.low);
            m.crashed.high = std::max(m.crashed.high, m.suspect.high);
          } else {
            m.given_up_through = std::max(m.given_up_through, m.crashed.high);
            m.crashed = m.suspect;
          }
        }
        m.unconfirmed = 0;
        m.suspect = Range();
        m.fallbacks = 0;
        m.needed.clear();
      }
      if (crashed) next.push_back(candidate);
      next.push_back(m);
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    models_ = std::move(next);
    restored_here_ = false;
  }

  // S7: a second Store opened for writing while the first is open gets Io, changing nothing.
  void second_writer() {
    log_ << "second writer\n";
    const std::vector<std::uint8_t> before = fs_.contents(path_);
    symcr::Store second;
    const symcr::Status opened = symcr::Store::open(path_.c_str(), schema, options_, second);
    if (opened.ok() || opened.error() != symcr::Error::Io) {
      fail("S7: a second writer opened the store");
    } else if (fs_.contents(path_) != before) {
      fail("S7: a refused second writer changed the store");
    }
  }

  // A byte of a slot is damaged from outside: the checkpoint there, if any, is gone. Or a byte
  // of one journal copy, while both hold the current journal: nothing is lost.
  void damage() {
    std::vector<std::uint8_t> file = fs_.contents(path_);
    const std::uint64_t copy0 = symcr::detail::kRestoreJournalOffsets[0];
    const std::uint64_t copy1 = symcr::detail::kRestoreJournalOffsets[1];
    const std::size_t copy_size = symcr::detail::kRestoreJournalCopySize;
    if (pick(0, 2) == 0 && file.size() >= copy1 + copy_size &&
        std::equal(file.begin() + copy0, file.begin() + copy0 + copy_size, file.begin() + copy1)) {
      const std::uint64_t at = (pick(0, 1) == 0 ? copy0 : copy1) +
                               static_cast<std::uint64_t>(pick(0, static_cast<int>(copy_size) - 1));
      file[at] ^= static_cast<std::uint8_t>(1u << pick(0, 7));
      fs_.set_contents(path_, file);
      damaged_since_save_ = true;
      log_ << "damage a journal copy\n";
      return;
    }
    symcr::detail::StoreGeometry g;
    if (!symcr::detail::decode_store_header(file.data(), file.size(), "store", g).ok()) return;
    const std::uint32_t slot = static_cast<std::uint32_t>(pick(0, static_cast<int>(g.slot_count) - 1));
    const std::uint64_t at = g.slot_offset(slot) + static_cast<std::uint64_t>(pick(0, 400));
    if (at >= file.size()) return;
    const auto before = intact_checkpoints(file);
    file[at] ^= static_cast<std::uint8_t>(1u << pick(0, 7));
    fs_.set_contents(path_, file);
    damaged_since_save_ = true;
    const auto after = intact_checkpoints(file);
    for (const auto& [sequence, counter] : before) {
      (void)counter;
      if (after.count(sequence) == 0) damaged_.insert(sequence);
    }
    log_ << "damage slot " << slot << "\n";
  }

  void check_invariants() {
    if (!running_ || models_.empty()) return;
    const auto disk = on_disk();
    // S1: the newest save that returned Ok and that the fallback does not pass over stays
    // restorable until a newer one lands (unless it was damaged): so says one candidate model
    // at least, the true one. Saves after a restore that waits for confirm() are suspect
    // until then (S2), and may make room for each other.
    bool kept = false;
    std::uint64_t lost = 0;
    for (const Model& m : models_) {
      std::uint64_t newest = 0;
      for (const std::uint64_t sequence : ok_saves_)
        if (!m.excludes(sequence) && damaged_.count(sequence) == 0 &&
            gone_.count(sequence) == 0 && m.abandoned.count(sequence) == 0 &&
            (m.unconfirmed == 0 || sequence <= m.unconfirmed))
          newest = sequence;
      bool here = newest == 0 || disk.count(newest) != 0;
      for (const auto& [sequence, counter] : disk) {
        (void)counter;
        here = here || sequence > newest;
      }
      kept = kept || here;
      if (!here) lost = newest;
    }
    if (!kept) fail("S1: the newest Ok save #" + std::to_string(lost) + " is gone");
    // Older saves may make room for newer ones: from now on they are not expected.
    for (const std::uint64_t sequence : ok_saves_)
      if (disk.count(sequence) == 0) gone_.insert(sequence);
    // S4: what the fallback may still restore is kept until confirm() or the next start (what
    // every candidate model says it needs).
    for (const std::uint64_t sequence : models_.front().needed) {
      bool everyone = true;
      for (const Model& m : models_) everyone = everyone && m.needed.count(sequence) != 0;
      if (everyone) {
        if (disk.count(sequence) == 0 && damaged_.count(sequence) == 0) {
          fail("S4: checkpoint #" + std::to_string(sequence) +
               ", which the crash-loop fallback still needs, was overwritten");
        }
      }
    }
    // S6: between operations, nothing but the store (a read-only file system keeps what an
    // earlier crash left until a start can write again).
    if (!read_only_ && fs_.names() != expected_names() && !fs_.names().empty()) {
      std::string names;
      for (const std::string& n : fs_.names()) names += " " + n;
      fail("S6: a file was left behind:" + names);
    }
  }

  const std::uint64_t seed_;
  std::mt19937_64 random_;
  SimulatedFileSystem fs_;
  FileSystemInstalled installed_;
  Counts& counts_;
  const std::string path_ = "/sim/copter.store";
  symcr::StoreOptions options_;
  int depth_ = 0;
  std::unique_ptr<symcr::Store> store_;
  bool running_ = false;
  std::vector<Model> models_;
  bool read_only_ = false;
  bool restored_here_ = false;
  std::int64_t counter_ = 0;
  bool keyed_ = false;
  bool stale_ = false;  // the last restore found the store older than its counter
  // Something was damaged from outside since the last save (a slot, or a journal copy that a
  // torn write of the other may then take with it): the store may be older than its counter.
  bool damaged_since_save_ = false;
  std::set<std::uint64_t> ok_saves_;
  std::set<std::uint64_t> gone_;  // Ok saves overwritten after newer ones landed
  std::set<std::uint64_t> damaged_;
  std::string failure_;
  std::ostringstream log_;
};

std::uint64_t environment_number(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 10) : fallback;
}

TEST(StoreSimulator, RandomSequencesOfStartsSavesConfirmsCrashesAndTornWritesKeepS1ToS8) {
  const std::uint64_t sequences = environment_number("SYMCR_SIM_SEQUENCES", 10000);
  const std::uint64_t first_seed = environment_number("SYMCR_SIM_SEED", 1);
  Counts counts;
  for (std::uint64_t i = 0; i < sequences; ++i) {
    Simulation simulation(first_seed + i, counts);
    const std::string failure = simulation.run(40);
    ++counts.sequences;
    ASSERT_TRUE(failure.empty()) << failure;
  }
  std::printf("store simulator: %" PRIu64 " sequences, %" PRIu64 " steps, %" PRIu64
              " crash points hit (%" PRIu64 " restores checked, %" PRIu64
              " fallback restores, %" PRIu64 " saves refused to keep the fallback's checkpoints, %"
              PRIu64 " restores refused as rolled back)\n",
              counts.sequences, counts.steps, counts.crashes, counts.restores, counts.fallbacks,
              counts.refused_saves, counts.rolled_back);
  EXPECT_GT(counts.crashes, sequences / 4) << "the simulator crashed too rarely to mean much";
  EXPECT_GT(counts.fallbacks, 0u);
  EXPECT_GT(counts.rolled_back, 0u) << "no damaged newest checkpoint met the freshness check";
}

// Single faults the sequences above meet only by chance, each made to happen.
class StoreFaultTest : public ::testing::Test {
 protected:
  SimulatedFileSystem fs{"/sim"};
  FileSystemInstalled installed{fs};
  const std::string path = "/sim/copter.store";
  symcr::StoreOptions options;

  StoreFaultTest() {
    options.slot_size = 4096;
    fs.start_process();
  }
  void restart() {
    fs.kill_process();
    fs.start_process();
  }
  void save_counters(std::int64_t first, std::int64_t last) {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, store).ok());
    for (std::int64_t c = first; c <= last; ++c) {
      set_state(c);
      ASSERT_TRUE(store.save().ok());
    }
  }
};

// S8: with a fallback depth, a store that cannot record the restore does not restore unless
// the program allows it, and then says the fallback is disarmed.
TEST_F(StoreFaultTest, AStoreThatCannotRecordARestoreRefusesItUnlessAllowed) {
  options.fallback_depth = 2;
  save_counters(1, 3);
  restart();
  fs.set_read_only(true);
  const std::vector<std::uint8_t> before = fs.contents(path);
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, store).ok());
    EXPECT_TRUE(store.read_only());
    set_state(-1);
    const symcr::Report refused = store.restore_latest();
    EXPECT_EQ(refused.status().error(), symcr::Error::Io);
    EXPECT_NE(std::string(refused.status().message()).find("crash-loop fallback"),
              std::string::npos)
        << refused.status().message();
    // The way out is named in full, even after the store's reason (a long path would cut it).
    EXPECT_NE(std::string(refused.status().message())
                  .find("StoreOptions::allow_unrecorded_restore restores without the fallback"),
              std::string::npos)
        << refused.status().message();
    EXPECT_TRUE(state_holds(-1));
  }
  options.allow_unrecorded_restore = true;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, store).ok());
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_TRUE(state_holds(3));
    ASSERT_EQ(report.warnings().size(), 1u);
    EXPECT_NE(report.warnings()[0].find("disarmed"), std::string::npos) << report.warnings()[0];
    EXPECT_NE(report.to_text().find("warning: the crash-loop fallback is disarmed"),
              std::string::npos);
  }
  EXPECT_EQ(fs.contents(path), before);
}

// S6: a rewrite for another geometry killed before its rename leaves its new file behind;
// the next open removes it and the store keeps its checkpoints.
TEST_F(StoreFaultTest, ARewriteKilledBeforeItsRenameLeavesNothingAfterTheNextOpen) {
  save_counters(1, 3);
  restart();
  options.slots = 8;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, store).ok());
    // The rewrite's calls: create the file, truncate, allocate, copy the schema area and
    // three slots, write the header, sync, rename: crash just before the rename.
    SimulatedFileSystem::CrashPlan plan;
    plan.at = 10;
    fs.plan_crash(plan);
    set_state(4);
    EXPECT_FALSE(store.save().ok());
    ASSERT_TRUE(fs.crashed());
  }
  ASSERT_EQ(fs.names().size(), 2u) << "the rewrite's file is there";
  restart();
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, store).ok());
  EXPECT_EQ(fs.names(), std::vector<std::string>{"copter.store"});
  set_state(-1);
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_TRUE(state_holds(3));
}

// S7: a second writer whose open() got the store just before the first rewrote it (a new file
// renamed over the path) must not lock the replaced file and save into it.
TEST_F(StoreFaultTest, ASecondWriterThatOpenedTheReplacedFileGetsIo) {
  save_counters(1, 3);
  restart();
  options.slots = 6;  // the first writer rewrites at its first save
  symcr::Store first;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema, options, first).ok());
  struct Turn {
    symcr::Store* first;
    bool saved;
  } turn{&first, false};
  // The second writer's open() has the old file; before it locks it, the first saves (and
  // rewrites the store) and closes its old descriptor.
  fs.before_next_flock(
      [](void* context) {
        auto& t = *static_cast<Turn*>(context);
        set_state(4);
        t.saved = t.first->save().ok();
      },
      &turn);
  symcr::Store second;
  const symcr::Status opened = symcr::Store::open(path.c_str(), schema, options, second);
  ASSERT_TRUE(turn.saved);
  EXPECT_EQ(opened.error(), symcr::Error::Io) << opened.message();
  EXPECT_FALSE(second.is_open());
  set_state(5);
  ASSERT_TRUE(first.save().ok());
  set_state(-1);
  const symcr::Report report = first.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_TRUE(state_holds(5));
}

}  // namespace
}  // namespace reliability
