// The file system calls the store and single-file checkpoints make, behind one interface so
// that the test suite can replace the disk: its crash simulator runs the real store code over
// an in-memory file system that cuts a write at any byte, crashes at any call and checks the
// store's guarantees after every step (tests/reliability/store_simulator_test.cpp). Programs
// always use the POSIX one. Internal to the runtime.
//
// Each call has its POSIX namesake's contract: -1 (or an error number, for fallocate) with
// errno set on failure.
#ifndef SYMCR_SRC_FILE_SYSTEM_HPP
#define SYMCR_SRC_FILE_SYSTEM_HPP

#include <sys/stat.h>
#include <sys/types.h>

#include <cstddef>

namespace symcr::detail {

class FileSystem {
 public:
  virtual ~FileSystem() = default;
  virtual int open(const char* path, int flags, mode_t mode) = 0;
  virtual int close(int fd) = 0;
  virtual ssize_t pread(int fd, void* data, std::size_t size, off_t offset) = 0;
  virtual ssize_t pwrite(int fd, const void* data, std::size_t size, off_t offset) = 0;
  virtual int fstat(int fd, struct stat* out) = 0;
  virtual int lstat(const char* path, struct stat* out) = 0;
  // Follows symlinks: for the folders on a path, which may be links.
  virtual int stat(const char* path, struct stat* out) = 0;
  virtual int ftruncate(int fd, off_t size) = 0;
  // posix_fallocate(fd, 0, size): returns 0 or an error number (errno is not used).
  virtual int fallocate(int fd, off_t size) = 0;
  virtual int fdatasync(int fd) = 0;
  virtual int fsync(int fd) = 0;
  virtual int flock(int fd, int operation) = 0;
  virtual int rename(const char* from, const char* to) = 0;
  virtual int unlink(const char* path) = 0;
  // Calls `visit` with each entry's name in `directory`; false when it cannot be listed.
  virtual bool list_directory(const char* directory, void (*visit)(void* context, const char* name),
                              void* context) = 0;
  // The calling process's id and whether a process `pid` still exists: whose temp files are
  // stale.
  virtual long process_id() = 0;
  virtual bool process_exists(long pid) = 0;
};

// The file system in use: POSIX, unless a test installed another.
FileSystem& file_system();
// For tests: makes `replacement` (nullptr: POSIX again) the process's file system. Call it
// while no store is open and no checkpoint is being written.
void set_file_system(FileSystem* replacement);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_FILE_SYSTEM_HPP
