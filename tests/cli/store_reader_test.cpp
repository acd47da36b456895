// StoreReader (runtime/src/api/store_reader.hpp): a store's slots as restore_latest() sees them,
// read without a Schema and without the store's lock.
#include "store_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fixture_tables.hpp"
#include "freshness.hpp"
#include "symcr/symcr.hpp"

namespace {

using symcr::detail::StoreReader;
using symcr::detail::StoreSlotState;

class StoreReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = std::string(::testing::TempDir()) + "symcr_cli_unit_" + std::to_string(::getpid()) +
            ".store";
    ::unlink(path_.c_str());
  }
  void TearDown() override {
    (void)symcr::set_checkpoint_keys(nullptr, 0);
    ::unlink(path_.c_str());
    ::unlink((path_ + ".fresh").c_str());
  }

  // Saves and restores from here on authenticate with one key (TearDown drops it).
  static void hold_a_key() {
    static const std::uint8_t kKey[32] = {9, 8, 7, 6, 5, 4, 3, 2, 1};
    const symcr::CheckpointKey key{1, kKey, sizeof kKey};
    ASSERT_TRUE(symcr::set_checkpoint_keys(&key, 1).ok());
  }

  // Four slots after `saves` saves; the Store stays open (and locked) while it is read.
  void save(symcr::Store& store, int saves) {
    symcr::StoreOptions options;
    options.slots = 4;
    options.slot_size = 4096;
    options.fallback_depth = kDepth;
    ASSERT_TRUE(symcr::Store::open(path_.c_str(), cli_fixture::schema(), options, store).ok());
    for (int seed = 1; seed <= saves; ++seed) {
      cli_fixture::fill_state(seed);
      ASSERT_TRUE(store.save().ok());
    }
  }

  void flip_byte(long offset) {
    std::FILE* file = std::fopen(path_.c_str(), "r+b");
    ASSERT_NE(file, nullptr);
    std::fseek(file, offset, SEEK_SET);
    const int byte = std::fgetc(file);
    std::fseek(file, offset, SEEK_SET);
    std::fputc(~byte & 0xFF, file);
    std::fclose(file);
  }

  // `starts` starts that restore with the crash-loop fallback and never confirm.
  void restore_unconfirmed(int starts) {
    for (int start = 0; start < starts; ++start) {
      symcr::Store store;
      symcr::StoreOptions options;
      options.fallback_depth = kDepth;
      ASSERT_TRUE(symcr::Store::open(path_.c_str(), cli_fixture::schema(), options, store).ok());
      store.restore_latest();
    }
  }

  static constexpr std::uint32_t kDepth = 2;
  std::string path_;
};

TEST_F(StoreReaderTest, ListsSlotsNewestFirstWhileTheStoreIsOpen) {
  symcr::Store store;
  save(store, 6);  // sequences by slot: 5, 6, 3, 4
  StoreReader reader;
  const symcr::Status status = reader.open(path_.c_str());
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(reader.geometry().slot_count, 4u);
  EXPECT_TRUE(reader.area(0).valid);
  EXPECT_FALSE(reader.area(1).valid);
  EXPECT_EQ(reader.valid_slots_newest_first(), (std::vector<std::uint32_t>{1, 0, 3, 2}));
  EXPECT_EQ(reader.slots()[1].header.sequence, 6u);

  std::vector<std::uint8_t> bytes;
  symcr::detail::RecordView view;
  int area = -1;
  ASSERT_TRUE(reader.read_record(1, bytes, view, area).ok());
  EXPECT_EQ(area, 0);
  EXPECT_EQ(view.header.sequence, 6u);
  EXPECT_GT(view.payload_size, 0u);
}

TEST_F(StoreReaderTest, ClassifiesEmptyAndCorruptSlots) {
  {
    symcr::Store store;
    save(store, 2);
  }
  StoreReader before;
  ASSERT_TRUE(before.open(path_.c_str()).ok());
  const std::uint64_t slot1 = before.geometry().slots_offset + before.geometry().slot_size;
  flip_byte(static_cast<long>(slot1 + 60));

  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_EQ(reader.slots()[0].state, StoreSlotState::Valid);
  EXPECT_EQ(reader.slots()[1].state, StoreSlotState::Corrupt);
  EXPECT_EQ(reader.slots()[1].problem.error(), symcr::Error::Checksum);
  EXPECT_EQ(reader.slots()[2].state, StoreSlotState::Empty);
  EXPECT_EQ(reader.valid_slots_newest_first(), (std::vector<std::uint32_t>{0}));
  std::vector<std::uint8_t> bytes;
  symcr::detail::RecordView view;
  int area = -1;
  EXPECT_EQ(reader.read_record(1, bytes, view, area).error(), symcr::Error::Checksum);
  EXPECT_EQ(reader.read_record(2, bytes, view, area).error(), symcr::Error::NoValidSlot);
  EXPECT_EQ(reader.read_record(9, bytes, view, area).error(), symcr::Error::Io);
}

// A truncated store keeps every slot still whole, for the reader as for a program's restore.
TEST_F(StoreReaderTest, ReadsATruncatedStoreAsAProgramDoes) {
  {
    symcr::Store store;
    save(store, 6);  // sequences by slot: 5, 6, 3, 4
  }
  StoreReader whole;
  ASSERT_TRUE(whole.open(path_.c_str()).ok());
  const symcr::detail::StoreGeometry geometry = whole.geometry();
  const auto newest_restored = [this]() -> std::uint64_t {
    symcr::Store store;
    if (!symcr::Store::open_readonly(path_.c_str(), cli_fixture::schema(), store).ok()) return 0;
    return store.restore_latest().ok() ? store.last_sequence() : 0;
  };

  ASSERT_EQ(::truncate(path_.c_str(), static_cast<off_t>(geometry.file_size() - 1)), 0);
  StoreReader one_byte_short;
  ASSERT_TRUE(one_byte_short.open(path_.c_str()).ok());
  ASSERT_FALSE(one_byte_short.valid_slots_newest_first().empty());
  EXPECT_EQ(one_byte_short.slots()[one_byte_short.valid_slots_newest_first()[0]].header.sequence,
            6u);
  EXPECT_EQ(newest_restored(), 6u);

  // Cut inside slot 1, the newest: slot 0 is what is left to restore.
  ASSERT_EQ(::truncate(path_.c_str(),
                       static_cast<off_t>(geometry.slots_offset + geometry.slot_size + 100)),
            0);
  StoreReader cut;
  ASSERT_TRUE(cut.open(path_.c_str()).ok());
  EXPECT_EQ(cut.slots()[1].state, StoreSlotState::Corrupt);
  EXPECT_EQ(cut.slots()[2].state, StoreSlotState::Empty);
  EXPECT_EQ(cut.valid_slots_newest_first(), (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(newest_restored(), 5u);
}

// A damaged header, magic included: the checkpoints are found by scanning, as a program's open
// finds them, and the reader names the one the program restores.
TEST_F(StoreReaderTest, ReadsAStoreWithADamagedHeaderAsAProgramDoes) {
  {
    symcr::Store store;
    save(store, 6);  // sequences by slot: 5, 6, 3, 4
  }
  const auto newest_restored = [this]() -> std::uint64_t {
    symcr::Store store;
    if (!symcr::Store::open_readonly(path_.c_str(), cli_fixture::schema(), store).ok()) return 0;
    return store.restore_latest().ok() ? store.last_sequence() : 0;
  };
  for (const long offset : {14L, 0L}) {  // slot_count under the header CRC; the magic
    flip_byte(offset);
    StoreReader reader;
    ASSERT_TRUE(reader.open(path_.c_str()).ok()) << "byte " << offset;
    EXPECT_NE(reader.salvaged().find("found by scanning"), std::string::npos);
    EXPECT_EQ(reader.slots().size(), 4u);
    const std::vector<std::uint32_t> valid = reader.valid_slots_newest_first();
    ASSERT_EQ(valid.size(), 4u);
    EXPECT_EQ(reader.slots()[valid[0]].header.sequence, 6u);
    EXPECT_EQ(newest_restored(), 6u);
    flip_byte(offset);  // whole again
  }
}

// With no checkpoint to find, a damaged header is the store's problem.
TEST_F(StoreReaderTest, RefusesADamagedStoreHoldingNoCheckpoint) {
  {
    symcr::Store store;
    save(store, 0);
  }
  flip_byte(14);  // slot_count, under the header CRC
  StoreReader bad_header;
  EXPECT_EQ(bad_header.open(path_.c_str()).error(), symcr::Error::Checksum);

  flip_byte(0);
  StoreReader not_a_store;
  EXPECT_EQ(not_a_store.open(path_.c_str()).error(), symcr::Error::NotACheckpoint);
}

TEST_F(StoreReaderTest, NextStartCountsAnUnconfirmedRestoreAsACrash) {
  {
    symcr::Store store;
    save(store, 6);  // sequences by slot: 5, 6, 3, 4
  }
  restore_unconfirmed(1);  // restored 6, never confirmed
  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_EQ(reader.journal().unconfirmed, 6u);
  EXPECT_EQ(reader.journal().depth, kDepth);
  EXPECT_FALSE(reader.journal().excludes(6));
  EXPECT_EQ(reader.highest_known_sequence(), 6u);
  bool counts_crash = false;
  const symcr::detail::RestoreJournal next = reader.journal_at_next_start(&counts_crash);
  EXPECT_TRUE(counts_crash);
  EXPECT_EQ(next.unconfirmed, 0u);
  EXPECT_EQ(next.suspect_low, 6u);
  EXPECT_EQ(next.suspect_high, 6u);
  EXPECT_EQ(next.fallbacks, 1u);
  EXPECT_TRUE(next.excludes(6));
  EXPECT_FALSE(next.excludes(5));
}

TEST_F(StoreReaderTest, NextStartGivesUpPastTheRecordedDepth) {
  {
    symcr::Store store;
    save(store, 6);
  }
  restore_unconfirmed(3);  // 6, 5, 4 restored in turn; the next start counts a third crash
  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_EQ(reader.journal().unconfirmed, 4u);
  EXPECT_FALSE(reader.journal().excludes(3));
  bool counts_crash = false;
  const symcr::detail::RestoreJournal next = reader.journal_at_next_start(&counts_crash);
  EXPECT_TRUE(counts_crash);
  EXPECT_EQ(next.given_up_through, 6u);
  EXPECT_EQ(next.fallbacks, 0u);
  for (std::uint64_t sequence = 3; sequence <= 6; ++sequence) EXPECT_TRUE(next.excludes(sequence));
}

TEST_F(StoreReaderTest, NextStartOfAJournalWithoutADepthGoesOneLevelDeeper) {
  {
    symcr::Store store;
    save(store, 6);
  }
  // A journal as an earlier version wrote it: a restore unconfirmed, no depth recorded.
  symcr::detail::RestoreJournal journal;
  journal.generation = 1;
  journal.unconfirmed = 6;
  std::uint8_t copy[symcr::detail::kRestoreJournalCopySize];  // the journal and its (empty) seal
  symcr::detail::encode_restore_journal(journal, copy);
  std::FILE* file = std::fopen(path_.c_str(), "r+b");
  ASSERT_NE(file, nullptr);
  std::fseek(file, static_cast<long>(symcr::detail::kRestoreJournalOffsets[1]), SEEK_SET);
  ASSERT_EQ(std::fwrite(copy, 1, sizeof copy, file), sizeof copy);
  std::fclose(file);

  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  ASSERT_EQ(reader.journal().unconfirmed, 6u);
  bool counts_crash = false;
  const symcr::detail::RestoreJournal next = reader.journal_at_next_start(&counts_crash);
  EXPECT_TRUE(counts_crash);
  EXPECT_EQ(next.given_up_through, 0u);
  EXPECT_EQ(next.suspect_high, 6u);
  EXPECT_FALSE(next.excludes(5));
}

// With keys, an older genuine journal put back is not trusted by the reader, as a program's
// open does not trust it: the reader names the slot the program restores.
TEST_F(StoreReaderTest, WithKeysAnOlderJournalPutBackIsNotTrusted) {
  hold_a_key();
  {
    symcr::Store store;
    save(store, 6);  // sequences by slot: 5, 6, 3, 4
  }
  restore_unconfirmed(1);  // restored 6, never confirmed
  std::uint8_t old_page[4096];
  {
    std::FILE* file = std::fopen(path_.c_str(), "rb");
    ASSERT_NE(file, nullptr);
    ASSERT_EQ(std::fread(old_page, 1, sizeof old_page, file), sizeof old_page);
    std::fclose(file);
  }
  {
    // The next start counts the crash, falls back to 5, and saves 7 under the new journal.
    symcr::Store store;
    symcr::StoreOptions options;
    options.fallback_depth = kDepth;
    ASSERT_TRUE(symcr::Store::open(path_.c_str(), cli_fixture::schema(), options, store).ok());
    ASSERT_TRUE(store.restore_latest().ok());
    cli_fixture::fill_state(7);
    ASSERT_TRUE(store.save().ok());
  }
  {
    // The older journal (both copies) put back.
    std::FILE* file = std::fopen(path_.c_str(), "r+b");
    ASSERT_NE(file, nullptr);
    const long from = static_cast<long>(symcr::detail::kRestoreJournalOffsets[0]);
    std::fseek(file, from, SEEK_SET);
    const std::size_t length = static_cast<std::size_t>(symcr::detail::kRestoreJournalOffsets[1]) +
                               symcr::detail::kRestoreJournalCopySize -
                               static_cast<std::size_t>(from);
    ASSERT_EQ(std::fwrite(old_page + from, 1, length, file), length);
    std::fclose(file);
  }
  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_NE(reader.journal_distrust().find("older copy put back"), std::string::npos)
      << reader.journal_distrust();
  EXPECT_EQ(reader.journal().unconfirmed, 0u);
  const symcr::detail::RestoreJournal next = reader.journal_at_next_start();
  const std::vector<std::uint32_t> valid = reader.valid_slots_newest_first();
  ASSERT_FALSE(valid.empty());
  const std::uint64_t newest = reader.slots()[valid[0]].header.sequence;
  EXPECT_FALSE(next.excludes(newest));

  symcr::Store store;
  symcr::StoreOptions options;
  options.fallback_depth = kDepth;
  ASSERT_TRUE(symcr::Store::open(path_.c_str(), cli_fixture::schema(), options, store).ok());
  ASSERT_TRUE(store.restore_latest().ok());
  EXPECT_EQ(store.last_sequence(), newest);
}

// With keys, a store that lost both copies of its identity takes it back from its counter file
// when a checkpoint verifies under it, for the reader as for a program's open.
TEST_F(StoreReaderTest, WithKeysALostIdentityIsTakenBackFromTheCounterFile) {
  hold_a_key();
  {
    symcr::Store store;
    save(store, 6);  // sequences by slot: 5, 6, 3, 4
  }
  std::vector<std::uint8_t> identity;
  {
    StoreReader whole;
    ASSERT_TRUE(whole.open(path_.c_str()).ok());
    identity.assign(whole.store_id(), whole.store_id() + symcr::detail::kStoreIdSize);
  }
  {
    std::FILE* file = std::fopen(path_.c_str(), "r+b");
    ASSERT_NE(file, nullptr);
    const std::vector<std::uint8_t> zeros(symcr::detail::kStoreIdBlockSize, 0);
    std::fseek(file, static_cast<long>(symcr::detail::kStoreIdOffset), SEEK_SET);
    ASSERT_EQ(std::fwrite(zeros.data(), 1, zeros.size(), file), zeros.size());
    std::fclose(file);
  }
  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_EQ(
      std::vector<std::uint8_t>(reader.store_id(), reader.store_id() + symcr::detail::kStoreIdSize),
      identity);
  // Each valid slot verifies under the identity taken back.
  std::vector<std::uint8_t> bytes;
  symcr::detail::RecordView view;
  for (const std::uint32_t slot : reader.valid_slots_newest_first()) {
    int area = -1;
    ASSERT_TRUE(reader.read_record(slot, bytes, view, area).ok());
    EXPECT_TRUE(symcr::detail::check_authentication(symcr::detail::current_keys().get(),
                                                    bytes.data(), view, reader.binding(slot, area))
                    .ok())
        << "slot " << slot;
  }
  // Another counter file (none here) lends no identity.
  StoreReader elsewhere;
  ASSERT_TRUE(elsewhere.open(path_.c_str(), (path_ + ".no-such-counter").c_str()).ok());
  EXPECT_EQ(std::vector<std::uint8_t>(elsewhere.store_id(),
                                      elsewhere.store_id() + symcr::detail::kStoreIdSize),
            std::vector<std::uint8_t>(symcr::detail::kStoreIdSize, 0));

  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open_readonly(path_.c_str(), cli_fixture::schema(), store).ok());
  ASSERT_TRUE(store.restore_latest().ok());
  EXPECT_EQ(store.last_sequence(), 6u);
}

}  // namespace
