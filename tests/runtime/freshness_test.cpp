// Freshness of authenticated stores (docs/threat-model.md): with keys set, someone who can write
// the store file but holds no key cannot make the program restore an older state than the
// newest it wrote, nor freeze it there, nor switch restores off. Each attack leaves the state
// untouched and is refused (Error::RolledBack, Unauthenticated) or reported.
#include "freshness.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <string>
#include <vector>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "record.hpp"
#include "restore_journal.hpp"
#include "schema_blob.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {
namespace {

const std::vector<std::uint8_t> kKey(32, 0x5a);

// A counter a program would keep in hardware: here in memory, counting its writes.
class MemoryCounter : public symcr::FreshnessCounter {
 public:
  symcr::Status read(std::uint64_t& value) override {
    value = value_;
    return symcr::Status();
  }
  symcr::Status advance(std::uint64_t value) override {
    ++advances;
    if (failing) return symcr::Status(symcr::Error::Io, "the counter's chip is busy");
    if (value > value_) value_ = value;
    return symcr::Status();
  }
  std::uint64_t value_ = 0;
  int advances = 0;
  bool failing = false;  // advance() fails and keeps the value
};

class FreshnessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const symcr::CheckpointKey key{1, kKey.data(), kKey.size()};
    ASSERT_TRUE(symcr::set_checkpoint_keys(&key, 1).ok());
    path = dir.file("fresh.store");
  }
  void TearDown() override { EXPECT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok()); }

  // The program holds only key 1 (the store's, as SetUp sets) or only key 2 (another key
  // holder's).
  static void hold_only_key(std::uint32_t id) {
    static const std::vector<std::uint8_t> kOtherKey(32, 0x33);
    const std::vector<std::uint8_t>& bytes = id == 1 ? kKey : kOtherKey;
    const symcr::CheckpointKey key{id, bytes.data(), bytes.size()};
    ASSERT_TRUE(symcr::set_checkpoint_keys(&key, 1).ok());
  }

  // Saves seeds first..last (one save each) into the store at `at`.
  void save_seeds(int first, int last, const std::string& at = "") {
    symcr::Store store;
    const symcr::Status opened =
        symcr::Store::open((at.empty() ? path : at).c_str(), schema_a, options, store);
    ASSERT_TRUE(opened.ok()) << opened.message();
    for (int seed = first; seed <= last; ++seed) {
      fill_a(seed);
      const symcr::Status saved = store.save();
      ASSERT_TRUE(saved.ok()) << saved.message();
      last_saved = store.last_sequence();
    }
  }
  symcr::Report restore(const std::string& at = "") {
    symcr::Store store;
    const symcr::Status opened =
        symcr::Store::open((at.empty() ? path : at).c_str(), schema_a, options, store);
    EXPECT_TRUE(opened.ok()) << opened.message();
    scramble_a();
    return store.restore_latest();
  }
  static void expect_untouched() {
    EXPECT_EQ(copter_a.ticks, -1);
    EXPECT_EQ(telemetry_a.frames, 0xFFFFFFFFu);
  }
  static void expect_error(const symcr::Report& report, symcr::Error error, const char* why) {
    EXPECT_EQ(report.status().error(), error) << report.status().message();
    EXPECT_NE(std::string(report.status().message()).find(why), std::string::npos)
        << report.status().message();
  }
  // The file offset of the slot holding sequence `sequence`, or 0.
  static std::uint64_t slot_of(const std::vector<std::uint8_t>& bytes, std::uint64_t sequence) {
    const std::uint32_t slots = symcr::format::load32(bytes.data() + 12);
    const std::uint32_t slot_size = symcr::format::load32(bytes.data() + 16);
    const std::uint64_t first = symcr::format::load64(bytes.data() + 24);
    for (std::uint32_t i = 0; i < slots; ++i) {
      const std::uint64_t at = first + std::uint64_t{i} * slot_size;
      if (std::memcmp(bytes.data() + at, "SYMCRCKP", 8) == 0 &&
          symcr::format::load64(bytes.data() + at + 16) == sequence) {
        return at;
      }
    }
    return 0;
  }
  static std::size_t record_size(const std::vector<std::uint8_t>& bytes, std::uint64_t at) {
    return symcr::format::load16(bytes.data() + at + 10) +
           symcr::format::load32(bytes.data() + at + 40) +
           symcr::format::load32(bytes.data() + at + 44);
  }
  static void fix_crc(std::vector<std::uint8_t>& bytes, std::uint64_t at) {
    const std::size_t size = record_size(bytes, at);
    symcr::format::store32(bytes.data() + at + 48, 0);
    symcr::format::store32(bytes.data() + at + 48, symcr::detail::crc32c(bytes.data() + at, size));
  }

  TempDir dir;
  std::string path;
  symcr::StoreOptions options;
  std::uint64_t last_saved = 0;  // the sequence of save_seeds()'s last save
};

TEST_F(FreshnessTest, EachSaveAdvancesTheCounterAndTheNewestRestores) {
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 5);
  EXPECT_EQ(counter.value_, 5u);
  EXPECT_EQ(counter.advances, 5);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 5u);
  expect_a(5);
  // The default counter is a file beside the store; the user's hook was used instead here.
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"fresh.store"});
}

// A save whose counter cannot be advanced has still written a whole checkpoint: its error says
// so, and the checkpoint counts (a counter behind the store is no rollback).
TEST_F(FreshnessTest, ASaveWhoseCounterFailsSaysItsCheckpointWasSavedAndItRestores) {
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 2);
  counter.failing = true;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
    fill_a(3);
    const symcr::Status saved = store.save();
    EXPECT_EQ(saved.error(), symcr::Error::Io);
    EXPECT_NE(std::string(saved.message()).find("checkpoint 3 was saved, but"), std::string::npos)
        << saved.message();
    EXPECT_NE(std::string(saved.message()).find("the counter's chip is busy"), std::string::npos)
        << saved.message();
  }
  EXPECT_EQ(counter.value_, 2u);
  counter.failing = false;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(3);
}

TEST_F(FreshnessTest, AnOlderCopyOfTheStoreFileCopiedBackIsRefused) {
  save_seeds(1, 3);
  const std::vector<std::uint8_t> old_copy = read_file(path);
  save_seeds(4, 6);
  write_file(path, old_copy);
  const symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "newest authenticated checkpoint is sequence 3");
  expect_error(report, symcr::Error::RolledBack, "says 6 was written");
  expect_untouched();
  // Refused with nothing written: the file is still the old copy.
  EXPECT_EQ(read_file(path), old_copy);
}

TEST_F(FreshnessTest, TheNewestSlotDamagedIsRefusedNotFallenBackFrom) {
  save_seeds(1, 4);
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t newest = slot_of(bytes, 4);
  ASSERT_NE(newest, 0u);
  bytes[newest + 130] ^= 1;  // in the payload; the CRC no longer holds
  write_file(path, bytes);
  const symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "newest authenticated checkpoint is sequence 3");
  expect_untouched();
  // The program goes on from its initial state; its next save makes the store fresh again.
  save_seeds(9, 9);
  EXPECT_GT(last_saved, 4u);
  const symcr::Report after = restore();
  ASSERT_TRUE(after.ok()) << after.status().message();
  EXPECT_EQ(after.sequence(), last_saved);
  expect_a(9);
}

// After a start recorded its restore (the journal written last), the newest slot damaged: the
// journal says which checkpoint the store held then, so the fallback to an older one is refused.
TEST_F(FreshnessTest, TheNewestSlotDamagedAfterARecordedRestoreIsRefused) {
  options.fallback_depth = 1;
  save_seeds(1, 4);
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
    ASSERT_TRUE(store.restore_latest().ok());
    ASSERT_TRUE(store.confirm().ok());
  }
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t newest = slot_of(bytes, 4);
  ASSERT_NE(newest, 0u);
  bytes[newest + 130] ^= 1;
  write_file(path, bytes);
  const symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "the journal was written when it held sequence 4");
  expect_untouched();
  EXPECT_EQ(read_file(path), bytes);
}

TEST_F(FreshnessTest, AForgedJournalIsReportedAndNeverDisablesRestores) {
  save_seeds(1, 4);
  std::vector<std::uint8_t> bytes = read_file(path);
  // A journal that gives up on every checkpoint, its CRC right, its seal absent (no key).
  symcr::detail::RestoreJournal forged;
  forged.generation = 9;
  forged.given_up_through = symcr::format::kMaxRecordSequence;
  for (const std::uint64_t copy : symcr::detail::kRestoreJournalOffsets) {
    symcr::detail::encode_restore_journal(forged, bytes.data() + copy);
  }
  write_file(path, bytes);
  options.fallback_depth = 2;
  options.slots = 6;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 4u);
  expect_a(4);
  ASSERT_EQ(report.warnings().size(), 1u);
  EXPECT_NE(report.warnings()[0].find("restore journal was not trusted"), std::string::npos)
      << report.warnings()[0];
  EXPECT_NE(report.warnings()[0].find("carries no MAC"), std::string::npos) << report.warnings()[0];
  // Saves after it number above the real checkpoints, not above the forged journal.
  save_seeds(5, 5);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  EXPECT_LT(store.last_sequence(), 100u);
}

TEST_F(FreshnessTest, AnOlderGenuineJournalPutBackIsRefusedOrNotTrusted) {
  options.fallback_depth = 2;
  options.slots = 6;
  save_seeds(1, 3);
  // A start restores #3 and has not confirmed yet: the journal names it unconfirmed.
  std::vector<std::uint8_t> unconfirmed_page;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
    ASSERT_TRUE(store.restore_latest().ok());
    const std::vector<std::uint8_t> bytes = read_file(path);
    unconfirmed_page.assign(bytes.begin(), bytes.begin() + 4096);
    ASSERT_TRUE(store.confirm().ok());
  }
  // Put back the unconfirmed journal after the confirm: the newest write (the confirm's
  // journal) is missing, so the store is older than the counter.
  std::vector<std::uint8_t> bytes = read_file(path);
  std::copy(unconfirmed_page.begin() + 128, unconfirmed_page.begin() + 400, bytes.begin() + 128);
  write_file(path, bytes);
  symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "freshness counter says");
  expect_untouched();
  EXPECT_EQ(read_file(path), bytes);

  // Saves after the confirm: putting the unconfirmed journal back would blame #3 for a crash
  // and restore #2; the newest checkpoint was saved under a newer journal, so it is not trusted.
  save_seeds(4, 4);  // re-establishes the journal freshness the record carries
  bytes = read_file(path);
  std::copy(unconfirmed_page.begin() + 128, unconfirmed_page.begin() + 400, bytes.begin() + 128);
  write_file(path, bytes);
  report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(4);
  ASSERT_EQ(report.warnings().size(), 1u);
  EXPECT_NE(report.warnings()[0].find("older than the journal the newest checkpoint was saved "
                                      "under"),
            std::string::npos)
      << report.warnings()[0];
}

// A store refused as rolled back becomes fresh with the next save, which is saved under a newer
// journal freshness than the journal in the file (never written without a fallback depth). That
// journal holds nothing, so reading it as empty changes nothing: no warning at every start.
TEST_F(FreshnessTest, AnEmptyJournalOlderThanTheNewestCheckpointIsNoWarning) {
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 3);
  counter.value_ = 10;  // ahead of the store: its newest checkpoints lost
  expect_error(restore(), symcr::Error::RolledBack, "freshness counter says");
  save_seeds(4, 4);
  for (int start = 0; start < 2; ++start) {
    const symcr::Report report = restore();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), last_saved);
    expect_a(4);
    EXPECT_TRUE(report.warnings().empty()) << report.to_text();
  }
}

TEST_F(FreshnessTest, ASlotMovedToAnotherSlotOrAnotherStoreDoesNotVerify) {
  const std::string other = dir.file("other.store");
  save_seeds(1, 2);
  save_seeds(7, 7, other);
  // Another store's newest slot (its CRC intact, its MAC genuine) copied over this one's #2.
  const std::vector<std::uint8_t> theirs = read_file(other);
  std::vector<std::uint8_t> ours = read_file(path);
  const std::uint64_t from = slot_of(theirs, 1), to = slot_of(ours, 2);
  ASSERT_NE(from, 0u);
  ASSERT_NE(to, 0u);
  std::copy(theirs.begin() + from, theirs.begin() + from + record_size(theirs, from),
            ours.begin() + to);
  symcr::format::store64(ours.data() + to + 16, 2);  // not even its sequence changed would help
  fix_crc(ours, to);
  write_file(path, ours);
  symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "newest authenticated checkpoint is sequence 1");
  expect_untouched();
  bool listed = false;
  for (const symcr::SkippedCheckpoint& skipped : report.skipped()) {
    listed |= skipped.reason.find("moved from another slot or store") != std::string::npos;
  }
  EXPECT_TRUE(listed);

  // Within one store: #1 copied over the slot of #2 (same store, another slot).
  save_seeds(3, 3);  // the store is fresh again: this save is the newest
  ours = read_file(path);
  const std::uint64_t one = slot_of(ours, 1), three = slot_of(ours, last_saved);
  ASSERT_NE(one, 0u);
  ASSERT_NE(three, 0u);
  std::copy(ours.begin() + one, ours.begin() + one + record_size(ours, one), ours.begin() + three);
  write_file(path, ours);
  report = restore();
  expect_error(report, symcr::Error::RolledBack,
               ("freshness counter says " + std::to_string(last_saved)).c_str());
  expect_untouched();
}

TEST_F(FreshnessTest, AnUnauthenticatedSlotAtTheTopOfTheSequenceRangeSteersNothing) {
  save_seeds(1, 3);
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t at = slot_of(bytes, 1);
  symcr::format::store64(bytes.data() + at + 16, ~std::uint64_t{0});  // its MAC no longer verifies
  fix_crc(bytes, at);
  write_file(path, bytes);
  save_seeds(4, 6);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  EXPECT_EQ(store.last_sequence(), 6u);
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 6u);
  expect_a(6);
}

TEST_F(FreshnessTest, SequencesNeverWrapEvenFromAnAuthenticSlot) {
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 2);
  // An authentic record at the top of the range (only a key holder could write it).
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t at = slot_of(bytes, 2);
  ASSERT_NE(at, 0u);
  symcr::format::store64(bytes.data() + at + 16, symcr::format::kMaxRecordSequence);
  symcr::detail::KeySnapshot keys = symcr::detail::current_keys();
  symcr::detail::RecordBinding binding;
  symcr::detail::read_store_id(bytes.data(), bytes.size(), binding.store_id);
  binding.location = at;
  const symcr::detail::SchemaBlob& blob = symcr::detail::schema_blob(schema_a);
  symcr::detail::schema_digest(blob.data, blob.size, binding.schema_digest);
  symcr::detail::RecordSigning signing;
  signing.keys = keys.get();
  signing.binding = &binding;
  symcr::detail::reseal_record(bytes.data() + at, record_size(bytes, at), signing);
  write_file(path, bytes);
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
    fill_a(5);
    const symcr::Status saved = store.save();
    EXPECT_EQ(saved.error(), symcr::Error::Corrupt) << saved.message();
    EXPECT_NE(std::string(saved.message()).find("sequence numbers are exhausted"),
              std::string::npos);
    EXPECT_EQ(read_file(path), bytes);  // nothing written
  }
  // A restore that records itself first (the crash-loop fallback) cannot record it either: it
  // is refused, and nothing is written or restored.
  options.fallback_depth = 2;
  {
    const symcr::Report report = restore();
    EXPECT_EQ(report.status().error(), symcr::Error::Corrupt) << report.status().message();
    EXPECT_NE(std::string(report.status().message()).find("sequence numbers are exhausted"),
              std::string::npos);
    expect_untouched();
    EXPECT_EQ(read_file(path), bytes);
  }
  options.fallback_depth = 0;
  // Above the range, a record is damage: without keys it reads as corrupt, never as newest.
  ASSERT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok());
  symcr::format::store64(bytes.data() + at + 16, symcr::format::kMaxRecordSequence + 1);
  fix_crc(bytes, at);
  write_file(path, bytes);
  options.freshness_counter = nullptr;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 1u);
}

TEST_F(FreshnessTest, AMissingForgedOrForeignCounterRestoresNothing) {
  save_seeds(1, 2);
  const std::string counter = path + ".fresh";
  const std::vector<std::uint8_t> genuine = read_file(counter);
  ASSERT_EQ(genuine.size(), 200u);

  ASSERT_EQ(::unlink(counter.c_str()), 0);
  symcr::Report report = restore();
  expect_error(report, symcr::Error::RolledBack, "is missing");
  expect_untouched();

  std::vector<std::uint8_t> forged = genuine;
  symcr::format::store64(forged.data() + 16, 0);  // lowered, its MAC no longer right
  symcr::format::store64(forged.data() + 128 + 16, 0);
  write_file(counter, forged);
  report = restore();
  expect_error(report, symcr::Error::RolledBack, "MAC does not verify");
  expect_untouched();

  // Another store's genuine counter (same key) is not this store's.
  const std::string other = dir.file("other.store");
  save_seeds(1, 1, other);
  write_file(counter, read_file(other + ".fresh"));
  report = restore();
  expect_error(report, symcr::Error::RolledBack, "counter of another store");
  expect_untouched();

  // The genuine counter back: the store restores.
  write_file(counter, genuine);
  report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(2);
}

// A program holding other keys only opens the store: its records do not verify for it, and the
// counter is not its to create or rewrite; the program holding the store's key still restores.
TEST_F(FreshnessTest, AnOpenWithOtherKeysLeavesTheCounterAsItIs) {
  save_seeds(1, 3);
  const std::string counter = path + ".fresh";
  const std::vector<std::uint8_t> genuine = read_file(counter);
  hold_only_key(2);
  {
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open(path.c_str(), schema_a, options, store);
    ASSERT_TRUE(opened.ok()) << opened.message();
  }
  EXPECT_EQ(read_file(counter), genuine);
  hold_only_key(1);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(3);
}

// The same with the crash-loop fallback on, in a store whose journal its own program wrote: the
// restore finds nothing it can verify and restores nothing, so neither the journal nor the
// counter is signed over, and the store's own program trusts its journal still.
TEST_F(FreshnessTest, ARestoreWithOtherKeysAndTheFallbackOnWritesNothing) {
  options.fallback_depth = 2;
  save_seeds(1, 3);
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    ASSERT_TRUE(store.confirm().ok());
  }
  const std::string counter = path + ".fresh";
  const std::vector<std::uint8_t> genuine_counter = read_file(counter);
  const std::vector<std::uint8_t> genuine_store = read_file(path);
  hold_only_key(2);
  for (int start = 0; start < 2; ++start) {
    const symcr::Report report = restore();
    EXPECT_EQ(report.status().error(), symcr::Error::NoValidSlot) << report.status().message();
    expect_untouched();
    EXPECT_EQ(read_file(counter), genuine_counter);
    EXPECT_EQ(read_file(path), genuine_store);
  }
  hold_only_key(1);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  EXPECT_TRUE(report.warnings().empty()) << report.to_text();
  expect_a(3);
}

// Both copies of the store's identity damaged: the checkpoints are bound to it. A program
// holding other keys that opens and restores writes nothing (no new identity over the lost
// one); the store's own program takes the identity back from its counter file, whose MAC vouches
// for it, restores its newest checkpoint and writes both copies again.
// Zeroed copies look like a store no version gave an identity yet: no different.
void damage_both_identity_copies(std::vector<std::uint8_t>& bytes, bool zeroed = false) {
  if (zeroed) {
    std::fill(bytes.begin() + symcr::detail::kStoreIdOffset,
              bytes.begin() + symcr::detail::kStoreIdOffset + symcr::detail::kStoreIdBlockSize, 0);
    return;
  }
  bytes[symcr::detail::kStoreIdOffset + 10] ^= 0xFF;
  bytes[symcr::detail::kStoreIdSecondCopy + 10] ^= 0xFF;
}

class IdentityDamage : public FreshnessTest, public ::testing::WithParamInterface<bool> {};

TEST_P(IdentityDamage, BothIdentityCopiesLostAreTakenBackFromTheCounterFile) {
  save_seeds(1, 3);
  std::vector<std::uint8_t> bytes = read_file(path);
  std::uint8_t genuine_id[symcr::detail::kStoreIdSize];
  ASSERT_TRUE(symcr::detail::read_store_id(bytes.data(), bytes.size(), genuine_id));
  damage_both_identity_copies(bytes, GetParam());
  write_file(path, bytes);
  const std::vector<std::uint8_t> counter = read_file(path + ".fresh");
  {  // a program holding no keys opens it for writing, and saves nothing
    ASSERT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok());
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  }
  EXPECT_EQ(read_file(path), bytes);

  hold_only_key(2);
  for (const std::uint32_t depth : {0u, 2u}) {
    options.fallback_depth = depth;
    const symcr::Report report = restore();
    EXPECT_EQ(report.status().error(), symcr::Error::NoValidSlot) << report.status().message();
    expect_untouched();
    EXPECT_EQ(read_file(path), bytes);
    EXPECT_EQ(read_file(path + ".fresh"), counter);
  }

  hold_only_key(1);
  options.fallback_depth = 0;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(3);
  const std::vector<std::uint8_t> repaired = read_file(path);
  std::uint8_t id[symcr::detail::kStoreIdSize];
  bool both = false;
  ASSERT_TRUE(symcr::detail::read_store_id(repaired.data(), repaired.size(), id, &both));
  EXPECT_TRUE(both);
  EXPECT_EQ(std::memcmp(id, genuine_id, sizeof id), 0);
}

INSTANTIATE_TEST_SUITE_P(DamagedOrZeroed, IdentityDamage, ::testing::Bool());

// A store whose header is damaged too is restored from the checkpoints found by scanning, and
// takes its identity back all the same, opened read-only or not.
TEST_F(FreshnessTest, ASalvagedStoreTakesItsLostIdentityBackFromTheCounterFile) {
  save_seeds(1, 3);
  std::vector<std::uint8_t> bytes = read_file(path);
  damage_both_identity_copies(bytes, false);
  bytes[0] ^= 0xFF;  // the store's magic
  write_file(path, bytes);
  hold_only_key(1);
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open_readonly(path.c_str(), schema_a, store).ok());
    scramble_a();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 3u);
    expect_a(3);
  }
  EXPECT_EQ(read_file(path), bytes);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
}

// Another store's genuine counter (the same key) names another identity: none of this store's
// checkpoints verifies under it, so it is not taken, and nothing is written; with this store's
// counter back (or one copy of it beside the other store's) the identity comes back.
TEST_F(FreshnessTest, AnotherStoresCounterDoesNotLendItsIdentity) {
  save_seeds(1, 3);
  const std::string other = dir.file("other.store");
  save_seeds(1, 5, other);
  std::vector<std::uint8_t> bytes = read_file(path);
  std::uint8_t genuine_id[symcr::detail::kStoreIdSize];
  ASSERT_TRUE(symcr::detail::read_store_id(bytes.data(), bytes.size(), genuine_id));
  damage_both_identity_copies(bytes);
  write_file(path, bytes);
  const std::vector<std::uint8_t> own_counter = read_file(path + ".fresh");
  const std::vector<std::uint8_t> other_counter = read_file(other + ".fresh");
  write_file(path + ".fresh", other_counter);
  const symcr::Report refused = restore();
  EXPECT_FALSE(refused.ok());
  expect_untouched();
  EXPECT_EQ(read_file(path), bytes);

  // The other store's first copy, this store's second.
  std::vector<std::uint8_t> mixed = own_counter;
  std::copy(other_counter.begin(), other_counter.begin() + symcr::format::kCounterCopySize,
            mixed.begin() + symcr::format::kCounterFirstCopyOffset);
  write_file(path + ".fresh", mixed);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(3);
  std::uint8_t id[symcr::detail::kStoreIdSize];
  const std::vector<std::uint8_t> repaired = read_file(path);
  ASSERT_TRUE(symcr::detail::read_store_id(repaired.data(), repaired.size(), id));
  EXPECT_EQ(std::memcmp(id, genuine_id, sizeof id), 0);
}

// With a counter that keeps no identity (the program's own FreshnessCounter), nothing gives the
// lost identity back: its checkpoints no longer verify, so the store is older than its counter
// (RolledBack), and nothing is written until the next save, which gives the store a new
// identity and is restored after it.
TEST_F(FreshnessTest, BothIdentityCopiesDamagedWithoutACounterFileWaitForTheNextSave) {
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 3);
  std::vector<std::uint8_t> bytes = read_file(path);
  damage_both_identity_copies(bytes);
  write_file(path, bytes);
  {
    const symcr::Report report = restore();
    EXPECT_EQ(report.status().error(), symcr::Error::RolledBack) << report.status().message();
    expect_untouched();
    EXPECT_EQ(read_file(path), bytes);
  }
  save_seeds(4, 4);
  const std::vector<std::uint8_t> saved = read_file(path);
  std::uint8_t id[symcr::detail::kStoreIdSize];
  bool both = false;
  ASSERT_TRUE(symcr::detail::read_store_id(saved.data(), saved.size(), id, &both));
  EXPECT_TRUE(both);
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), last_saved);
  expect_a(4);
}

// A counter that exists but cannot be read is a fault to repair, not evidence of an attack:
// Io, naming the file (a missing or untrustworthy one is RolledBack, above). Nothing is
// restored either way, and once the counter reads again the newest checkpoint restores.
TEST_F(FreshnessTest, ACounterThatCannotBeReadIsAnIoErrorAndRestoresNothing) {
  save_seeds(1, 2);
  const std::string counter = path + ".fresh";
  const std::vector<std::uint8_t> genuine = read_file(counter);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  // Replaced by a directory after the store opened: it opens, and reading it fails (EISDIR).
  ASSERT_EQ(::unlink(counter.c_str()), 0);
  ASSERT_EQ(::mkdir(counter.c_str(), 0700), 0);
  scramble_a();
  symcr::Report report = store.restore_latest();
  expect_error(report, symcr::Error::Io, counter.c_str());
  expect_untouched();

  ASSERT_EQ(::rmdir(counter.c_str()), 0);
  write_file(counter, genuine);
  report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(2);
}

TEST_F(FreshnessTest, ACounterPathAwayFromTheStoreIsUsed) {
  const std::string elsewhere = dir.file("counter-elsewhere");
  options.counter_path = elsewhere.c_str();
  save_seeds(1, 2);
  EXPECT_EQ(read_file(elsewhere).size(), 200u);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"counter-elsewhere", "fresh.store"}));
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(2);
}

// A counter path in a folder that does not exist could never be written: every save would
// write its record and then fail, and every restore would find no counter and say the store
// was rolled back. Refused at open instead, naming the folder; the store and its checkpoints
// untouched.
TEST_F(FreshnessTest, ACounterPathInAMissingFolderIsRefusedAtOpen) {
  save_seeds(1, 2);
  const std::vector<std::uint8_t> before = read_file(path);
  const std::string missing = dir.file("no-such-folder");
  const std::string counter = missing + "/copter.fresh";
  options.counter_path = counter.c_str();
  symcr::Store store;
  const symcr::Status opened = symcr::Store::open(path.c_str(), schema_a, options, store);
  EXPECT_EQ(opened.error(), symcr::Error::Io);
  EXPECT_NE(std::string(opened.message()).find("its folder " + missing + " does not exist"),
            std::string::npos)
      << opened.message();
  EXPECT_EQ(read_file(path), before);
  // A file where the folder should be is refused the same way.
  const std::string file_as_folder = dir.file("fresh.store") + "/copter.fresh";
  options.counter_path = file_as_folder.c_str();
  EXPECT_EQ(symcr::Store::open(path.c_str(), schema_a, options, store).error(), symcr::Error::Io);
  // The last good checkpoint is still there, with its counter beside the store.
  options.counter_path = "";
  symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(2);
  // Once the folder exists, the counter path is used.
  ASSERT_EQ(mkdir(missing.c_str(), 0700), 0);
  options.counter_path = counter.c_str();
  save_seeds(3, 3);
  EXPECT_EQ(read_file(counter).size(), 200u);
  report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(3);
}

// A counter path naming the store itself would let the store overwrite its counter (and an
// older copy of the store bring its own): refused at open, the store untouched. So is one
// naming a directory; an empty path means the default, beside the store.
TEST_F(FreshnessTest, ACounterPathNamingTheStoreOrADirectoryIsRefused) {
  save_seeds(1, 2);
  const std::vector<std::uint8_t> before = read_file(path);
  for (const std::string& counter : {path, dir.path()}) {
    options.counter_path = counter.c_str();
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open(path.c_str(), schema_a, options, store);
    EXPECT_EQ(opened.error(), symcr::Error::Unsupported) << counter;
    EXPECT_NE(
        std::string(opened.message()).find(counter == path ? "is the store" : "not a regular"),
        std::string::npos)
        << opened.message();
  }
  EXPECT_EQ(read_file(path), before);
  // A new store whose counter path is its own path: refused, and no file is left behind.
  const std::string fresh = dir.file("new.store");
  options.counter_path = fresh.c_str();
  symcr::Store created;
  EXPECT_EQ(symcr::Store::open(fresh.c_str(), schema_a, options, created).error(),
            symcr::Error::Unsupported);
  options.counter_path = "";
  save_seeds(3, 3);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"fresh.store", "fresh.store.fresh"}));
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(3);
}

TEST_F(FreshnessTest, AHardwareCounterResetBelowTheStoreIsNoRollback) {
  // What the counter protects against is older state; a counter behind the store (a crash
  // between a save and its advance) still restores the newest.
  MemoryCounter counter;
  options.freshness_counter = &counter;
  save_seeds(1, 3);
  counter.value_ = 2;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(3);
  // Ahead of the store (an older store): refused.
  counter.value_ = 4;
  expect_error(restore(), symcr::Error::RolledBack, "says 4 was written");
  expect_untouched();
}

TEST_F(FreshnessTest, ARecordOfAnEarlierMacVersionIsRefused) {
  fill_a(3);
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, bytes).ok());
  symcr::format::store32(bytes.data() + symcr::format::kRecordMacVersionOffset, 0);
  symcr::format::store32(bytes.data() + 48, 0);
  symcr::format::store32(bytes.data() + 48, symcr::detail::crc32c(bytes.data(), bytes.size()));
  scramble_a();
  const symcr::Report report = symcr::restore_from_buffer(schema_a, bytes.data(), bytes.size());
  expect_error(report, symcr::Error::Unauthenticated, "MAC is of version 0");
  expect_untouched();
}

TEST_F(FreshnessTest, ARewriteForANewGeometryKeepsTheStoreAuthenticAndFresh) {
  save_seeds(1, 3);
  options.slots = 6;
  save_seeds(4, 4);  // rewrites the store into 6 slots, its checkpoints moved and signed again
  options.slots = 6;
  const symcr::Report report = restore();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 4u);
  expect_a(4);
  EXPECT_TRUE(report.skipped().empty());
}

}  // namespace
}  // namespace file_tests
