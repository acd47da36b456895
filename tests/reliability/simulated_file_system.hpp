// An in-memory file system for the store's crash simulator (store_simulator_test.cpp), in the
// spirit of SQLite's crash-test VFS: the real store code runs over it, and it can end the
// running "process" at any mutating call — before the call, or in the middle of a write, with
// only a prefix of its bytes landed (a torn write). A crash models kill -9 or a reset: what
// was written stays (the page cache survives a process), the process's descriptors and locks
// are gone, and every later call of that process fails with EIO. Processes are numbered; temp
// files name them, and a dead one's are stale.
#ifndef SYMCR_TESTS_RELIABILITY_SIMULATED_FILE_SYSTEM_HPP
#define SYMCR_TESTS_RELIABILITY_SIMULATED_FILE_SYSTEM_HPP

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "file_system.hpp"

namespace reliability {

class SimulatedFileSystem final : public symcr::detail::FileSystem {
 public:
  // Where the next crash happens: at the `at`-th mutating call from now (1: the next one),
  // and for a write, after `torn_bytes` of its bytes (0: before the call, the whole write
  // lost; a value of the write's size or more: the write completes, the crash follows).
  struct CrashPlan {
    std::uint64_t at = 0;  // 0: no crash planned
    std::size_t torn_bytes = 0;
  };

  explicit SimulatedFileSystem(std::string directory);

  // Starts a new process (the previous one, if any, must have ended).
  void start_process();
  // Ends the running process as a crash would: its descriptors and locks go away.
  void kill_process();
  bool crashed() const { return crashed_; }
  void plan_crash(const CrashPlan& plan);
  // Mutating calls made so far (writes, truncations, allocations, syncs, renames, unlinks).
  std::uint64_t mutating_calls() const { return mutating_calls_; }
  // Opens for writing fail with EROFS, as on a file system remounted read-only.
  void set_read_only(bool read_only) { read_only_ = read_only; }
  // Runs `call(context)` once, just before the next flock(): another process's turn.
  void before_next_flock(void (*call)(void*), void* context) {
    before_flock_ = call;
    before_flock_context_ = context;
  }

  // Outside the store's code: the bytes of a file (empty if absent), changing one, the names.
  std::vector<std::uint8_t> contents(const std::string& path) const;
  // The same without a copy; valid until the next call that changes the file system.
  const std::vector<std::uint8_t>& view(const std::string& path) const;
  void set_contents(const std::string& path, std::vector<std::uint8_t> bytes);
  std::vector<std::string> names() const;
  const std::string& directory() const { return directory_; }

  int open(const char* path, int flags, mode_t mode) override;
  int close(int fd) override;
  ssize_t pread(int fd, void* data, std::size_t size, off_t offset) override;
  ssize_t pwrite(int fd, const void* data, std::size_t size, off_t offset) override;
  int fstat(int fd, struct stat* out) override;
  int lstat(const char* path, struct stat* out) override;
  // No symlinks here: as lstat.
  int stat(const char* path, struct stat* out) override { return lstat(path, out); }
  int ftruncate(int fd, off_t size) override;
  int fallocate(int fd, off_t size) override;
  int fdatasync(int fd) override;
  int fsync(int fd) override;
  int flock(int fd, int operation) override;
  int rename(const char* from, const char* to) override;
  int unlink(const char* path) override;
  bool list_directory(const char* directory, void (*visit)(void*, const char*),
                      void* context) override;
  long process_id() override { return process_; }
  bool process_exists(long pid) override { return pid == process_ && running_; }

 private:
  struct Inode {
    std::uint64_t number = 0;
    std::vector<std::uint8_t> bytes;
    int locked_by = -1;  // the descriptor holding its exclusive lock
    unsigned links = 0;
  };
  struct Descriptor {
    std::shared_ptr<Inode> inode;  // null for the directory
    bool writable = false;
  };
  // False (errno EIO) when the process crashed; counts a mutating call and crashes before it
  // when planned so. `torn`: set to the bytes of a write to land before the crash.
  bool mutation_allowed(std::size_t* torn = nullptr);
  bool alive() const { return running_ && !crashed_; }
  Descriptor* descriptor(int fd);
  void fill_stat(const Inode& inode, unsigned links, struct stat* out) const;

  std::string directory_;
  std::map<std::string, std::shared_ptr<Inode>> files_;
  std::map<int, Descriptor> descriptors_;
  int next_fd_ = 100;
  std::uint64_t next_inode_ = 1;
  long process_ = 1000;
  bool running_ = false;
  bool crashed_ = false;
  bool read_only_ = false;
  std::uint64_t mutating_calls_ = 0;
  CrashPlan plan_;
  void (*before_flock_)(void*) = nullptr;
  void* before_flock_context_ = nullptr;
};

// Installs a file system for the current scope.
class FileSystemInstalled {
 public:
  explicit FileSystemInstalled(symcr::detail::FileSystem& fs) {
    symcr::detail::set_file_system(&fs);
  }
  ~FileSystemInstalled() { symcr::detail::set_file_system(nullptr); }
  FileSystemInstalled(const FileSystemInstalled&) = delete;
  FileSystemInstalled& operator=(const FileSystemInstalled&) = delete;
};

}  // namespace reliability

#endif  // SYMCR_TESTS_RELIABILITY_SIMULATED_FILE_SYSTEM_HPP
