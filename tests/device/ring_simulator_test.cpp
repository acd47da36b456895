// A crash simulator for the device profile's Ring: random, seeded, reproducible sequences of
// saves, resets, resets in the middle of a write or an erase at any byte, and damaged bytes, over
// backup SRAM and NOR flash, checked after every step against a small reference model of the
// ring's guarantees D1-D6 (docs/device.md, "What the ring guarantees").
//
// SYMCR_SIM_SEQUENCES sets how many sequences run (default 10000); SYMCR_SIM_SEED the first
// sequence's seed (sequence i uses seed + i). A failure prints its sequence's seed and steps:
// SYMCR_SIM_SEED=<seed> SYMCR_SIM_SEQUENCES=1 replays it alone.
#include <gtest/gtest.h>

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "schema_tables.hpp"
#include "symcr/device.hpp"

namespace ring_simulator {
namespace {

using symcr::device::Result;
using namespace schema_tables;

// The program's state: a counter and words derived from it, so that a record mixed from two
// saves shows as words that do not belong to the counter.
struct Counter {
  std::int64_t value;
  std::uint32_t words[6];
};
Counter counter;

const FieldInfo kCounterFields[] = {field("value", 0, offsetof(Counter, value)),
                                    field("words", 2, offsetof(Counter, words))};
const TypeInfo kTypes[] = {
    scalar("int64", Kind::Int, 8), scalar("uint32", Kind::UInt, 4),
    array("uint32[6]", 1, 6, 24, 4),
    record("Counter", sizeof(Counter), alignof(Counter), kCounterFields, 2)};
const symcr::RootInfo kRoots[] = {{"counter", 3, &counter, 0, nullptr}};
const symcr::Schema kSchema{kTypes, 4, kRoots, 1, "ring-simulator"};
const symcr::device::Build kBuild{&kSchema, 0x5eed5eed5eed5eedull};

std::uint64_t mix(std::uint64_t z) {  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

void set_counter(std::int64_t value) {
  counter.value = value;
  for (int i = 0; i < 6; ++i) {
    counter.words[i] = static_cast<std::uint32_t>(mix(static_cast<std::uint64_t>(value) * 8 + i));
  }
}

bool counter_consistent() {
  for (int i = 0; i < 6; ++i) {
    if (counter.words[i] !=
        static_cast<std::uint32_t>(mix(static_cast<std::uint64_t>(counter.value) * 8 + i))) {
      return false;
    }
  }
  return true;
}

// Seeded and the same on every platform (std::mt19937's distributions are not).
struct Random {
  std::uint64_t state;
  std::uint64_t next() { return mix(state += 0x9e3779b97f4a7c15ull); }
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
};

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 0) : fallback;
}

// Backup SRAM (erase_unit 1, bytes rewritten in place) or NOR flash (erase sets whole units to
// 0xFF; a write programs bytes in address order and can only clear bits). A power cut can be
// armed to fall after a number of changed bytes: the write or erase under way stops there (the
// bytes before the cut changed, the rest as they were), and everything after it fails until the
// power comes back (a reset). It also records what the ring did during one save.
class FaultyStorage {
 public:
  FaultyStorage(bool flash, std::size_t size, std::size_t unit, std::size_t slot_size,
                Random& random)
      : flash_(flash), unit_(unit), slot_size_(slot_size), bytes_(size) {
    for (std::uint8_t& b : bytes_) b = flash ? 0xFF : static_cast<std::uint8_t>(random.next());
  }

  symcr::device::Storage storage() {
    return {bytes_.size(), flash_ ? unit_ : 1, read, write, flash_ ? erase : nullptr, this};
  }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

  void arm_cut(std::size_t after_bytes) {
    armed_ = true;
    budget_ = after_bytes;
  }
  std::size_t budget() const { return budget_; }
  bool powered_off() const { return off_; }
  void power_on() {
    armed_ = false;
    off_ = false;
  }

  // What one save did to the storage.
  struct Activity {
    std::size_t bytes_changed = 0;  // written or erased, up to a cut
    std::size_t slot = SIZE_MAX;    // the slot of its first write or erase
    std::string misuse;             // a write or an erase the ring must not make (D2)
    std::size_t record_offset = SIZE_MAX;
    std::vector<std::uint8_t> record;  // the bytes of its record write (from the magic on)
  };
  void begin_save() { activity_ = Activity(); }
  const Activity& activity() const { return activity_; }

 private:
  static bool read(void* self, std::size_t offset, void* out, std::size_t n) {
    FaultyStorage& s = *static_cast<FaultyStorage*>(self);
    if (offset > s.bytes_.size() || n > s.bytes_.size() - offset) {
      s.activity_.misuse = "a read outside the storage";
      return false;
    }
    std::memcpy(out, s.bytes_.data() + offset, n);
    return true;
  }

  // Which slot a change touches; every change of one save must lie in one slot.
  bool touch(std::size_t offset, std::size_t n, const char* what) {
    if (n == 0) return true;
    if (offset > bytes_.size() || n > bytes_.size() - offset) {
      activity_.misuse = std::string("a ") + what + " outside the storage";
      return false;
    }
    const std::size_t first = offset / slot_size_, last = (offset + n - 1) / slot_size_;
    if (activity_.slot == SIZE_MAX) activity_.slot = first;
    if (first != activity_.slot || last != activity_.slot) {
      activity_.misuse = std::string("a ") + what + " outside the slot the save writes";
    }
    return true;
  }

  // One byte more may change: false once the power is cut.
  bool spend() {
    if (off_) return false;
    if (armed_) {
      if (budget_ == 0) {
        off_ = true;
        return false;
      }
      --budget_;
    }
    ++activity_.bytes_changed;
    return true;
  }

  static bool write(void* self, std::size_t offset, const void* data, std::size_t n) {
    FaultyStorage& s = *static_cast<FaultyStorage*>(self);
    if (s.off_ || !s.touch(offset, n, "write")) return false;
    const std::uint8_t* in = static_cast<const std::uint8_t*>(data);
    static const char kMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'C', 'K', 'P'};
    if (n >= sizeof kMagic && std::memcmp(in, kMagic, sizeof kMagic) == 0) {
      s.activity_.record_offset = offset;
      s.activity_.record.assign(in, in + n);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!s.spend()) return false;
      std::uint8_t& b = s.bytes_[offset + i];
      if (s.flash_) {
        if ((b & in[i]) != in[i]) s.activity_.misuse = "a write over flash it did not erase";
        b &= in[i];
      } else {
        b = in[i];
      }
    }
    return true;
  }

  static bool erase(void* self, std::size_t offset, std::size_t n) {
    FaultyStorage& s = *static_cast<FaultyStorage*>(self);
    if (s.off_ || !s.touch(offset, n, "erase")) return false;
    if (offset % s.unit_ != 0 || n % s.unit_ != 0) s.activity_.misuse = "an erase of part of a unit";
    for (std::size_t i = 0; i < n; ++i) {
      if (!s.spend()) return false;
      s.bytes_[offset + i] = 0xFF;
    }
    return true;
  }

  bool flash_;
  std::size_t unit_, slot_size_;
  std::vector<std::uint8_t> bytes_;
  bool armed_ = false, off_ = false;
  std::size_t budget_ = 0;
  Activity activity_;
};

// One save as the model knows it, in the order the saves were made.
struct Saved {
  std::int64_t value;
  bool returned_ok;                  // else a reset interrupted it
  std::size_t offset;                // where its record went
  std::vector<std::uint8_t> record;  // empty: the reset came before its record's first byte
};

std::uint64_t sequence_of(const std::vector<std::uint8_t>& record) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | record[16 + i];
  return v;
}

struct Totals {
  std::uint64_t sequences = 0, steps = 0, crash_points = 0, torn_whole = 0, damaged = 0,
                saves_ok = 0, restores = 0;
};

class Sequence {
 public:
  Sequence(std::uint64_t seed, Totals& totals) : seed_(seed), random_{seed}, totals_(totals) {
    record_size_ = symcr::device::record_size(kSchema);
    flash_ = random_.below(2) == 1;
    const std::size_t unit = flash_ ? std::size_t{64} << random_.below(3) : 1;  // 64..256
    slot_size_ = (record_size_ + unit - 1) / unit * unit + unit * random_.below(2);
    if (!flash_) slot_size_ += 8 * random_.below(4);
    slots_ = 2 + random_.below(kMaxSimSlots - 1);  // 2..9: 9 is one more than a ring uses
    const std::size_t tail = random_.below(2) * random_.below(slot_size_);  // not a whole slot
    storage_.reset(new FaultyStorage(flash_, slots_ * slot_size_ + tail, unit, slot_size_, random_));
    buffer_.resize(slot_size_);
    scratch_.resize(symcr::device::scratch_size(kSchema));
    last_save_bytes_ = slot_size_ + record_size_;  // until a whole save measures it
    trace("%s, %zu slots of %zu bytes (unit %zu), %zu bytes in all, record %zu bytes",
          flash_ ? "NOR flash" : "backup SRAM", slots_, slot_size_, unit,
          storage_->bytes().size(), record_size_);
  }

  // Runs the sequence; false (with the failure reported) at the first broken guarantee.
  bool run() {
    if (!open_ring(ring_, "open")) return false;
    if (!check("open")) return false;
    const std::size_t steps = 1 + random_.below(40);
    for (std::size_t step = 0; step < steps; ++step) {
      ++totals_.steps;
      const std::size_t pick = random_.below(100);
      bool ok;
      if (pick < 45) {
        ok = save();
      } else if (pick < 70) {
        ok = save_with_power_cut();
      } else if (pick < 85) {
        trace("reset");
        ok = open_ring(ring_, "reset");
      } else {
        ok = damage();
      }
      if (!ok || !check("the step")) return false;
    }
    return true;
  }

  const std::string& failure() const { return failure_; }

 private:
  static constexpr std::size_t kMaxSimSlots = 9;

  void trace(const char* format, ...) __attribute__((format(printf, 2, 3))) {
    char line[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    trace_ += "  ";
    trace_ += line;
    trace_ += '\n';
  }

  bool fail(const char* format, ...) __attribute__((format(printf, 2, 3))) {
    char line[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    char replay[160];
    std::snprintf(replay, sizeof replay,
                  "\nsequence seed %llu (replay: SYMCR_SIM_SEED=%llu SYMCR_SIM_SEQUENCES=1)\n",
                  static_cast<unsigned long long>(seed_), static_cast<unsigned long long>(seed_));
    failure_ = std::string(line) + replay + "steps:\n" + trace_;
    return false;
  }

  bool open_ring(symcr::device::Ring& ring, const char* when) {
    storage_->power_on();
    const Result r = ring.open(storage_->storage(), slot_size_);
    if (r != Result::Ok) {
      return fail("D3: %s: Ring::open returned %s", when, symcr::device::result_text(r));
    }
    return true;
  }

  bool whole(const Saved& s) const {
    const std::vector<std::uint8_t>& bytes = storage_->bytes();
    return !s.record.empty() && s.offset + s.record.size() <= bytes.size() &&
           std::memcmp(bytes.data() + s.offset, s.record.data(), s.record.size()) == 0;
  }

  // The newest save whose record is whole in storage: what restore_latest must restore.
  const Saved* newest_whole() const {
    for (std::size_t i = saves_.size(); i-- > 0;) {
      if (whole(saves_[i])) return &saves_[i];
    }
    return nullptr;
  }

  std::uint64_t highest_whole_sequence() const {
    std::uint64_t highest = 0;
    for (const Saved& s : saves_) {
      if (whole(s) && sequence_of(s.record) > highest) highest = sequence_of(s.record);
    }
    return highest;
  }

  // What a save did, against D2 and D6; `before`: the highest whole record's sequence then.
  bool check_activity(const char* what, std::uint64_t before) {
    const FaultyStorage::Activity& a = storage_->activity();
    if (!a.misuse.empty()) return fail("D2: %s made %s", what, a.misuse.c_str());
    if (a.record.empty()) return true;
    if (a.record_offset % slot_size_ != 0 || a.record_offset / slot_size_ >= ring_.slot_count()) {
      return fail("D2: %s wrote its record at offset %zu, not at one of the ring's slots", what,
                  a.record_offset);
    }
    if (a.record.size() != record_size_) {
      return fail("D2: %s wrote %zu bytes of record, not %zu", what, a.record.size(),
                  record_size_);
    }
    const std::uint64_t sequence = sequence_of(a.record);
    if (sequence == 0 || sequence == ~std::uint64_t{0} || sequence <= before) {
      return fail("D6: %s wrote sequence %llu with a whole record of sequence %llu in the ring",
                  what, static_cast<unsigned long long>(sequence),
                  static_cast<unsigned long long>(before));
    }
    return true;
  }

  bool save() {
    const std::int64_t value = next_value_++;
    set_counter(value);
    const std::uint64_t before = highest_whole_sequence();
    storage_->begin_save();
    const Result r = ring_.save(kBuild, buffer_.data(), buffer_.size());
    trace("save %lld: %s (slot %zu)", static_cast<long long>(value),
          symcr::device::result_text(r), storage_->activity().slot);
    if (!check_activity("save", before)) return false;
    if (r != Result::Ok) {
      return fail("D3: save %lld returned %s on working storage", static_cast<long long>(value),
                  symcr::device::result_text(r));
    }
    const FaultyStorage::Activity& a = storage_->activity();
    if (a.record.empty()) return fail("D1: save %lld returned Ok without writing a record",
                                      static_cast<long long>(value));
    last_save_bytes_ = a.bytes_changed;
    saves_.push_back(Saved{value, true, a.record_offset, a.record});
    ++totals_.saves_ok;
    return true;
  }

  // A save with the power cut after any byte it writes or erases (the last one included: the
  // reset then comes before save() returns), then the reset.
  bool save_with_power_cut() {
    const std::int64_t value = next_value_++;
    set_counter(value);
    const std::uint64_t before = highest_whole_sequence();
    const std::size_t cut = random_.below(last_save_bytes_ + 1);
    storage_->begin_save();
    storage_->arm_cut(cut);
    const Result r = ring_.save(kBuild, buffer_.data(), buffer_.size());
    const bool crashed = storage_->powered_off() || storage_->budget() == 0;
    const FaultyStorage::Activity& a = storage_->activity();
    trace("save %lld, reset after %zu bytes: %s (slot %zu, %s)", static_cast<long long>(value),
          cut, symcr::device::result_text(r), a.slot,
          crashed ? "torn" : "the save ended first");
    if (!check_activity("a save cut by a reset", before)) return false;
    if (crashed) {
      ++totals_.crash_points;
      saves_.push_back(Saved{value, false, a.record_offset, a.record});
      if (whole(saves_.back())) ++totals_.torn_whole;
    } else {
      if (r != Result::Ok) {
        return fail("D3: save %lld returned %s on working storage", static_cast<long long>(value),
                    symcr::device::result_text(r));
      }
      last_save_bytes_ = a.bytes_changed;
      saves_.push_back(Saved{value, true, a.record_offset, a.record});
      ++totals_.saves_ok;
    }
    return open_ring(ring_, "the reset after the power cut");
  }

  // One byte somewhere in the storage changes for good. A damaged byte never repairs a record
  // (makes a torn or damaged one whole again): such a change is undone and nothing is damaged.
  bool damage() {
    std::vector<std::uint8_t>& bytes = storage_->bytes();
    const std::size_t at = random_.below(bytes.size());
    const std::uint8_t flip = static_cast<std::uint8_t>(1 + random_.below(255));
    std::vector<bool> was_whole;
    for (const Saved& s : saves_) was_whole.push_back(whole(s));
    bytes[at] ^= flip;
    for (std::size_t i = 0; i < saves_.size(); ++i) {
      if (!was_whole[i] && whole(saves_[i])) {
        bytes[at] ^= flip;
        trace("damage at %zu: skipped (it would repair save %lld)", at,
              static_cast<long long>(saves_[i].value));
        return true;
      }
    }
    ++totals_.damaged;
    trace("damage: byte %zu (slot %zu) ^= 0x%02x", at, at / slot_size_, flip);
    return true;
  }

  // The guarantees after a step: on the running ring and on one opened after a reset.
  bool check(const char* after) {
    symcr::device::Ring fresh;
    if (!open_ring(fresh, "a reset for the check")) return false;
    const Saved* expected = newest_whole();
    const std::uint64_t expected_sequence = expected ? sequence_of(expected->record) : 0;
    if (fresh.last_sequence() != expected_sequence) {
      return fail("D6: after %s, a reopened ring's last_sequence() is %llu, the newest whole "
                  "record's is %llu",
                  after, static_cast<unsigned long long>(fresh.last_sequence()),
                  static_cast<unsigned long long>(expected_sequence));
    }
    return check_restore(ring_, "the running ring", after, expected) &&
           check_restore(fresh, "a reopened ring", after, expected);
  }

  bool check_restore(symcr::device::Ring& ring, const char* which, const char* after,
                     const Saved* expected) {
    ++totals_.restores;
    const std::int64_t sentinel = -1 - static_cast<std::int64_t>(totals_.restores % 1000);
    set_counter(sentinel);
    std::uint64_t sequence = 0;
    std::size_t slot = SIZE_MAX, skipped = SIZE_MAX;
    const Result r = ring.restore_latest(kBuild, buffer_.data(), buffer_.size(), scratch_.data(),
                                         scratch_.size(), &sequence, &slot, &skipped);
    if (r != Result::Ok) {
      if (counter.value != sentinel || !counter_consistent()) {
        return fail("D4: after %s, %s's restore_latest returned %s and changed the state",
                    after, which, symcr::device::result_text(r));
      }
      if (expected != nullptr) {
        return fail("D1: after %s, %s's restore_latest returned %s; save %lld (%s) is whole in "
                    "slot %zu",
                    after, which, symcr::device::result_text(r),
                    static_cast<long long>(expected->value),
                    expected->returned_ok ? "returned Ok" : "torn after its last byte",
                    expected->offset / slot_size_);
      }
      if (saves_.empty() && r != Result::Empty) {
        return fail("D5: nothing was ever saved, yet %s's restore_latest returned %s", which,
                    symcr::device::result_text(r));
      }
      return true;
    }
    if (!counter_consistent()) {
      return fail("D4: after %s, %s restored counter %lld with words of another save", after,
                  which, static_cast<long long>(counter.value));
    }
    if (expected == nullptr) {
      return fail("D%d: after %s, %s restored counter %lld; no save's record is whole", 
                  saves_.empty() ? 5 : 2, after, which, static_cast<long long>(counter.value));
    }
    if (counter.value != expected->value) {
      const bool older = counter.value < expected->value;
      return fail("D%d: after %s, %s restored counter %lld (sequence %llu, slot %zu); the newest "
                  "whole record is save %lld's (%s) in slot %zu",
                  older ? 1 : 2, after, which, static_cast<long long>(counter.value),
                  static_cast<unsigned long long>(sequence), slot,
                  static_cast<long long>(expected->value),
                  expected->returned_ok ? "returned Ok" : "torn after its last byte",
                  expected->offset / slot_size_);
    }
    if (sequence != sequence_of(expected->record) || slot != expected->offset / slot_size_) {
      return fail("D1: after %s, %s restored save %lld but reported sequence %llu, slot %zu "
                  "(it is %llu in slot %zu)",
                  after, which, static_cast<long long>(counter.value),
                  static_cast<unsigned long long>(sequence), slot,
                  static_cast<unsigned long long>(sequence_of(expected->record)),
                  expected->offset / slot_size_);
    }
    return true;
  }

  std::uint64_t seed_;
  Random random_;
  Totals& totals_;
  bool flash_ = false;
  std::size_t record_size_ = 0, slot_size_ = 0, slots_ = 0, last_save_bytes_ = 0;
  std::unique_ptr<FaultyStorage> storage_;
  std::vector<std::uint8_t> buffer_, scratch_;
  symcr::device::Ring ring_;
  std::vector<Saved> saves_;
  std::int64_t next_value_ = 1;
  std::string trace_, failure_;
};

TEST(DeviceRingSimulator, RandomSequencesOfSavesResetsTornWritesAndDamageKeepD1ToD6) {
  const std::uint64_t count = env_number("SYMCR_SIM_SEQUENCES", 10000);
  const std::uint64_t first_seed = env_number("SYMCR_SIM_SEED", 1);
  Totals totals;
  for (std::uint64_t i = 0; i < count; ++i) {
    Sequence sequence(first_seed + i, totals);
    ++totals.sequences;
    if (!sequence.run()) {
      ADD_FAILURE() << sequence.failure();
      break;
    }
  }
  std::printf("ring simulator: %llu sequences from seed %llu, %llu steps, %llu crash points "
              "(resets inside a save's writes or erases; %llu left the record whole), %llu "
              "saves returned Ok, %llu damaged bytes, %llu restores checked\n",
              static_cast<unsigned long long>(totals.sequences),
              static_cast<unsigned long long>(first_seed),
              static_cast<unsigned long long>(totals.steps),
              static_cast<unsigned long long>(totals.crash_points),
              static_cast<unsigned long long>(totals.torn_whole),
              static_cast<unsigned long long>(totals.saves_ok),
              static_cast<unsigned long long>(totals.damaged),
              static_cast<unsigned long long>(totals.restores));
  EXPECT_EQ(totals.sequences, count);
  if (count >= 100) {
    EXPECT_GT(totals.crash_points, count);  // the power cuts did fall inside saves
  }
}

}  // namespace
}  // namespace ring_simulator
