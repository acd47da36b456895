// POSIX file helpers for checkpoints and the store: errno-carrying statuses, complete reads and
// writes, and atomic replacement of a file that never follows a symlink.
#ifndef SYMCR_SRC_FILE_IO_HPP
#define SYMCR_SRC_FILE_IO_HPP

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "symcr/symcr.hpp"

namespace symcr::detail {

// Error::Io "<what> <path>: <strerror(error_number)>".
Status io_error(const char* what, const char* path, int error_number);
// An open's failure, as io_error; a symlink refused by O_NOFOLLOW (ELOOP) is named as such.
Status open_error(const char* what, const char* path, int error_number);

// Writes all `size` bytes at `offset` (retrying short writes and EINTR).
Status pwrite_all(int fd, const void* data, std::size_t size, off_t offset, const char* path);
// Reads up to `size` bytes at `offset`; `got` < size only at end of file.
Status pread_full(int fd, void* data, std::size_t size, off_t offset, std::size_t& got,
                  const char* path);

// Reads a whole regular file into `out` (capacity reused). Refuses a symlink as the final
// path component (O_NOFOLLOW) and anything but a regular file (FIFOs, devices), and a file
// larger than `max_size` (Error::TooLarge) before allocating for it.
Status read_regular_file(const char* path, std::uint64_t max_size, std::vector<std::uint8_t>& out);

// Reads the record at the start of regular file `path` into `out` (same refusals as
// read_regular_file), its header first: only the bytes that header gives the record are read,
// fewer when the file is shorter, and just the head when it does not decode (for the record
// parser to refuse), so a file's size never drives the allocation. Bytes after the record its
// header describes are never read: Corrupt "<path>: N unexpected bytes after the M-byte
// record", with N in `trailing` (0 otherwise) and the head in `out`.
Status read_record_file(const char* path, std::vector<std::uint8_t>& out, std::uint64_t& trailing);

// Temp file name for attempt `attempt` at replacing `path`: "<path>.tmp.<pid>.<attempt>".
// Returns false if it does not fit in `out`.
bool temp_path_for(const char* path, unsigned attempt, char* out, std::size_t out_size);

// Creates "<path>.tmp.<pid>.<n>" for the first free n, exclusively (O_CREAT|O_EXCL|O_NOFOLLOW,
// mode 0600, `access` being O_WRONLY or O_RDWR): its name goes into `temp`, its descriptor
// into `fd`. An existing file or symlink of that name is never reused or followed.
Status create_temp_file(const char* path, int access, char* temp, std::size_t temp_size, int& fd);

// Replaces `path` with `data` atomically: writes a new temp file in the same directory,
// created exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, mode 0600; an existing temp name is never
// reused or followed), optionally fdatasyncs it, renames it over `path`, and with Fdatasync
// also syncs the directory. Refuses if `path` is a symlink, so the link and what it points to
// both stay as they were. On failure `path` is unchanged and the temp file removed.
Status write_file_atomically(const char* path, const std::uint8_t* data, std::size_t size,
                             Durability durability);

// Removes the temp files ("<path>.tmp.<pid>.<n>") of replacing `path` that processes killed
// between creating and renaming them left behind: regular files of exactly that naming, owned
// by this user, whose process no longer exists.
void remove_stale_temp_files(const char* path);

// fsync of the directory holding `path`, making a rename or creation in it durable.
Status sync_parent_directory(const char* path);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_FILE_IO_HPP
