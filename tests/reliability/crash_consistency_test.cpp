// Crash consistency of the checkpoint store (docs/format.md §4):
//   - a writer process saving in a loop is SIGKILLed at random moments, hundreds of times;
//     after every kill restore_latest() must return a complete checkpoint whose sequence is
//     the newest one the writer reported as saved, or the one it was writing;
//   - a torn slot (a record cut at every page boundary and at random points) falls back to
//     the previous checkpoint;
//   - a full disk (ENOSPC on a small tmpfs, where mounting is allowed): the error is reported
//     and the previous good checkpoint survives.
// Per-byte truncation and per-bit flips of records and slots are covered by
// tests/runtime (CheckpointFile.EveryTruncationIsRefusedAndChangesNothing,
// CheckpointFile.EveryBitFlipIsRefusedAndChangesNothing, StoreTest.FallsBackPastATornNewestSlot,
// StoreTest.FallsBackPastABitFlipInTheNewestSlot); they are not repeated here.
#include <errno.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "file_test_util.hpp"
#include "reliability_schemas.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

using file_tests::TempDir;
using symcr::Error;

symcr::StoreOptions frame_store_options() {
  symcr::StoreOptions options;
  options.slots = 4;
  options.slot_size = 32 * 1024;
  return options;
}

// What the writer tells the parent, in memory shared across fork(): the sequence of its last
// save() that returned ok, and how many saves it completed.
struct Shared {
  std::atomic<std::uint64_t> last_saved;
  std::atomic<std::uint64_t> saves;
  std::atomic<int> ready;
};

[[noreturn]] void writer_process(const std::string& path, Shared* shared) {
  symcr::Store store;
  if (!symcr::Store::open(path.c_str(), frame_schema(), frame_store_options(), store).ok()) {
    ::_exit(3);
  }
  shared->ready.store(1);
  for (;;) {
    fill_frame(store.last_sequence() + 1);
    if (!store.save().ok()) ::_exit(4);
    shared->last_saved.store(store.last_sequence());
    shared->saves.fetch_add(1);
  }
}

TEST(CrashConsistency, WriterKilledAtRandomMomentsAlwaysLeavesTheNewestOrPreviousCheckpoint) {
  TempDir dir;
  const std::string path = dir.file("store");
  void* memory = ::mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE,
                        MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  auto* shared = new (memory) Shared{};
  std::mt19937 random(20261123);
  constexpr int kKills = 240;
  int restored_newer = 0;
  std::uint64_t total_saves = 0;
  for (int kill = 0; kill < kKills; ++kill) {
    shared->ready.store(0);
    shared->saves.store(0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) writer_process(path, shared);
    // Kill at a random moment: usually after some saves, sometimes during open or the first.
    while (shared->ready.load() == 0 && kill % 8 != 0) {
      int status = 0;
      if (::waitpid(child, &status, WNOHANG) == child) FAIL() << "writer exited early: " << status;
      ::usleep(50);
    }
    ::usleep(static_cast<useconds_t>(random() % 3000));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "the writer failed on its own (exit " << WEXITSTATUS(status) << ") at kill " << kill;
    const std::uint64_t reported = shared->last_saved.load();
    total_saves += shared->saves.load();
    if (reported == 0) continue;  // killed before any checkpoint existed

    frame.sequence = 0;
    symcr::Store store;
    const symcr::Status opened =
        symcr::Store::open(path.c_str(), frame_schema(), frame_store_options(), store);
    ASSERT_TRUE(opened.ok()) << "kill " << kill << ": " << opened.message();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << "kill " << kill << ": " << report.to_text();
    // The newest reported save, or the one being written when the kill came (its pwrite may
    // have completed before the writer could report it).
    ASSERT_TRUE(report.sequence() == reported || report.sequence() == reported + 1)
        << "kill " << kill << ": restored " << report.sequence() << ", writer reported "
        << reported;
    ASSERT_TRUE(frame_is(report.sequence())) << "kill " << kill << ": an incomplete checkpoint";
    if (report.sequence() == reported + 1) ++restored_newer;
    // The next writer continues from what is in the store.
    shared->last_saved.store(store.last_sequence());
  }
  std::printf("[ crash ] %d kills survived, %llu saves in total, %d restores found the save "
              "the writer had not reported yet\n",
              kKills, static_cast<unsigned long long>(total_saves), restored_newer);
  ::munmap(memory, sizeof(Shared));
}

// A slot whose write stopped part-way: the record is cut at every page boundary of its bytes
// (what a power cut leaves on a 4 KiB-page device) and at random byte counts; the old bytes of
// the slot (a previous, older record) remain behind the cut.
TEST(CrashConsistency, TornSlotAtEveryPageBoundaryFallsBackToThePreviousCheckpoint) {
  TempDir dir;
  const std::string path = dir.file("store");
  symcr::StoreOptions options = frame_store_options();
  options.slots = 2;
  std::uint64_t newest_offset = 0;
  std::vector<std::uint8_t> newest_record, oldest_slot;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), frame_schema(), options, store).ok());
    for (std::uint64_t s = 1; s <= 3; ++s) {
      fill_frame(s);
      ASSERT_TRUE(store.save().ok());
    }
  }
  // Slots: 1 and 3 share slot 0 (3 overwrote 1), 2 is in slot 1. Find slot 0 by its sequence.
  const std::vector<std::uint8_t> file = file_tests::read_file(path);
  const std::uint32_t area_size = symcr::format::load32(file.data() + 20);
  const std::uint64_t slots_offset = 4096 + 2 * std::uint64_t{area_size};
  for (std::uint32_t slot = 0; slot < 2; ++slot) {
    const std::uint64_t at = slots_offset + std::uint64_t{slot} * options.slot_size;
    if (symcr::format::load64(file.data() + at + 16) == 3) newest_offset = at;
  }
  ASSERT_NE(newest_offset, 0u);
  const std::uint64_t record_size = 56 + symcr::format::load32(file.data() + newest_offset + 44);
  newest_record.assign(file.begin() + newest_offset, file.begin() + newest_offset + record_size);

  // The slot as it was before sequence 3 was written: sequence 1's record.
  {
    TempDir other;
    const std::string old_path = other.file("store");
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(old_path.c_str(), frame_schema(), options, store).ok());
    fill_frame(1);
    ASSERT_TRUE(store.save().ok());
    store.close();
    const std::vector<std::uint8_t> old_file = file_tests::read_file(old_path);
    oldest_slot.assign(old_file.begin() + slots_offset, old_file.begin() + slots_offset + options.slot_size);
  }

  std::vector<std::uint64_t> cuts;
  for (std::uint64_t cut = 0; cut < record_size; cut += 512) cuts.push_back(cut);  // sectors
  std::mt19937 random(7);
  for (int i = 0; i < 64; ++i) cuts.push_back(random() % record_size);
  int tried = 0;
  for (const std::uint64_t cut : cuts) {
    std::vector<std::uint8_t> torn = file;
    std::memcpy(torn.data() + newest_offset, oldest_slot.data(), options.slot_size);
    std::memcpy(torn.data() + newest_offset, newest_record.data(), cut);
    file_tests::write_file(path, torn);
    frame.sequence = 0;
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), frame_schema(), options, store).ok());
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << "cut at " << cut << ": " << report.to_text();
    EXPECT_EQ(report.sequence(), 2u) << "cut at " << cut;
    ASSERT_TRUE(frame_is(2)) << "cut at " << cut;
    // The next save continues past the valid checkpoints and makes the store whole again.
    fill_frame(store.last_sequence() + 1);
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 3u);
    ++tried;
  }
  std::printf("[ crash ] %d torn versions of the newest slot tried\n", tried);
}

// A small tmpfs (1 MiB): real ENOSPC. Mounting needs CAP_SYS_ADMIN; without it these tests
// skip, and a failing write stays covered through RLIMIT_FSIZE (EFBIG) by
// CheckpointFile.FailedWriteKeepsThePreviousCheckpointAndRemovesTheTempFile.
class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    mounted_ = ::mount("tmpfs", dir_.path().c_str(), "tmpfs", MS_NOSUID | MS_NODEV,
                       "size=1m,mode=0700") == 0;
  }
  void TearDown() override {
    if (mounted_) ::umount2(dir_.path().c_str(), MNT_DETACH);
  }
  // Fills the file system up to its last few bytes.
  void fill_disk() {
    const std::string filler = dir_.file("filler");
    const int fd = ::open(filler.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0600);
    ASSERT_GE(fd, 0);
    std::vector<char> chunk(4096, 'x');
    while (::write(fd, chunk.data(), chunk.size()) > 0) {
    }
    const int error = errno;
    ::close(fd);
    ASSERT_EQ(error, ENOSPC);
  }
  TempDir dir_;
  bool mounted_ = false;
};

TEST_F(FullDisk, SingleFileCheckpointReportsTheErrorAndKeepsThePreviousOne) {
  if (!mounted_) GTEST_SKIP() << "cannot mount a tmpfs here (no CAP_SYS_ADMIN); RLIMIT_FSIZE "
                                 "is covered by CheckpointFile.FailedWriteKeepsThePrevious...";
  const std::string path = dir_.file("frame.ckpt");
  fill_frame(41);
  ASSERT_TRUE(symcr::checkpoint(frame_schema(), path.c_str()).ok());
  const std::vector<std::uint8_t> previous = file_tests::read_file(path);
  fill_disk();
  fill_frame(42);
  const symcr::Status saved = symcr::checkpoint(frame_schema(), path.c_str());
  EXPECT_EQ(saved.error(), Error::Io) << saved.message();
  EXPECT_NE(std::string(saved.message()).find(std::strerror(ENOSPC)), std::string::npos)
      << saved.message();
  EXPECT_EQ(file_tests::read_file(path), previous);
  EXPECT_EQ(dir_.entries(), (std::vector<std::string>{"filler", "frame.ckpt"}))
      << "the temp file must be removed";
  frame.sequence = 0;
  const symcr::Report report = symcr::restore(frame_schema(), path.c_str());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(frame_is(41));
}

TEST_F(FullDisk, CreatingAStoreReportsTheErrorAndLeavesNoStore) {
  if (!mounted_) GTEST_SKIP() << "cannot mount a tmpfs here";
  fill_disk();
  const std::string path = dir_.file("store");
  symcr::Store store;
  const symcr::Status opened =
      symcr::Store::open(path.c_str(), frame_schema(), frame_store_options(), store);
  EXPECT_EQ(opened.error(), Error::Io) << opened.message();
  EXPECT_FALSE(store.is_open());
  // Whatever is left at the path is not a store anyone could mistake for one with checkpoints.
  ::unlink(dir_.file("filler").c_str());
  const symcr::Status reopened =
      symcr::Store::open(path.c_str(), frame_schema(), frame_store_options(), store);
  ASSERT_TRUE(reopened.ok()) << reopened.message();
  EXPECT_EQ(store.restore_latest().status().error(), Error::NoValidSlot);
}

// The store is preallocated, so a full disk cannot take the slots' space away: saves go on
// and the newest checkpoint is restored.
TEST_F(FullDisk, APreallocatedStoreKeepsSavingWhenTheDiskFills) {
  if (!mounted_) GTEST_SKIP() << "cannot mount a tmpfs here";
  const std::string path = dir_.file("store");
  symcr::StoreOptions options = frame_store_options();
  options.durability = symcr::Durability::Fdatasync;
  symcr::Store store;
  const symcr::Status opened = symcr::Store::open(path.c_str(), frame_schema(), options, store);
  ASSERT_TRUE(opened.ok()) << opened.message();
  fill_frame(1);
  ASSERT_TRUE(store.save().ok());
  fill_disk();
  for (std::uint64_t s = 2; s <= 6; ++s) {
    fill_frame(s);
    const symcr::Status saved = store.save();
    ASSERT_TRUE(saved.ok()) << saved.message();
  }
  frame.sequence = 0;
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(report.sequence(), 6u);
  EXPECT_TRUE(frame_is(6));
}

}  // namespace
}  // namespace reliability
