// POSIX file helpers. Every call retries EINTR; every failure reports errno's text.
#include "file_io.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "file_system.hpp"
#include "record.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {
namespace {

// Closes the descriptor on scope exit unless released.
class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  ~FdGuard() {
    if (fd_ >= 0) file_system().close(fd_);
  }
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  int get() const { return fd_; }
  void reset(int fd) {
    if (fd_ >= 0) file_system().close(fd_);
    fd_ = fd;
  }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

int open_retrying(const char* path, int flags, mode_t mode = 0) {
  return file_system().open(path, flags, mode);
}

// Writes the directory holding `path` into `directory` ("." or "/" where that is it) and
// returns the final component of `path`; nullptr when the directory does not fit.
const char* split_directory(const char* path, char* directory, std::size_t size) {
  const char* slash = std::strrchr(path, '/');
  if (slash == nullptr) {
    std::strcpy(directory, ".");
    return path;
  }
  const std::size_t length = slash == path ? 1 : static_cast<std::size_t>(slash - path);
  if (length >= size) return nullptr;
  std::memcpy(directory, path, length);
  directory[length] = '\0';
  return slash + 1;
}

// "<base>.tmp.<pid>.<n>" for `base`: the pid, or -1 when `name` is not of that form.
long temp_file_pid(const char* name, const char* base, std::size_t base_length) {
  static constexpr char kTag[] = ".tmp.";
  if (std::strncmp(name, base, base_length) != 0) return -1;
  const char* p = name + base_length;
  if (std::strncmp(p, kTag, sizeof kTag - 1) != 0) return -1;
  p += sizeof kTag - 1;
  char* end = nullptr;
  errno = 0;
  const long pid = std::strtol(p, &end, 10);
  if (end == p || *end != '.' || errno != 0 || pid <= 0) return -1;
  p = end + 1;
  if (*p == '\0') return -1;
  for (; *p != '\0'; ++p) {
    if (*p < '0' || *p > '9') return -1;
  }
  return pid;
}

// Removes, once per path and thread, what remove_stale_temp_files() would: a steady stream of
// checkpoints of one path reads the directory once.
void remove_stale_temp_files_once(const char* path) {
  thread_local char last_cleaned[PATH_MAX] = {};
  if (std::strcmp(last_cleaned, path) == 0) return;
  const std::size_t length = std::strlen(path);
  if (length >= sizeof last_cleaned) return;
  std::memcpy(last_cleaned, path, length + 1);
  remove_stale_temp_files(path);
}

}  // namespace

__attribute__((cold)) Status io_error(const char* what, const char* path, int error_number) {
  char text[96];
  // GNU strerror_r: returns the message, which may or may not live in `text`.
  const char* message = strerror_r(error_number, text, sizeof text);
  return Status(Error::Io, "%s %s: %s", what, path, message);
}

__attribute__((cold)) Status open_error(const char* what, const char* path, int error_number) {
  if (error_number == ELOOP) {
    return Status(Error::Io, "%s %s: it is a symbolic link, which symcr does not follow", what,
                  path);
  }
  return io_error(what, path, error_number);
}

void remove_stale_temp_files(const char* path) {
  char directory[PATH_MAX];
  const char* base = split_directory(path, directory, sizeof directory);
  if (base == nullptr) return;
  struct Listing {
    const char* directory;
    const char* base;
    std::size_t base_length;
    long own_pid;
  } listing{directory, base, std::strlen(base), file_system().process_id()};
  file_system().list_directory(
      directory,
      [](void* context, const char* name) {
        const Listing& l = *static_cast<const Listing*>(context);
        const long pid = temp_file_pid(name, l.base, l.base_length);
        // Our own pid: another thread of this process may be writing that file right now.
        if (pid <= 0 || pid == l.own_pid || file_system().process_exists(pid)) return;
        char temp[PATH_MAX];
        const int n = std::snprintf(temp, sizeof temp, "%s/%s", l.directory, name);
        if (n <= 0 || static_cast<std::size_t>(n) >= sizeof temp) return;
        struct stat info {};
        if (file_system().lstat(temp, &info) != 0) return;
        if (!S_ISREG(info.st_mode) || info.st_uid != ::geteuid()) return;
        file_system().unlink(temp);
      },
      &listing);
}

Status pwrite_all(int fd, const void* data, std::size_t size, off_t offset, const char* path) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  while (size > 0) {
    const ssize_t written = file_system().pwrite(fd, p, size, offset);
    if (written < 0) {
      if (errno == EINTR) continue;
      return io_error("cannot write", path, errno);
    }
    if (written == 0) return io_error("cannot write", path, EIO);
    p += written;
    size -= static_cast<std::size_t>(written);
    offset += written;
  }
  return Status();
}

Status pread_full(int fd, void* data, std::size_t size, off_t offset, std::size_t& got,
                  const char* path) {
  auto* p = static_cast<std::uint8_t*>(data);
  got = 0;
  while (got < size) {
    const ssize_t n =
        file_system().pread(fd, p + got, size - got, offset + static_cast<off_t>(got));
    if (n < 0) {
      if (errno == EINTR) continue;
      return io_error("cannot read", path, errno);
    }
    if (n == 0) break;  // end of file
    got += static_cast<std::size_t>(n);
  }
  return Status();
}

namespace {

// Opens `path` for reading: never through a symlink as the final component, never waiting on a
// FIFO, and only a regular file.
Status open_regular_file(const char* path, FdGuard& fd, struct stat& info) {
  // O_NONBLOCK: opening a FIFO must not hang; it is refused just below.
  fd.reset(open_retrying(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK));
  if (fd.get() < 0) return open_error("cannot open", path, errno);
  if (file_system().fstat(fd.get(), &info) != 0) return io_error("cannot stat", path, errno);
  if (!S_ISREG(info.st_mode)) return Status(Error::Io, "%s is not a regular file", path);
  return Status();
}

}  // namespace

Status read_regular_file(const char* path, std::uint64_t max_size, std::vector<std::uint8_t>& out) {
  FdGuard fd(-1);
  struct stat info {};
  Status opened = open_regular_file(path, fd, info);
  if (!opened.ok()) return opened;
  if (static_cast<std::uint64_t>(info.st_size) > max_size) {
    return Status(Error::TooLarge, "%s has %lld bytes, more than the %llu such a file can have",
                  path, static_cast<long long>(info.st_size),
                  static_cast<unsigned long long>(max_size));
  }
  // Read to end of file rather than trusting st_size, which can change under us.
  out.resize(static_cast<std::size_t>(info.st_size) + 1);
  std::size_t total = 0;
  for (;;) {
    if (total == out.size()) {
      if (total > max_size) break;  // grew past the limit while we read; caught below
      out.resize(out.size() * 2);
    }
    std::size_t got = 0;
    Status status = pread_full(fd.get(), out.data() + total, out.size() - total,
                               static_cast<off_t>(total), got, path);
    if (!status.ok()) return status;
    total += got;
    if (total < out.size()) break;  // short read: end of file
  }
  if (total > max_size) {
    return Status(Error::TooLarge, "%s grew past %llu bytes while being read", path,
                  static_cast<unsigned long long>(max_size));
  }
  out.resize(total);
  return Status();
}

Status read_record_file(const char* path, std::vector<std::uint8_t>& out, std::uint64_t& trailing) {
  trailing = 0;
  FdGuard fd(-1);
  struct stat info {};
  Status status = open_regular_file(path, fd, info);
  if (!status.ok()) return status;
  const auto file_size = static_cast<std::uint64_t>(info.st_size);
  out.resize(
      static_cast<std::size_t>(std::min<std::uint64_t>(file_size, format::kRecordHeaderSize)));
  std::size_t got = 0;
  status = pread_full(fd.get(), out.data(), out.size(), 0, got, path);
  if (!status.ok()) return status;
  out.resize(got);
  // Only a header the parser would accept says how long the record is; any other head is all
  // the parser needs to refuse the file.
  format::RecordHeader header;
  if (format::decode_record_header(out.data(), got, &header) != format::HeaderFault::None) {
    return Status();
  }
  const std::uint64_t record_size = format::claimed_record_size(header);
  if (file_size > record_size) {
    trailing = file_size - record_size;
    return Status(Error::Corrupt, "%s: %llu unexpected bytes after the %llu-byte record", path,
                  static_cast<unsigned long long>(trailing),
                  static_cast<unsigned long long>(record_size));
  }
  // A file shorter than its record is read whole (the parser says how much is missing); it
  // never grows the read past the record, whatever is appended meanwhile.
  out.resize(static_cast<std::size_t>(file_size));
  std::size_t rest = 0;
  status =
      pread_full(fd.get(), out.data() + got, out.size() - got, static_cast<off_t>(got), rest, path);
  if (!status.ok()) return status;
  out.resize(got + rest);
  return Status();
}

bool temp_path_for(const char* path, unsigned attempt, char* out, std::size_t out_size) {
  const int n =
      std::snprintf(out, out_size, "%s.tmp.%ld.%u", path, file_system().process_id(), attempt);
  return n > 0 && static_cast<std::size_t>(n) < out_size;
}

Status create_temp_file(const char* path, int access, char* temp, std::size_t temp_size, int& fd) {
  constexpr unsigned kAttempts = 100;
  fd = -1;
  for (unsigned attempt = 0; attempt < kAttempts && fd < 0; ++attempt) {
    if (!temp_path_for(path, attempt, temp, temp_size)) {
      return io_error("cannot create a temp file for", path, ENAMETOOLONG);
    }
    fd = open_retrying(temp, access | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0 && errno != EEXIST) return io_error("cannot create", temp, errno);
  }
  if (fd < 0) return io_error("cannot create a temp file for", path, EEXIST);
  return Status();
}

Status write_file_atomically(const char* path, const std::uint8_t* data, std::size_t size,
                             Durability durability) {
  struct stat existing {};
  if (file_system().lstat(path, &existing) == 0) {
    if (S_ISLNK(existing.st_mode)) {
      return Status(Error::Io, "refusing to replace %s: it is a symbolic link", path);
    }
    // A FIFO, a device node (/dev/null) or a socket is never replaced by a checkpoint.
    if (!S_ISREG(existing.st_mode)) {
      return Status(Error::Io, "refusing to replace %s: it is not a regular file", path);
    }
  }
  remove_stale_temp_files_once(path);

  char temp[PATH_MAX];
  int fd = -1;
  Status status = create_temp_file(path, O_WRONLY, temp, sizeof temp, fd);
  if (!status.ok()) return status;

  FdGuard guard(fd);
  status = pwrite_all(fd, data, size, 0, temp);
  if (status.ok() && durability == Durability::Fdatasync && file_system().fdatasync(fd) != 0) {
    status = io_error("cannot fdatasync", temp, errno);
  }
  // close() reports delayed write errors on some file systems (NFS): check it.
  if (file_system().close(guard.release()) != 0 && status.ok()) {
    status = io_error("cannot close", temp, errno);
  }
  if (status.ok() && file_system().rename(temp, path) != 0) {
    status = io_error("cannot rename the temp file onto", path, errno);
  }
  if (!status.ok()) {
    file_system().unlink(temp);
    return status;
  }
  if (durability == Durability::Fdatasync) return sync_parent_directory(path);
  return Status();
}

Status sync_parent_directory(const char* path) {
  char directory[PATH_MAX];
  if (split_directory(path, directory, sizeof directory) == nullptr) {
    return io_error("cannot sync the directory of", path, ENAMETOOLONG);
  }
  FdGuard fd(open_retrying(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) return io_error("cannot open directory", directory, errno);
  if (file_system().fsync(fd.get()) != 0)
    return io_error("cannot fsync directory", directory, errno);
  return Status();
}

}  // namespace symcr::detail
