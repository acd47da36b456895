// The POSIX file system (file_system.hpp). Calls interrupted by a signal are retried.
#include "file_system.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

namespace symcr::detail {
namespace {

template <typename Call>
auto retrying(Call call) -> decltype(call()) {
  decltype(call()) result;
  do {
    result = call();
  } while (result < 0 && errno == EINTR);
  return result;
}

class PosixFileSystem final : public FileSystem {
 public:
  int open(const char* path, int flags, mode_t mode) override {
    return retrying([&] { return ::open(path, flags, mode); });
  }
  int close(int fd) override { return ::close(fd); }
  ssize_t pread(int fd, void* data, std::size_t size, off_t offset) override {
    return ::pread(fd, data, size, offset);
  }
  ssize_t pwrite(int fd, const void* data, std::size_t size, off_t offset) override {
    return ::pwrite(fd, data, size, offset);
  }
  int fstat(int fd, struct stat* out) override { return ::fstat(fd, out); }
  int lstat(const char* path, struct stat* out) override { return ::lstat(path, out); }
  int stat(const char* path, struct stat* out) override { return ::stat(path, out); }
  int ftruncate(int fd, off_t size) override {
    return retrying([&] { return ::ftruncate(fd, size); });
  }
  int fallocate(int fd, off_t size) override { return ::posix_fallocate(fd, 0, size); }
  int fdatasync(int fd) override { return ::fdatasync(fd); }
  int fsync(int fd) override { return ::fsync(fd); }
  int flock(int fd, int operation) override {
    return retrying([&] { return ::flock(fd, operation); });
  }
  int rename(const char* from, const char* to) override { return ::rename(from, to); }
  int unlink(const char* path) override { return ::unlink(path); }
  bool list_directory(const char* directory, void (*visit)(void*, const char*),
                      void* context) override {
    DIR* listing = ::opendir(directory);
    if (listing == nullptr) return false;
    while (const dirent* entry = ::readdir(listing)) visit(context, entry->d_name);
    ::closedir(listing);
    return true;
  }
  long process_id() override { return static_cast<long>(::getpid()); }
  bool process_exists(long pid) override {
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
  }
};

PosixFileSystem posix_file_system;
FileSystem* installed = &posix_file_system;

}  // namespace

FileSystem& file_system() { return *installed; }

void set_file_system(FileSystem* replacement) {
  installed = replacement != nullptr ? replacement : &posix_file_system;
}

}  // namespace symcr::detail
