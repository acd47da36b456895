// File safety beyond the file layer's own tests (tests/runtime: CheckpointFile.CreatedWithMode0600,
// .SymlinkAtThePathIsNeitherFollowedNorReplaced, .ExistingTempNamesAreNeverReusedOrFollowed,
// .FailedWriteKeepsThePreviousCheckpointAndRemovesTheTempFile, .ADirectoryAtThePathIsLeftAlone,
// .DirectoriesAndFifosAreRefusedWithoutBlocking; StoreTest.CreatesAPreallocatedFileWithMode0600,
// .ASymlinkAtThePathIsNotFollowed, .OneOpenStorePerFile, .AFileThatIsNotAStoreIsLeftAlone):
//   - a *dangling* symlink planted at the path (the classic attack: it names a file the victim
//     may create, e.g. in another user's directory) is neither followed nor its target created,
//     for the store and for single-file checkpoints;
//   - a store path that is a FIFO or a directory is refused without blocking and left alone;
//   - checkpoint() never replaces a FIFO or a device node with a regular file;
//   - temp files left by a checkpoint() whose process was killed are removed by the next one;
//   - a store whose creation fails (the file size limit) leaves no empty file behind.
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

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

TEST(FileSafety, CheckpointNeverReplacesAFifoOrADeviceNode) {
  TempDir dir;
  const std::string fifo = dir.file("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::vector<std::string> special = {fifo};
  const std::string null_device = dir.file("null");
  // A character device like /dev/null needs privileges to create; root (CI) has them.
  if (::mknod(null_device.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) {
    special.push_back(null_device);
  } else {
    std::printf("mknod not permitted here: only the FIFO case runs\n");
  }
  fill_frame(1);
  for (const std::string& path : special) {
    const symcr::Status saved = symcr::checkpoint(frame_schema(), path.c_str());
    EXPECT_EQ(saved.error(), symcr::Error::Io) << path;
    EXPECT_NE(std::string(saved.message()).find("not a regular file"), std::string::npos)
        << saved.message();
  }
  struct stat info {};
  ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
  if (special.size() > 1) {
    ASSERT_EQ(::lstat(null_device.c_str(), &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode));
  }
  EXPECT_EQ(dir.entries().size(), special.size()) << "a temp file was left behind";
}

pid_t a_pid_that_no_longer_exists() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(FileSafety, TempFilesOfAKilledCheckpointAreRemovedByTheNextOne) {
  TempDir dir;
  const std::string path = dir.file("frame.ckpt");
  const std::string dead = path + ".tmp." + std::to_string(a_pid_that_no_longer_exists()) + ".0";
  const std::string alive = path + ".tmp." + std::to_string(::getppid()) + ".0";
  const std::string other_name = dir.file("other.ckpt.tmp.") +
                                 std::to_string(a_pid_that_no_longer_exists()) + ".0";
  const std::string not_ours = path + ".tmp.notapid.0";
  for (const std::string& name : {dead, alive, other_name, not_ours}) {
    file_tests::write_file(name, {1, 2, 3});
  }
  fill_frame(7);
  ASSERT_TRUE(symcr::checkpoint(frame_schema(), path.c_str()).ok());
  EXPECT_FALSE(exists(dead)) << "the temp file of a dead process is still there";
  EXPECT_TRUE(exists(alive)) << "a live process's temp file was removed";
  EXPECT_TRUE(exists(other_name)) << "another checkpoint's temp file was removed";
  EXPECT_TRUE(exists(not_ours));
  EXPECT_TRUE(symcr::restore(frame_schema(), path.c_str()).ok());
}

// A file system remounted read-only after a fault (ext4's errors=remount-ro): the patched build
// still restores the last good checkpoint with the ordinary Store::open.
TEST(FileSafety, AStoreOnAReadOnlyFileSystemStillRestores) {
  TempDir dir;
  const std::string mountpoint = dir.file("mnt");
  ASSERT_EQ(::mkdir(mountpoint.c_str(), 0700), 0);
  if (::mount("tmpfs", mountpoint.c_str(), "tmpfs", 0, "size=4m") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno)
                 << "): the read-only file system case needs CAP_SYS_ADMIN";
  }
  const std::string path = mountpoint + "/store";
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), frame_schema(), small_store(), store).ok());
    fill_frame(5);
    ASSERT_TRUE(store.save().ok());
  }
  ASSERT_EQ(::mount(nullptr, mountpoint.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr), 0)
      << std::strerror(errno);
  {
    symcr::Store store;
    const symcr::Status opened =
        symcr::Store::open(path.c_str(), frame_schema(), small_store(), store);
    ASSERT_TRUE(opened.ok()) << opened.message();
    EXPECT_TRUE(store.read_only());
    fill_frame(9);
    const symcr::Report report = store.restore_latest();
    EXPECT_TRUE(report.ok()) << report.status().message();
    EXPECT_TRUE(frame_is(5));
    EXPECT_EQ(store.save().error(), symcr::Error::Io);
  }
  EXPECT_EQ(::umount(mountpoint.c_str()), 0);
}

TEST(FileSafety, AStoreWhoseCreationFailsLeavesNoFile) {
  TempDir dir;
  const std::string path = dir.file("store");
  const pid_t child = ::fork();
  if (child == 0) {
    // The file size limit makes preallocation fail (EFBIG) after the file was created.
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(3);
    symcr::Store store;
    const symcr::Status opened =
        symcr::Store::open(path.c_str(), frame_schema(), small_store(), store);
    ::_exit(opened.ok() ? 1 : opened.error() == symcr::Error::Io ? 0 : 2);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the store was created or failed with another error";
  EXPECT_FALSE(exists(path)) << "a failed creation left a file behind";
}

}  // namespace
}  // namespace reliability
