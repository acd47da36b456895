// File safety beyond the file layer's own tests (tests/runtime: CheckpointFile.CreatedWithMode0600,
// .SymlinkAtThePathIsNeitherFollowedNorReplaced, .ExistingTempNamesAreNeverReusedOrFollowed,
// .FailedWriteKeepsThePreviousCheckpointAndRemovesTheTempFile, .ADirectoryAtThePathIsLeftAlone,
// .DirectoriesAndFifosAreRefusedWithoutBlocking; StoreTest.CreatesAPreallocatedFileWithMode0600,
// .ASymlinkAtThePathIsNotFollowed, .OneOpenStorePerFile, .AFileThatIsNotAStoreIsLeftAlone):
//   - a *dangling* symlink planted at the path (the classic attack: it names a file the victim
//     may create, e.g. in another user's directory) is neither followed nor its target created,
//     for the store and for single-file checkpoints;
//   - a store path that is a FIFO or a directory is refused without blocking and left alone.
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

#include "file_test_util.hpp"
#include "reliability_schemas.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

using file_tests::TempDir;

bool exists(const std::string& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0;
}

symcr::StoreOptions small_store() {
  symcr::StoreOptions options;
  options.slots = 2;
  options.slot_size = 32 * 1024;
  return options;
}

TEST(FileSafety, ADanglingSymlinkIsNeverFollowedAndItsTargetNeverCreated) {
  TempDir dir;
  const std::string target = dir.file("target-that-does-not-exist");
  const std::string store_link = dir.file("store");
  const std::string file_link = dir.file("frame.ckpt");
  ASSERT_EQ(::symlink(target.c_str(), store_link.c_str()), 0);
  ASSERT_EQ(::symlink(target.c_str(), file_link.c_str()), 0);

  symcr::Store store;
  const symcr::Status opened = symcr::Store::open(store_link.c_str(), frame_schema(), small_store(), store);
  EXPECT_EQ(opened.error(), symcr::Error::Io) << opened.message();
  EXPECT_FALSE(exists(target)) << "the store followed a dangling symlink";
  EXPECT_TRUE(file_tests::is_symlink(store_link));

  fill_frame(1);
  const symcr::Status saved = symcr::checkpoint(frame_schema(), file_link.c_str());
  EXPECT_EQ(saved.error(), symcr::Error::Io) << saved.message();
  EXPECT_FALSE(exists(target)) << "checkpoint() followed a dangling symlink";
  EXPECT_TRUE(file_tests::is_symlink(file_link));
  EXPECT_EQ(symcr::restore(frame_schema(), file_link.c_str()).status().error(), symcr::Error::Io);
}

TEST(FileSafety, AStorePathThatIsAFifoOrADirectoryIsRefusedWithoutBlocking) {
  TempDir dir;
  const std::string fifo = dir.file("fifo");
  const std::string directory = dir.file("directory");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ASSERT_EQ(::mkdir(directory.c_str(), 0700), 0);
  ::alarm(20);  // a blocking open would hang here: fail loudly instead
  for (const std::string& path : {fifo, directory}) {
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open(path.c_str(), frame_schema(), small_store(), store);
    EXPECT_EQ(opened.error(), symcr::Error::Io) << path << ": " << opened.message();
    EXPECT_FALSE(store.is_open());
  }
  ::alarm(0);
  struct stat info {};
  ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
  ASSERT_EQ(::lstat(directory.c_str(), &info), 0);
  EXPECT_TRUE(S_ISDIR(info.st_mode));
}

}  // namespace
}  // namespace reliability
