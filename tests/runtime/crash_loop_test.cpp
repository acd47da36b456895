// The store's crash-loop fallback (StoreOptions::fallback_depth, Store::confirm; docs/format.md
// §4 "Restore journal"): a start whose restore was never confirmed makes the next start pass
// over that checkpoint and the ones saved after it, down to the configured depth, then give up
// and leave the state initial. A "start" is a Store opened on the file; a crash is a Store
// closed (or a process ended) without confirm(), which is all the store can see of one.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "crc32c.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "freshness.hpp"
#include "restore_journal.hpp"
#include "store_fixture.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {
namespace {

using symcr::Error;
using symcr::detail::RestoreJournal;

std::vector<std::uint64_t> skipped_sequences(const symcr::Report& report) {
  std::vector<std::uint64_t> sequences;
  for (const symcr::SkippedCheckpoint& skipped : report.skipped()) {
    sequences.push_back(skipped.sequence);
  }
  return sequences;
}

class CrashLoopTest : public StoreFixture {
 protected:
  CrashLoopTest() { options.fallback_depth = 2; }

  // One start that restores (the live state scrambled first) and ends without confirming.
  symcr::Report start_and_crash() {
    symcr::Store store;
    open(store);
    scramble_a();
    return store.restore_latest();
  }
  // One start that restores and confirms.
  symcr::Report start_and_confirm() {
    symcr::Store store;
    open(store);
    scramble_a();
    symcr::Report report = store.restore_latest();
    const symcr::Status confirmed = store.confirm();
    EXPECT_TRUE(confirmed.ok()) << confirmed.message();
    return report;
  }
  RestoreJournal journal() const {
    const std::vector<std::uint8_t> bytes = read_file(path);
    return symcr::detail::read_restore_journal(bytes.data(), bytes.size());
  }
  // Where the file's current journal copy starts.
  std::size_t journal_offset() const {
    return symcr::detail::kRestoreJournalOffsets[journal().generation % 2];
  }
};

TEST_F(CrashLoopTest, WithoutADepthNothingIsRecordedAndTheNewestIsAlwaysRestored) {
  options.fallback_depth = 0;
  save_seeds(1, 4);
  for (int start = 0; start < 3; ++start) {
    const symcr::Report report = start_and_crash();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 4u);
    EXPECT_TRUE(report.skipped().empty());
  }
  // Nothing past the header but the store's identity (two copies).
  const std::vector<std::uint8_t> bytes = read_file(path);
  for (std::size_t i = 36; i < 4096; ++i) {
    if (i >= symcr::detail::kStoreIdOffset && i < symcr::detail::kStoreHeaderPageRead) continue;
    ASSERT_EQ(bytes[i], 0) << "header page byte " << i;
  }
}

TEST_F(CrashLoopTest, ACrashAfterARestoreMakesTheNextStartRestoreTheOlderCheckpoint) {
  save_seeds(1, 4);
  const symcr::Report first = start_and_crash();
  ASSERT_TRUE(first.ok()) << first.status().message();
  EXPECT_EQ(first.sequence(), 4u);
  expect_a(4);
  EXPECT_EQ(journal().unconfirmed, 4u);

  const symcr::Report second = start_and_crash();
  ASSERT_TRUE(second.ok()) << second.status().message();
  EXPECT_EQ(second.sequence(), 3u);
  expect_a(3);
  ASSERT_EQ(second.skipped().size(), 1u);
  EXPECT_EQ(second.skipped()[0].sequence, 4u);
  EXPECT_NE(second.skipped()[0].reason.find("Store::confirm()"), std::string::npos)
      << second.skipped()[0].reason;
  // The report's renderings say it too.
  EXPECT_NE(second.to_text().find("skipped slot"), std::string::npos) << second.to_text();
  EXPECT_NE(second.to_json().find("\"skipped\":[{\"slot\":"), std::string::npos)
      << second.to_json();
  const RestoreJournal after = journal();
  EXPECT_EQ(after.unconfirmed, 3u);
  EXPECT_EQ(after.suspect_low, 4u);
  EXPECT_EQ(after.suspect_high, 4u);
  EXPECT_EQ(after.fallbacks, 1u);
}

TEST_F(CrashLoopTest, AProcessKilledAfterItsRestoreIsSeenByTheNextStart) {
  save_seeds(1, 3);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    symcr::Store store;
    if (!symcr::Store::open(path.c_str(), schema_a, options, store).ok()) ::_exit(2);
    if (store.restore_latest().sequence() != 3) ::_exit(3);
    ::abort();  // the restored state "crashes" the program
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exit " << WEXITSTATUS(status);
  const symcr::Report report = start_and_crash();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
  expect_a(2);
}

TEST_F(CrashLoopTest, AConfirmedRestoreIsRestoredAgainAtTheNextStart) {
  save_seeds(1, 4);
  ASSERT_EQ(start_and_confirm().sequence(), 4u);
  EXPECT_TRUE(journal().empty());
  const symcr::Report again = start_and_confirm();
  EXPECT_EQ(again.sequence(), 4u);
  EXPECT_TRUE(again.skipped().empty());
  expect_a(4);
}

TEST_F(CrashLoopTest, AConfirmAfterAFallbackNeverMakesTheCrashedCheckpointEligibleAgain) {
  save_seeds(1, 4);
  start_and_crash();
  ASSERT_EQ(start_and_confirm().sequence(), 3u);
  EXPECT_EQ(journal().unconfirmed, 0u);
  EXPECT_EQ(journal().fallbacks, 0u);
  EXPECT_EQ(journal().crashed_low, 4u);
  EXPECT_EQ(journal().crashed_high, 4u);
  // The program stops before its next save: the next starts restore 3 again, never the 4 that
  // crashed, and a restore that proves itself is not counted as a fallback.
  for (int start = 0; start < 3; ++start) {
    const symcr::Report again = start_and_confirm();
    ASSERT_TRUE(again.ok()) << again.status().message();
    EXPECT_EQ(again.sequence(), 3u);
    expect_a(3);
    EXPECT_EQ(skipped_sequences(again), (std::vector<std::uint64_t>{4}));
    EXPECT_NE(again.skipped()[0].reason.find("crashed the program"), std::string::npos)
        << again.skipped()[0].reason;
  }
  // What is saved from then on is numbered above the crashed range and restored.
  {
    symcr::Store store;
    open(store);
    fill_a(50);
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 5u);
  }
  EXPECT_EQ(start_and_confirm().sequence(), 5u);
  expect_a(50);
}

TEST_F(CrashLoopTest, ASecondCrashLoopAfterAConfirmedOneExcludesBoth) {
  options.fallback_depth = 3;
  options.slots = 8;
  save_seeds(1, 4);
  start_and_crash();                               // 4 crashes
  ASSERT_EQ(start_and_confirm().sequence(), 3u);   // 3 proves itself
  {
    symcr::Store store;
    open(store);
    for (int seed = 5; seed <= 6; ++seed) {
      fill_a(seed);
      ASSERT_TRUE(store.save().ok());  // sequences 5 and 6
    }
  }
  EXPECT_EQ(start_and_crash().sequence(), 6u);    // 6 crashes
  EXPECT_EQ(start_and_crash().sequence(), 5u);    // so does 5
  const symcr::Report third = start_and_confirm();  // passes over 6, 5 and the crashed 4
  ASSERT_TRUE(third.ok()) << third.status().message();
  EXPECT_EQ(third.sequence(), 3u);
  EXPECT_EQ(skipped_sequences(third), (std::vector<std::uint64_t>{6, 5, 4}));
  EXPECT_EQ(journal().crashed_low, 4u);
  EXPECT_EQ(journal().crashed_high, 6u);
  EXPECT_EQ(start_and_confirm().sequence(), 3u);
}

TEST_F(CrashLoopTest, CheckpointsSavedAfterAnUnconfirmedRestoreAreSuspectToo) {
  save_seeds(1, 3);
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 3u);
    // The program runs on the restored state and saves it: 4 and 5 carry what 3 held.
    fill_a(40);
    ASSERT_TRUE(store.save().ok());
    fill_a(50);
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 5u);
  }  // crash before confirm()
  const symcr::Report report = start_and_crash();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
  expect_a(2);
  // 5 took the slot of 4: 3, and 2 and 1 (a depth of two), were kept for the fallback.
  EXPECT_EQ(skipped_sequences(report), (std::vector<std::uint64_t>{5, 3}));
}

// Before confirm(), saves never overwrite what the fallback may still restore: the restored
// checkpoint and one older checkpoint for each fallback the depth allows. With the default four
// slots and a depth of three every slot is needed, so saves are refused until confirm().
TEST_F(CrashLoopTest, SavesBeforeConfirmKeepEveryCheckpointTheFallbackNeeds) {
  options.fallback_depth = 3;
  save_seeds(1, 6);  // slots hold 3..6
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 6u);
    for (int loop = 7; loop <= 10; ++loop) {
      fill_a(loop);
      const symcr::Status saved = store.save();
      EXPECT_EQ(saved.error(), Error::StoreFull) << loop;
      EXPECT_NE(std::string(saved.message()).find("confirm()"), std::string::npos)
          << saved.message();
    }
  }  // crash before confirm()
  for (int expected = 5; expected >= 3; --expected) {  // the whole depth, one start each
    const symcr::Report report = start_and_crash();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), static_cast<std::uint64_t>(expected));
    expect_a(expected);
  }
  EXPECT_EQ(start_and_crash().status().error(), Error::NoValidSlot);  // past the depth
}

TEST_F(CrashLoopTest, WithTwoSlotsMoreThanTheDepthSavesGoOnBeforeConfirm) {
  options.fallback_depth = 3;
  options.slots = 5;
  save_seeds(1, 6);  // slots hold 2..6
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 6u);
    for (int loop = 7; loop <= 12; ++loop) {
      fill_a(loop);
      ASSERT_TRUE(store.save().ok()) << loop;  // each into the one slot left: 7's, then 8's...
    }
  }
  for (int expected = 5; expected >= 3; --expected) {
    const symcr::Report report = start_and_crash();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), static_cast<std::uint64_t>(expected));
  }
}

TEST_F(CrashLoopTest, OnceConfirmedTheNewestSaveIsRestored) {
  options.fallback_depth = 3;
  options.slots = 5;
  save_seeds(1, 6);
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 6u);
    for (int loop = 7; loop <= 9; ++loop) {
      fill_a(loop);
      ASSERT_TRUE(store.save().ok()) << loop;
    }
    ASSERT_TRUE(store.confirm().ok());
  }
  const symcr::Report report = start_and_confirm();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 9u);
  expect_a(9);
}

TEST_F(CrashLoopTest, ARewriteForAnotherGeometryKeepsWhatTheFallbackNeeds) {
  options.fallback_depth = 3;
  save_seeds(1, 6);
  start_and_crash();  // restored 6, crashed
  options.slots = 2;  // a new build with a smaller store
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 5u);
    fill_a(30);
    // 5, and 4 and 3 for the two fallbacks left, cannot move into two slots with a new one.
    EXPECT_EQ(store.save().error(), Error::StoreFull);
    EXPECT_EQ(store.options().slots, 4u) << "the store kept its geometry";
  }
  EXPECT_EQ(start_and_crash().sequence(), 4u);
  EXPECT_EQ(start_and_crash().sequence(), 3u);
  // Once a restore is confirmed, the rewrite goes ahead and keeps the newest ones.
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().status().error(), Error::NoValidSlot);
  }
  save_seeds(40, 40);
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 7u);
    ASSERT_TRUE(store.confirm().ok());
    fill_a(41);
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.options().slots, 2u);
  }
  EXPECT_EQ(start_and_confirm().sequence(), 8u);
  expect_a(41);
}

TEST_F(CrashLoopTest, PastTheDepthNothingIsRestoredAndTheStateStaysInitial) {
  options.fallback_depth = 1;
  save_seeds(1, 4);
  EXPECT_EQ(start_and_crash().sequence(), 4u);
  EXPECT_EQ(start_and_crash().sequence(), 3u);  // the one fallback the depth allows
  const std::vector<std::uint8_t> scrambled = [] {
    scramble_a();
    return state_a();
  }();
  symcr::Store store;
  open(store);
  const symcr::Report gave_up = store.restore_latest();
  EXPECT_EQ(gave_up.status().error(), Error::NoValidSlot);
  EXPECT_NE(std::string(gave_up.status().message()).find("crash-loop fallback"), std::string::npos)
      << gave_up.status().message();
  EXPECT_EQ(state_a(), scrambled) << "a given-up restore wrote into the state";
  EXPECT_EQ(skipped_sequences(gave_up), (std::vector<std::uint64_t>{4, 3, 2, 1}));
  EXPECT_TRUE(store.confirm().ok());  // nothing restored: nothing to confirm
  EXPECT_EQ(journal().given_up_through, 4u);
  EXPECT_EQ(journal().unconfirmed, 0u);

  // The program starts afresh and saves from its initial state: those checkpoints, and only
  // they, are restored from now on, and the depth starts over for them.
  fill_a(9);
  ASSERT_TRUE(store.save().ok());
  EXPECT_EQ(store.last_sequence(), 5u);
  store.close();
  const symcr::Report fresh = start_and_crash();
  ASSERT_TRUE(fresh.ok()) << fresh.status().message();
  EXPECT_EQ(fresh.sequence(), 5u);
  expect_a(9);
  // That restore crashes too: no older checkpoint is left that was not given up on.
  const symcr::Report none = start_and_crash();
  EXPECT_EQ(none.status().error(), Error::NoValidSlot);
  EXPECT_EQ(journal().given_up_through, 5u);
}

TEST_F(CrashLoopTest, WhenEveryCheckpointIsSuspectBeforeTheDepthTheStartGivesUpAtOnce) {
  options.fallback_depth = 5;
  save_seeds(1, 2);
  EXPECT_EQ(start_and_crash().sequence(), 2u);
  EXPECT_EQ(start_and_crash().sequence(), 1u);
  scramble_a();
  const std::vector<std::uint8_t> scrambled = state_a();
  const symcr::Report report = start_and_crash();
  EXPECT_EQ(report.status().error(), Error::NoValidSlot);
  EXPECT_NE(std::string(report.status().message()).find("found no older checkpoint to restore"),
            std::string::npos)
      << report.status().message();
  EXPECT_EQ(state_a(), scrambled);
  // A start after that is not another crash: nothing was restored to crash on.
  const symcr::Report later = start_and_crash();
  EXPECT_EQ(later.status().error(), Error::NoValidSlot);
  EXPECT_NE(std::string(later.status().message()).find("2 passed over by the crash-loop"),
            std::string::npos)
      << later.status().message();
}

TEST_F(CrashLoopTest, ASecondRestoreInOneRunIsNotACrash) {
  save_seeds(1, 4);
  symcr::Store store;
  open(store);
  EXPECT_EQ(store.restore_latest().sequence(), 4u);
  EXPECT_EQ(store.restore_latest().sequence(), 4u);
  EXPECT_EQ(journal().fallbacks, 0u);
}

TEST_F(CrashLoopTest, ARefusedRestoreLeavesNothingToConfirm) {
  static symcr::Schema rover = schema_a;
  static symcr::Schema copter = schema_a;
  rover.program = "rover";
  copter.program = "copter";
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), rover, options, store).ok());
    fill_a(4);
    ASSERT_TRUE(store.save().ok());
  }
  for (int start = 0; start < 3; ++start) {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), copter, options, store).ok());
    EXPECT_EQ(store.restore_latest().status().error(), Error::Incompatible);
    EXPECT_EQ(journal().unconfirmed, 0u);
    EXPECT_EQ(journal().fallbacks, 0u) << "a refused restore counted as a crash";
  }
}

TEST_F(CrashLoopTest, TheJournalMovesWithTheCheckpointsWhenTheGeometryChanges) {
  save_seeds(1, 3);
  start_and_crash();  // restored 3
  options.slots = 6;
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 2u);
    fill_a(7);
    ASSERT_TRUE(store.save().ok());  // rewrites the store with six slots
    EXPECT_EQ(store.options().slots, 6u);
  }
  const RestoreJournal moved = journal();
  EXPECT_EQ(moved.unconfirmed, 2u);
  const symcr::Report report = start_and_crash();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 1u);
  expect_a(1);
}

TEST_F(CrashLoopTest, AReadOnlyStoreHonoursTheSuspicionsButRecordsNothing) {
  save_seeds(1, 4);
  start_and_crash();                            // restored 4
  ASSERT_EQ(start_and_crash().sequence(), 3u);  // 4 suspect, 3 unconfirmed
  const std::vector<std::uint8_t> before = read_file(path);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open_readonly(path.c_str(), schema_a, store).ok());
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  EXPECT_EQ(skipped_sequences(report), (std::vector<std::uint64_t>{4}));
  EXPECT_TRUE(store.confirm().ok());
  EXPECT_EQ(read_file(path), before);
}

// Both copies hold the current journal: one damaged later leaves it in the other (a stale
// journal there would blame good checkpoints on a crash).
TEST_F(CrashLoopTest, OneDamagedJournalCopyLeavesTheCurrentJournal) {
  save_seeds(1, 4);
  start_and_crash();  // journal: 4 unconfirmed
  start_and_crash();  // journal: 4 suspect, 3 unconfirmed
  ASSERT_EQ(journal().unconfirmed, 3u);
  for (const std::uint64_t damaged : symcr::detail::kRestoreJournalOffsets) {
    std::vector<std::uint8_t> bytes = read_file(path);
    bytes[damaged + 16] ^= 0x01;  // that copy's unconfirmed sequence
    write_file(path, bytes);
    EXPECT_EQ(journal().unconfirmed, 3u) << "copy at " << damaged;
    EXPECT_EQ(journal().suspect_low, 4u);
    bytes[damaged + 16] ^= 0x01;
    write_file(path, bytes);
  }
  std::vector<std::uint8_t> bytes = read_file(path);
  bytes[journal_offset() + 16] ^= 0x01;
  write_file(path, bytes);
  const symcr::Report report = start_and_crash();  // 3 crashed too
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
}

// A store written by an earlier version kept its single journal at 64; once this version wrote
// its copies, that one is stale and never read again, even with both copies damaged.
TEST_F(CrashLoopTest, TheEarlierVersionsJournalCountsOnlyUntilTheCopiesAreWritten) {
  save_seeds(1, 4);
  std::vector<std::uint8_t> bytes = read_file(path);
  std::uint8_t legacy[48] = {'S', 'Y', 'M', 'C', 'R', 'J', 'N', 'L'};
  symcr::format::store64(legacy + 8, 4);  // 4 restored, never confirmed
  symcr::format::store32(legacy + 44, symcr::detail::crc32c(legacy, 44));
  std::copy(legacy, legacy + sizeof legacy, bytes.begin() + 64);
  write_file(path, bytes);
  ASSERT_EQ(journal().unconfirmed, 4u) << "the earlier version's journal is read";
  ASSERT_EQ(start_and_confirm().sequence(), 3u);  // 4 passed over, as that journal says
  bytes = read_file(path);
  for (const std::uint64_t copy : symcr::detail::kRestoreJournalOffsets) bytes[copy + 20] ^= 1;
  write_file(path, bytes);
  EXPECT_TRUE(journal().empty()) << "both copies damaged: no journal, not the stale one";
}

// A second restore in one run (the program restores again after a soft fault) does not vouch
// for the first: a crash is still blamed on the older restore, so the fallback goes below it.
TEST_F(CrashLoopTest, ASecondRestoreInOneRunKeepsTheFirstUnconfirmed) {
  options.fallback_depth = 3;
  options.slots = 6;
  save_seeds(1, 3);
  {
    symcr::Store store;
    open(store);
    ASSERT_EQ(store.restore_latest().sequence(), 3u);
    fill_a(40);
    ASSERT_TRUE(store.save().ok());  // 4
    ASSERT_EQ(store.restore_latest().sequence(), 4u);
    EXPECT_EQ(journal().unconfirmed, 3u);
    fill_a(50);
    ASSERT_TRUE(store.save().ok());  // 5
  }  // crash
  const symcr::Report report = start_and_crash();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
  EXPECT_EQ(skipped_sequences(report), (std::vector<std::uint64_t>{5, 4, 3}));
  EXPECT_EQ(start_and_crash().sequence(), 1u);
}

TEST_F(CrashLoopTest, ADamagedJournalIsIgnored) {
  save_seeds(1, 4);
  start_and_crash();
  std::vector<std::uint8_t> bytes = read_file(path);
  for (const std::uint64_t offset : symcr::detail::kRestoreJournalOffsets) bytes[offset + 16] ^= 1;
  write_file(path, bytes);
  const symcr::Report report = start_and_crash();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 4u);
  EXPECT_TRUE(report.skipped().empty());
  EXPECT_EQ(journal().unconfirmed, 4u);  // rewritten whole
}

TEST_F(CrashLoopTest, ConfirmWritesOnlyOnce) {
  save_seeds(1, 2);
  symcr::Store store;
  open(store);
  ASSERT_EQ(store.restore_latest().sequence(), 2u);
  ASSERT_TRUE(store.confirm().ok());
  const std::vector<std::uint8_t> confirmed = read_file(path);
  // Later calls (a program may confirm in every loop) find nothing to write.
  std::vector<std::uint8_t> tampered = confirmed;
  tampered[journal_offset() + 20] ^= 0x10;
  write_file(path, tampered);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(store.confirm().ok());
  EXPECT_EQ(read_file(path), tampered);
}

TEST(RestoreJournalTest, EncodesAndDecodes) {
  RestoreJournal journal;
  journal.unconfirmed = 7;
  journal.suspect_low = 8;
  journal.suspect_high = 11;
  journal.given_up_through = 3;
  journal.crashed_low = 1;
  journal.crashed_high = 2;
  journal.fallbacks = 2;
  journal.depth = 4;
  journal.generation = 5;
  std::uint8_t page[symcr::detail::kRestoreJournalEnd] = {};
  std::uint8_t* bytes = page + symcr::detail::kRestoreJournalOffsets[journal.generation % 2];
  symcr::detail::encode_restore_journal(journal, bytes);
  const RestoreJournal decoded = symcr::detail::read_restore_journal(page, sizeof page);
  EXPECT_TRUE(decoded.same_state(journal));
  EXPECT_EQ(decoded.generation, 5u);
  EXPECT_EQ(decoded.unconfirmed, 7u);
  EXPECT_EQ(decoded.suspect_low, 8u);
  EXPECT_EQ(decoded.suspect_high, 11u);
  EXPECT_EQ(decoded.given_up_through, 3u);
  EXPECT_EQ(decoded.crashed_high, 2u);
  EXPECT_EQ(decoded.fallbacks, 2u);
  EXPECT_EQ(decoded.depth, 4u);
  // Every byte is covered: by the magic, the fields or the checksum.
  for (std::size_t i = 0; i < symcr::detail::kRestoreJournalSize; ++i) {
    bytes[i] ^= 0x20;
    EXPECT_TRUE(symcr::detail::read_restore_journal(page, sizeof page).empty()) << i;
    bytes[i] ^= 0x20;
  }
  EXPECT_TRUE(symcr::detail::read_restore_journal(page, symcr::detail::kRestoreJournalOffsets[1] +
                                                           symcr::detail::kRestoreJournalSize - 1)
                  .empty());
}

TEST(RestoreJournalTest, TheCopyWithTheHigherGenerationIsTheJournal) {
  std::uint8_t page[symcr::detail::kRestoreJournalEnd] = {};
  RestoreJournal older, newer;
  older.generation = 6;
  older.unconfirmed = 3;
  newer.generation = 7;
  newer.unconfirmed = 4;
  symcr::detail::encode_restore_journal(older, page + symcr::detail::kRestoreJournalOffsets[0]);
  symcr::detail::encode_restore_journal(newer, page + symcr::detail::kRestoreJournalOffsets[1]);
  EXPECT_EQ(symcr::detail::read_restore_journal(page, sizeof page).unconfirmed, 4u);
  page[symcr::detail::kRestoreJournalOffsets[1] + 30] ^= 1;  // a write of it cut short
  EXPECT_EQ(symcr::detail::read_restore_journal(page, sizeof page).unconfirmed, 3u);
}

TEST(RestoreJournalTest, ACrashWidensTheSuspectRangeDownwardsAndCountsTheDepth) {
  RestoreJournal journal;
  journal.unconfirmed = 9;
  EXPECT_TRUE(journal.record_crash(/*newest=*/12, /*depth=*/2));
  EXPECT_EQ(journal.suspect_low, 9u);
  EXPECT_EQ(journal.suspect_high, 12u);
  EXPECT_EQ(journal.unconfirmed, 0u);
  EXPECT_TRUE(journal.excludes(9));
  EXPECT_TRUE(journal.excludes(12));
  EXPECT_FALSE(journal.excludes(8));
  EXPECT_FALSE(journal.excludes(13));
  journal.unconfirmed = 6;
  EXPECT_TRUE(journal.record_crash(14, 2));
  EXPECT_EQ(journal.suspect_low, 6u);
  EXPECT_EQ(journal.suspect_high, 14u);
  journal.unconfirmed = 5;
  EXPECT_FALSE(journal.record_crash(14, 2)) << "a third fallback exceeds a depth of two";
  journal.give_up(14);
  EXPECT_EQ(journal.given_up_through, 14u);
  EXPECT_EQ(journal.fallbacks, 0u);
  EXPECT_TRUE(journal.excludes(1));
  EXPECT_FALSE(journal.excludes(15));
  journal.confirm();
  EXPECT_EQ(journal.given_up_through, 14u) << "what was given up on stays so";
}

}  // namespace
}  // namespace file_tests
