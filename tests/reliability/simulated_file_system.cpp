// The crash simulator's file system (simulated_file_system.hpp).
#include "simulated_file_system.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace reliability {

SimulatedFileSystem::SimulatedFileSystem(std::string directory)
    : directory_(std::move(directory)) {}

void SimulatedFileSystem::start_process() {
  ++process_;
  running_ = true;
  crashed_ = false;
  plan_ = CrashPlan();
}

void SimulatedFileSystem::kill_process() {
  for (auto& [fd, open] : descriptors_) {
    if (open.inode && open.inode->locked_by == fd) open.inode->locked_by = -1;
  }
  descriptors_.clear();
  running_ = false;
}

void SimulatedFileSystem::plan_crash(const CrashPlan& plan) {
  plan_ = plan;
  if (plan_.at != 0) plan_.at += mutating_calls_;
}

bool SimulatedFileSystem::mutation_allowed(std::size_t* torn) {
  if (!alive()) {
    errno = EIO;
    return false;
  }
  ++mutating_calls_;
  if (plan_.at == 0 || mutating_calls_ != plan_.at) return true;
  // The planned crash: before this call, or after (part of) it.
  if (plan_.torn_bytes == 0) {
    crashed_ = true;
    errno = EIO;
    return false;
  }
  if (torn != nullptr) *torn = plan_.torn_bytes;
  crashed_ = true;  // the call lands (torn, for a write), then the process is gone
  return true;
}

SimulatedFileSystem::Descriptor* SimulatedFileSystem::descriptor(int fd) {
  auto found = descriptors_.find(fd);
  if (!alive() || found == descriptors_.end()) {
    errno = alive() ? EBADF : EIO;
    return nullptr;
  }
  return &found->second;
}

void SimulatedFileSystem::fill_stat(const Inode& inode, unsigned links, struct stat* out) const {
  std::memset(out, 0, sizeof *out);
  out->st_dev = 1;
  out->st_ino = inode.number;
  out->st_mode = S_IFREG | 0600;
  out->st_nlink = links;
  out->st_uid = ::geteuid();
  out->st_size = static_cast<off_t>(inode.bytes.size());
}

std::vector<std::uint8_t> SimulatedFileSystem::contents(const std::string& path) const {
  auto found = files_.find(path);
  return found == files_.end() ? std::vector<std::uint8_t>() : found->second->bytes;
}

const std::vector<std::uint8_t>& SimulatedFileSystem::view(const std::string& path) const {
  static const std::vector<std::uint8_t> kNone;
  auto found = files_.find(path);
  return found == files_.end() ? kNone : found->second->bytes;
}

void SimulatedFileSystem::set_contents(const std::string& path, std::vector<std::uint8_t> bytes) {
  auto& inode = files_[path];
  if (!inode) {
    inode = std::make_shared<Inode>();
    inode->number = next_inode_++;
    inode->links = 1;
  }
  inode->bytes = std::move(bytes);
}

std::vector<std::string> SimulatedFileSystem::names() const {
  std::vector<std::string> names;
  for (const auto& [path, inode] : files_) names.push_back(path.substr(directory_.size() + 1));
  return names;
}

int SimulatedFileSystem::open(const char* path, int flags, mode_t) {
  if (!alive()) {
    errno = EIO;
    return -1;
  }
  const int fd = next_fd_++;
  if ((flags & O_DIRECTORY) != 0) {
    if (directory_ != path) {
      errno = ENOENT;
      return -1;
    }
    descriptors_[fd] = Descriptor();
    return fd;
  }
  const bool writable = (flags & O_ACCMODE) != O_RDONLY;
  if (writable && read_only_) {
    errno = EROFS;
    return -1;
  }
  auto found = files_.find(path);
  if (found == files_.end()) {
    if ((flags & O_CREAT) == 0) {
      errno = ENOENT;
      return -1;
    }
    if (!mutation_allowed()) return -1;
    auto inode = std::make_shared<Inode>();
    inode->number = next_inode_++;
    inode->links = 1;
    found = files_.emplace(path, inode).first;
  } else if ((flags & (O_CREAT | O_EXCL)) == (O_CREAT | O_EXCL)) {
    errno = EEXIST;
    return -1;
  }
  descriptors_[fd] = Descriptor{found->second, writable};
  return fd;
}

int SimulatedFileSystem::close(int fd) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr) return -1;
  if (open->inode && open->inode->locked_by == fd) open->inode->locked_by = -1;
  descriptors_.erase(fd);
  return 0;
}

ssize_t SimulatedFileSystem::pread(int fd, void* data, std::size_t size, off_t offset) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr) return -1;
  if (!open->inode) {
    errno = EISDIR;
    return -1;
  }
  const std::vector<std::uint8_t>& bytes = open->inode->bytes;
  const auto at = static_cast<std::size_t>(offset);
  if (at >= bytes.size()) return 0;
  const std::size_t n = std::min(size, bytes.size() - at);
  std::memcpy(data, bytes.data() + at, n);
  return static_cast<ssize_t>(n);
}

ssize_t SimulatedFileSystem::pwrite(int fd, const void* data, std::size_t size, off_t offset) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr) return -1;
  if (!open->inode || !open->writable) {
    errno = EBADF;
    return -1;
  }
  std::size_t landed = size;
  if (!mutation_allowed(&landed)) return -1;
  landed = std::min(landed, size);
  std::vector<std::uint8_t>& bytes = open->inode->bytes;
  const auto at = static_cast<std::size_t>(offset);
  if (bytes.size() < at + landed) bytes.resize(at + landed);
  std::memcpy(bytes.data() + at, data, landed);
  if (crashed_) {
    errno = EIO;
    return -1;
  }
  return static_cast<ssize_t>(size);
}

int SimulatedFileSystem::fstat(int fd, struct stat* out) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr) return -1;
  if (!open->inode) {
    std::memset(out, 0, sizeof *out);
    out->st_mode = S_IFDIR | 0700;
    return 0;
  }
  fill_stat(*open->inode, open->inode->links, out);
  return 0;
}

int SimulatedFileSystem::lstat(const char* path, struct stat* out) {
  if (!alive()) {
    errno = EIO;
    return -1;
  }
  if (directory_ == path) {  // its one folder
    std::memset(out, 0, sizeof *out);
    out->st_dev = 1;
    out->st_mode = S_IFDIR | 0700;
    out->st_uid = ::geteuid();
    return 0;
  }
  auto found = files_.find(path);
  if (found == files_.end()) {
    errno = ENOENT;
    return -1;
  }
  fill_stat(*found->second, found->second->links, out);
  return 0;
}

int SimulatedFileSystem::ftruncate(int fd, off_t size) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr || !mutation_allowed()) return -1;
  open->inode->bytes.resize(static_cast<std::size_t>(size));
  return crashed_ ? (errno = EIO, -1) : 0;
}

int SimulatedFileSystem::fallocate(int fd, off_t size) {
  Descriptor* open = descriptor(fd);
  if (open == nullptr || !mutation_allowed()) return errno;
  std::vector<std::uint8_t>& bytes = open->inode->bytes;
  if (bytes.size() < static_cast<std::size_t>(size)) bytes.resize(static_cast<std::size_t>(size));
  return crashed_ ? EIO : 0;
}

int SimulatedFileSystem::fdatasync(int fd) {
  if (descriptor(fd) == nullptr || !mutation_allowed()) return -1;
  return crashed_ ? (errno = EIO, -1) : 0;
}

int SimulatedFileSystem::fsync(int fd) { return fdatasync(fd); }

int SimulatedFileSystem::flock(int fd, int operation) {
  if (before_flock_ != nullptr) {
    void (*call)(void*) = before_flock_;
    before_flock_ = nullptr;
    call(before_flock_context_);
  }
  Descriptor* open = descriptor(fd);
  if (open == nullptr) return -1;
  Inode& inode = *open->inode;
  if ((operation & LOCK_UN) != 0) {
    if (inode.locked_by == fd) inode.locked_by = -1;
    return 0;
  }
  if (inode.locked_by >= 0 && inode.locked_by != fd) {
    errno = EWOULDBLOCK;
    return -1;
  }
  inode.locked_by = fd;
  return 0;
}

int SimulatedFileSystem::rename(const char* from, const char* to) {
  auto found = files_.find(from);
  if (alive() && found == files_.end()) {
    errno = ENOENT;
    return -1;
  }
  if (!mutation_allowed()) return -1;
  std::shared_ptr<Inode> moved = found->second;
  files_.erase(found);
  auto replaced = files_.find(to);
  if (replaced != files_.end()) --replaced->second->links;
  files_[to] = moved;
  return crashed_ ? (errno = EIO, -1) : 0;
}

int SimulatedFileSystem::unlink(const char* path) {
  auto found = files_.find(path);
  if (alive() && found == files_.end()) {
    errno = ENOENT;
    return -1;
  }
  if (!mutation_allowed()) return -1;
  --found->second->links;
  files_.erase(found);
  return crashed_ ? (errno = EIO, -1) : 0;
}

bool SimulatedFileSystem::list_directory(const char* directory, void (*visit)(void*, const char*),
                                         void* context) {
  if (!alive() || directory_ != directory) return false;
  for (const std::string& name : names()) visit(context, name.c_str());
  return true;
}

}  // namespace reliability
