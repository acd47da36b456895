// The store's identity and the file-backed freshness counter (freshness.hpp).
#include "freshness.hpp"

#include <fcntl.h>
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "crc32c.hpp"
#include "file_io.hpp"
#include "file_system.hpp"
#include "record.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {
namespace {

using format::kCounterMagic;
using format::kStoreIdMagic;
constexpr char kCounterDomain[] = "symcr freshness counter";
constexpr std::uint64_t kCounterCopies[kCounterCopyCount] = {format::kCounterFirstCopyOffset,
                                                             format::kCounterSecondCopyOffset};
constexpr std::size_t kCounterSigned = format::kCounterMacOffset;  // what precedes the MAC
constexpr std::size_t kCounterCopySize = format::kCounterCopySize;
static_assert(kCounterSigned + format::kSha256Size == kCounterCopySize, "an HMAC-SHA-256 ends it");

bool fill_random(std::uint8_t* out, std::size_t size) {
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = getrandom(out + got, size - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got == size) return true;
  const int fd = ::open("/dev/urandom", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::size_t read_bytes = 0;
  const bool ok =
      pread_full(fd, out, size, 0, read_bytes, "/dev/urandom").ok() && read_bytes == size;
  ::close(fd);
  return ok;
}

void encode_counter_copy(std::uint64_t value, const std::uint8_t* store_id, const OwnedKey& key,
                         std::uint8_t* out) {
  std::memcpy(out, kCounterMagic, sizeof kCounterMagic);
  format::store32(out + format::kCounterKeyIdOffset, key.id);
  format::store32(out + format::kCounterReservedOffset, 0);
  format::store64(out + format::kCounterValueOffset, value);
  std::memcpy(out + format::kCounterStoreIdOffset, store_id, kStoreIdSize);
  std::uint8_t mac[format::kSha256Size];
  store_item_mac(key, kCounterDomain, store_id, out, kCounterSigned, mac);
  std::memcpy(out + kCounterSigned, mac, sizeof mac);
}

}  // namespace

void new_store_id(std::uint8_t (&id)[kStoreIdSize]) {
  if (fill_random(id, sizeof id)) return;
  // No entropy source: still distinct per store and process (identity, not a secret).
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  const std::uint64_t a = static_cast<std::uint64_t>(now.tv_sec) * 1000000000u +
                          static_cast<std::uint64_t>(now.tv_nsec);
  const std::uint64_t b = static_cast<std::uint64_t>(getpid()) ^ (a << 17);
  format::store64(id, a);
  format::store64(id + 8, b);
}

void encode_store_id(const std::uint8_t (&id)[kStoreIdSize], std::uint8_t* out) {
  std::memset(out, 0, kStoreIdBlockSize);
  for (const std::uint64_t at : {kStoreIdOffset, kStoreIdSecondCopy}) {
    std::uint8_t* copy = out + (at - kStoreIdOffset);
    std::memcpy(copy, kStoreIdMagic, sizeof kStoreIdMagic);
    std::memcpy(copy + sizeof kStoreIdMagic, id, kStoreIdSize);
    format::store32(copy + format::kStoreIdCrcOffset, crc32c(copy, format::kStoreIdCrcOffset));
  }
}

bool read_store_id(const std::uint8_t* page, std::size_t size, std::uint8_t (&id)[kStoreIdSize],
                   bool* both) {
  std::memset(id, 0, sizeof id);
  int holding = 0;
  for (const std::uint64_t at : {kStoreIdSecondCopy, kStoreIdOffset}) {  // the first one last
    if (size < at + kStoreIdCopySize) continue;
    const std::uint8_t* copy = page + at;
    if (std::memcmp(copy, kStoreIdMagic, sizeof kStoreIdMagic) != 0 ||
        format::load32(copy + format::kStoreIdCrcOffset) !=
            crc32c(copy, format::kStoreIdCrcOffset)) {
      continue;
    }
    std::memcpy(id, copy + sizeof kStoreIdMagic, kStoreIdSize);
    ++holding;
  }
  if (both != nullptr) *both = holding == 2;
  return holding != 0;
}

Status freshness_verdict(const char* path, std::uint64_t newest, std::uint64_t allowed,
                         const RestoreJournal& journal, std::uint64_t counted) {
  if (newest >= counted) return Status();
  if (journal.freshness >= counted) {
    if (allowed >= journal.newest) return Status();
    return Status(Error::RolledBack,
                  "%s: rolled back: the newest authenticated checkpoint its journal lets a start "
                  "restore is sequence %llu, but the journal was written when it held sequence "
                  "%llu: its newest checkpoints damaged; nothing restored",
                  path, static_cast<unsigned long long>(allowed),
                  static_cast<unsigned long long>(journal.newest));
  }
  return Status(Error::RolledBack,
                "%s: rolled back: its newest authenticated checkpoint is sequence %llu (journal "
                "freshness %llu), the freshness counter says %llu was written: an older copy, "
                "or its newest checkpoints damaged; nothing restored",
                path, static_cast<unsigned long long>(newest),
                static_cast<unsigned long long>(journal.freshness),
                static_cast<unsigned long long>(counted));
}

namespace {

// Whether the counter copy at `copy` is one, signed with a key of `keys` (its MAC covers the
// store identity it names); `why` says otherwise.
bool counter_copy_verifies(const std::uint8_t* copy, const KeyRing& keys, Status& why) {
  if (std::memcmp(copy, kCounterMagic, sizeof kCounterMagic) != 0) return false;
  const OwnedKey* key = keys.find(format::load32(copy + format::kCounterKeyIdOffset));
  if (key == nullptr) {
    why = Status(Error::RolledBack, "it is signed with key id %u, which this program does not hold",
                 format::load32(copy + format::kCounterKeyIdOffset));
    return false;
  }
  std::uint8_t mac[format::kSha256Size];
  store_item_mac(*key, kCounterDomain, copy + format::kCounterStoreIdOffset, copy, kCounterSigned,
                 mac);
  if (!format::equal_macs(mac, copy + kCounterSigned, format::kSha256Size)) {
    why = Status(Error::RolledBack, "its MAC does not verify: it was forged or damaged");
    return false;
  }
  return true;
}

}  // namespace

std::size_t store_ids_in_counter_file(const std::uint8_t* bytes, std::size_t size,
                                      const KeyRing& keys,
                                      std::uint8_t (&ids)[kCounterCopyCount][kStoreIdSize]) {
  Status ignored;
  std::size_t count = 0;
  for (const std::uint64_t at : kCounterCopies) {
    if (at + kCounterCopySize > size || !counter_copy_verifies(bytes + at, keys, ignored)) continue;
    const std::uint8_t* id = bytes + at + format::kCounterStoreIdOffset;
    if (count == 1 && std::memcmp(ids[0], id, kStoreIdSize) == 0) continue;
    std::memcpy(ids[count++], id, kStoreIdSize);
  }
  return count;
}

Status decode_counter_file(const std::uint8_t* bytes, std::size_t size,
                           const std::uint8_t* store_id, const KeyRing& keys,
                           std::uint64_t& value) {
  value = 0;
  Status why(Error::RolledBack, "it holds no counter");
  bool found = false;
  for (const std::uint64_t at : kCounterCopies) {
    if (at + kCounterCopySize > size) continue;
    const std::uint8_t* copy = bytes + at;
    if (!counter_copy_verifies(copy, keys, why)) continue;
    if (std::memcmp(copy + format::kCounterStoreIdOffset, store_id, kStoreIdSize) != 0) {
      why = Status(Error::RolledBack, "it is the counter of another store");
      continue;
    }
    const std::uint64_t copy_value = format::load64(copy + format::kCounterValueOffset);
    if (copy_value > format::kMaxRecordSequence) {
      why = Status(Error::RolledBack, "its value is beyond the sequence range");
      continue;
    }
    if (!found || copy_value > value) value = copy_value;
    found = true;
  }
  return found ? Status() : why;
}

Status check_counter_path(const char* counter, const struct stat& store, const char* store_path) {
  struct stat info {};
  if (file_system().lstat(counter, &info) != 0) {
    // No counter yet: the first save writes one, so its folder must be there. Refused now rather
    // than at every save (which would write its record and fail) and every restore (which
    // would find no counter and roll back).
    const char* slash = std::strrchr(counter, '/');
    const std::string folder = slash == nullptr
                                   ? std::string(".")
                                   : std::string(counter, slash == counter ? 1 : slash - counter);
    // The folder may be reached through a symlink: only the counter itself is never followed.
    struct stat folder_info {};
    if (file_system().stat(folder.c_str(), &folder_info) != 0 || !S_ISDIR(folder_info.st_mode)) {
      return Status(Error::Io,
                    "the freshness counter %s of store %s cannot be written: its folder %s does "
                    "not exist (create it, or name a file in an existing folder)",
                    counter, store_path, folder.c_str());
    }
    return Status();
  }
  if (info.st_dev == store.st_dev && info.st_ino == store.st_ino) {
    return Status(Error::Unsupported,
                  "the freshness counter %s is the store %s itself: name another file, where "
                  "whoever may write the store cannot",
                  counter, store_path);
  }
  if (!S_ISREG(info.st_mode)) {
    return Status(Error::Unsupported,
                  "the freshness counter %s of store %s is not a regular file (a directory, "
                  "device or symbolic link): name a file",
                  counter, store_path);
  }
  return Status();
}

FileFreshnessCounter::FileFreshnessCounter(std::string path,
                                           const std::uint8_t (&store_id)[kStoreIdSize],
                                           Durability durability)
    : path_(std::move(path)), durability_(durability) {
  std::memcpy(store_id_, store_id, sizeof store_id_);
}

Status FileFreshnessCounter::read_file(std::uint8_t (&bytes)[kCounterFileSize],
                                       std::size_t& got) const {
  got = 0;
  FileSystem& files = file_system();
  const int fd = files.open(path_.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0);
  if (fd < 0) {
    if (errno == ENOENT) {
      return Status(Error::RolledBack, "the freshness counter %s is missing", path_.c_str());
    }
    return io_error("cannot open the freshness counter", path_.c_str(), errno);
  }
  Status status = pread_full(fd, bytes, sizeof bytes, 0, got, path_.c_str());
  files.close(fd);
  return status;
}

std::size_t FileFreshnessCounter::store_ids(
    std::uint8_t (&ids)[kCounterCopyCount][kStoreIdSize]) const {
  std::uint8_t bytes[kCounterFileSize] = {};
  std::size_t got = 0;
  if (keys_ == nullptr || !read_file(bytes, got).ok()) return 0;
  return store_ids_in_counter_file(bytes, got, *keys_, ids);
}

void FileFreshnessCounter::use_store_id(const std::uint8_t (&id)[kStoreIdSize]) {
  std::memcpy(store_id_, id, sizeof store_id_);
  known_ = false;
}

Status FileFreshnessCounter::read(std::uint64_t& value) {
  value = 0;
  if (keys_ == nullptr) return Status(Error::Unauthenticated, "no keys to verify the counter");
  std::uint8_t bytes[kCounterFileSize] = {};
  std::size_t got = 0;
  Status status = read_file(bytes, got);
  if (!status.ok()) return status;
  status = decode_counter_file(bytes, got, store_id_, *keys_, value);
  if (!status.ok()) {
    return Status(Error::RolledBack, "the freshness counter %s cannot be trusted: %s",
                  path_.c_str(), status.message());
  }
  known_ = true;
  value_ = value;
  return Status();
}

Status FileFreshnessCounter::advance(std::uint64_t value) {
  if (keys_ == nullptr) return Status(Error::Unauthenticated, "no keys to sign the counter");
  if (!known_) {
    std::uint64_t current = 0;
    if (read(current).ok() && current >= value) return Status();
  } else if (value_ >= value) {
    return Status();
  }
  FileSystem& files = file_system();
  const int fd = files.open(path_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return io_error("cannot open the freshness counter", path_.c_str(), errno);
  std::uint8_t bytes[kCounterCopies[1] + kCounterCopySize] = {};
  for (const std::uint64_t at : kCounterCopies) {
    encode_counter_copy(value, store_id_, keys_->signing(), bytes + at);
  }
  Status status = pwrite_all(fd, bytes, sizeof bytes, 0, path_.c_str());
  if (status.ok() && durability_ == Durability::Fdatasync && files.fdatasync(fd) != 0) {
    status = io_error("cannot fdatasync", path_.c_str(), errno);
  }
  files.close(fd);
  if (!status.ok()) {
    known_ = false;
    return status;
  }
  known_ = true;
  value_ = value;
  return Status();
}

}  // namespace symcr::detail
