// The checkpoint store (docs/format.md §4): one preallocated file, a header page, two schema
// areas and a ring of fixed-size slots, each holding one record that references its schema by
// hash. save() is one pwrite of a whole record into the oldest slot; restore_latest() takes the
// newest slot that validates and falls back past torn or corrupt ones.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "crc32c.hpp"
#include "engine.hpp"
#include "file_io.hpp"
#include "little_endian.hpp"
#include "program_schema.hpp"
#include "record.hpp"
#include "symcr/symcr.hpp"

namespace symcr {
namespace {

constexpr std::uint8_t kStoreMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'S', 'T', 'O'};
constexpr std::uint16_t kStoreFormatVersion = 1;
constexpr std::size_t kStoreHeaderSize = 36;      // 32 bytes of fields + their CRC
constexpr std::uint64_t kPageSize = 4096;
constexpr std::uint64_t kSchemaAreasOffset = kPageSize;
constexpr std::size_t kAreaHeaderSize = 16;       // u64 hash, u32 size, u32 crc
constexpr std::uint32_t kMinSchemaAreaSize = 64 * 1024;
constexpr std::uint32_t kMaxSlots = 1u << 20;
constexpr std::uint32_t kMinSlotSize = 2 * detail::kRecordHeaderSize;
constexpr std::uint32_t kMaxSlotSize = 1u << 30;
// First read of a slot when scanning: one pread covers the header and a record of up to a page.
constexpr std::size_t kSlotFirstRead = 4096;

std::uint64_t round_up_to_page(std::uint64_t n) { return (n + kPageSize - 1) / kPageSize * kPageSize; }

struct Geometry {
  std::uint32_t slot_count = 0;
  std::uint32_t slot_size = 0;
  std::uint32_t schema_area_size = 0;
  std::uint64_t slots_offset = 0;

  std::uint64_t area_offset(int area) const {
    return kSchemaAreasOffset + static_cast<std::uint64_t>(area) * schema_area_size;
  }
  std::uint64_t slot_offset(std::uint32_t slot) const {
    return slots_offset + static_cast<std::uint64_t>(slot) * slot_size;
  }
  std::uint64_t file_size() const { return slot_offset(slot_count); }
};

// A new store leaves room for a later build's larger schema: four times this build's, and at
// least 64 KiB.
Geometry geometry_for(const StoreOptions& options, std::size_t schema_bytes) {
  Geometry g;
  g.slot_count = options.slots;
  g.slot_size = options.slot_size;
  const std::uint64_t wanted = 4 * (kAreaHeaderSize + std::uint64_t{schema_bytes});
  g.schema_area_size = static_cast<std::uint32_t>(
      round_up_to_page(std::max<std::uint64_t>(kMinSchemaAreaSize, wanted)));
  g.slots_offset = kSchemaAreasOffset + 2 * std::uint64_t{g.schema_area_size};
  return g;
}

void encode_store_header(const Geometry& g, std::uint8_t* p) {
  std::memset(p, 0, kStoreHeaderSize);
  std::memcpy(p, kStoreMagic, sizeof kStoreMagic);
  detail::le::store16(p + 8, kStoreFormatVersion);
  detail::le::store32(p + 12, g.slot_count);
  detail::le::store32(p + 16, g.slot_size);
  detail::le::store32(p + 20, g.schema_area_size);
  detail::le::store64(p + 24, g.slots_offset);
  detail::le::store32(p + 32, detail::crc32c(p, 32));
}

Status decode_store_header(const std::uint8_t* p, const char* path, Geometry& g) {
  if (std::memcmp(p, kStoreMagic, sizeof kStoreMagic) != 0) {
    return Status(Error::NotACheckpoint, "%s is not a symcr store (bad magic)", path);
  }
  const std::uint16_t version = detail::le::load16(p + 8);
  if (version > kStoreFormatVersion) {
    return Status(Error::FutureVersion,
                  "%s was written by store format version %u; this build reads up to %u", path,
                  unsigned{version}, unsigned{kStoreFormatVersion});
  }
  if (detail::le::load32(p + 32) != detail::crc32c(p, 32)) {
    return Status(Error::Checksum, "%s: store header checksum mismatch", path);
  }
  g.slot_count = detail::le::load32(p + 12);
  g.slot_size = detail::le::load32(p + 16);
  g.schema_area_size = detail::le::load32(p + 20);
  g.slots_offset = detail::le::load64(p + 24);
  if (version == 0 || g.slot_count < 2 || g.slot_count > kMaxSlots ||
      g.slot_size < kMinSlotSize || g.slot_size > kMaxSlotSize ||
      g.schema_area_size <= kAreaHeaderSize || g.schema_area_size % kPageSize != 0 ||
      g.slots_offset != kSchemaAreasOffset + 2 * std::uint64_t{g.schema_area_size}) {
    return Status(Error::Corrupt, "%s: invalid store header", path);
  }
  return Status();
}

Status validate_options(const StoreOptions& options) {
  if (options.slots < 2 || options.slots > kMaxSlots) {
    return Status(Error::TooLarge, "a store needs 2 to %u slots, not %u", kMaxSlots,
                  options.slots);
  }
  if (options.slot_size < kMinSlotSize || options.slot_size > kMaxSlotSize) {
    return Status(Error::TooLarge, "a store slot must have %u to %u bytes, not %u",
                  kMinSlotSize, kMaxSlotSize, options.slot_size);
  }
  return Status();
}

bool all_zero(const std::uint8_t* p, std::size_t n) {
  return std::all_of(p, p + n, [](std::uint8_t b) { return b == 0; });
}

// Why a slot does not hold a restorable checkpoint.
enum class SlotState : std::uint8_t { Valid, Empty, Corrupt, UnknownSchema, FutureVersion };

}  // namespace

struct Store::Impl {
  struct Area {
    bool valid = false;
    std::uint64_t hash = 0;
    detail::ParsedSchema schema;
  };
  struct Slot {
    SlotState state = SlotState::Empty;
    std::uint64_t sequence = 0;
    int area = -1;
  };

  std::string path;
  Geometry geometry;
  Area areas[2];
  int own_area = -1;       // the area holding this build's schema, once written or found
  std::vector<Slot> slots;
  std::vector<std::uint8_t> record;    // save(): the encoded record
  std::vector<std::uint8_t> slot_bytes;  // restore: one slot as read
  detail::RecordView view;                // of slot_bytes, when its slot is valid
  // The newest valid slot of the last scan, kept so restoring it needs no second read.
  std::vector<std::uint8_t> newest_bytes;
  detail::RecordView newest_view;
  int newest_scanned = -1;
  std::vector<std::uint32_t> newest_first;

  int area_for_hash(std::uint64_t hash) const {
    for (int i = 0; i < 2; ++i) {
      if (areas[i].valid && areas[i].hash == hash) return i;
    }
    return -1;
  }

  // The valid slot with the highest sequence, or -1.
  int newest_valid_slot() const {
    int newest = -1;
    for (std::uint32_t i = 0; i < slots.size(); ++i) {
      if (slots[i].state == SlotState::Valid &&
          (newest < 0 || slots[i].sequence > slots[static_cast<std::size_t>(newest)].sequence)) {
        newest = static_cast<int>(i);
      }
    }
    return newest;
  }

  // Reads slot `i` and classifies it; when Valid, `view` describes its record in slot_bytes.
  Status read_slot(int fd, std::uint32_t i, Slot& slot) {
    slot = Slot();
    const off_t offset = static_cast<off_t>(geometry.slot_offset(i));
    const std::size_t first = std::min<std::size_t>(geometry.slot_size, kSlotFirstRead);
    std::size_t got = 0;
    Status status = detail::pread_full(fd, slot_bytes.data(), first, offset, got, path.c_str());
    if (!status.ok()) return status;
    if (got < detail::kRecordHeaderSize || all_zero(slot_bytes.data(), 8)) return Status();
    // Read the rest of the record when the header claims more (bounded by the slot).
    const std::uint64_t claimed = std::uint64_t{detail::le::load16(slot_bytes.data() + 10)} +
                                  detail::le::load32(slot_bytes.data() + 40) +
                                  detail::le::load32(slot_bytes.data() + 44);
    const std::size_t wanted = static_cast<std::size_t>(
        std::min<std::uint64_t>(claimed, geometry.slot_size));
    if (wanted > got && got == first) {
      std::size_t more = 0;
      status = detail::pread_full(fd, slot_bytes.data() + got, wanted - got,
                                  offset + static_cast<off_t>(got), more, path.c_str());
      if (!status.ok()) return status;
      got += more;
    }
    const Status parsed = detail::parse_record(slot_bytes.data(), got, view);
    if (!parsed.ok()) {
      slot.state = parsed.error() == Error::FutureVersion ? SlotState::FutureVersion
                                                          : SlotState::Corrupt;
      return Status();
    }
    if (view.schema != nullptr) {  // store records reference their schema; never inline
      slot.state = SlotState::Corrupt;
      return Status();
    }
    slot.sequence = view.header.sequence;
    slot.area = area_for_hash(view.header.schema_hash);
    slot.state = slot.area < 0 ? SlotState::UnknownSchema : SlotState::Valid;
    return Status();
  }

  Status scan_slots(int fd) {
    newest_scanned = -1;
    for (std::uint32_t i = 0; i < geometry.slot_count; ++i) {
      Status status = read_slot(fd, i, slots[i]);
      if (!status.ok()) return status;
      if (slots[i].state == SlotState::Valid &&
          (newest_scanned < 0 ||
           slots[i].sequence > slots[static_cast<std::size_t>(newest_scanned)].sequence)) {
        // Swapping vectors moves no bytes: `view` keeps pointing at the same storage.
        std::swap(slot_bytes, newest_bytes);
        newest_view = view;
        newest_scanned = static_cast<int>(i);
      }
    }
    return Status();
  }

  void size_buffers() {
    slot_bytes.resize(geometry.slot_size);
    newest_bytes.resize(geometry.slot_size);
    newest_first.reserve(geometry.slot_count);
  }

  Status load_area(int fd, int i) {
    Area& area = areas[i];
    area = Area();
    std::uint8_t head[kAreaHeaderSize];
    std::size_t got = 0;
    Status status = detail::pread_full(fd, head, sizeof head,
                                       static_cast<off_t>(geometry.area_offset(i)), got,
                                       path.c_str());
    if (!status.ok()) return status;
    const std::uint32_t size = detail::le::load32(head + 8);
    if (got < sizeof head || size == 0 || size > geometry.schema_area_size - kAreaHeaderSize) {
      return Status();  // empty or damaged: no schema here
    }
    std::vector<std::uint8_t> bytes(size);
    status = detail::pread_full(fd, bytes.data(), size,
                                static_cast<off_t>(geometry.area_offset(i) + kAreaHeaderSize),
                                got, path.c_str());
    if (!status.ok()) return status;
    const std::uint64_t hash = detail::le::load64(head);
    const std::uint32_t crc = detail::crc32c_extend(detail::crc32c(head, 12), bytes.data(), size);
    if (got < size || crc != detail::le::load32(head + 12) ||
        detail::fnv1a64(bytes.data(), size) != hash ||
        !detail::parse_schema(bytes.data(), size, area.schema).ok()) {
      area = Area();
      return Status();
    }
    area.valid = true;
    area.hash = hash;
    return Status();
  }

  // Writes this build's schema into the area the newest valid slot does not use, so that
  // checkpoint stays restorable; slots using the overwritten area become unrestorable.
  Status write_own_area(int fd, const Schema& schema, Durability durability) {
    Status status = scan_slots(fd);  // the disk may have changed since open
    if (!status.ok()) return status;
    const int newest = newest_valid_slot();
    const int target = (newest >= 0 && slots[static_cast<std::size_t>(newest)].area == 0) ? 1 : 0;
    const detail::SchemaBlob& blob = detail::schema_blob(schema);
    if (kAreaHeaderSize + blob.bytes.size() > geometry.schema_area_size) {
      return Status(Error::TooLarge,
                    "%s: this build's schema (%zu bytes) does not fit the store's schema area "
                    "(%u bytes); remove the store to recreate it",
                    path.c_str(), blob.bytes.size(), geometry.schema_area_size);
    }
    std::vector<std::uint8_t> area_bytes(kAreaHeaderSize + blob.bytes.size());
    detail::le::store64(area_bytes.data(), blob.hash);
    detail::le::store32(area_bytes.data() + 8, static_cast<std::uint32_t>(blob.bytes.size()));
    std::memcpy(area_bytes.data() + kAreaHeaderSize, blob.bytes.data(), blob.bytes.size());
    detail::le::store32(area_bytes.data() + 12,
                        detail::crc32c_extend(detail::crc32c(area_bytes.data(), 12),
                                              blob.bytes.data(), blob.bytes.size()));
    // Forget the old area before overwriting it: a failed write leaves it unusable either way.
    areas[target] = Area();
    for (Slot& slot : slots) {
      if (slot.area == target) slot = Slot{SlotState::UnknownSchema, slot.sequence, -1};
    }
    status = detail::pwrite_all(fd, area_bytes.data(), area_bytes.size(),
                                static_cast<off_t>(geometry.area_offset(target)), path.c_str());
    if (status.ok() && durability == Durability::Fdatasync && ::fdatasync(fd) != 0) {
      status = detail::io_error("cannot fdatasync", path.c_str(), errno);
    }
    if (!status.ok()) return status;
    status = detail::parse_schema(blob.bytes.data(), blob.bytes.size(), areas[target].schema);
    if (!status.ok()) return status;
    areas[target].valid = true;
    areas[target].hash = blob.hash;
    own_area = target;
    return Status();
  }

  // Zero-filled, preallocated file with a header: every slot and area empty. The header is
  // written last, so an interrupted initialisation leaves a file that reads as blank.
  Status initialise(int fd) {
    if (::ftruncate(fd, 0) != 0) return detail::io_error("cannot truncate", path.c_str(), errno);
    const int rc = ::posix_fallocate(fd, 0, static_cast<off_t>(geometry.file_size()));
    if (rc != 0) return detail::io_error("cannot preallocate", path.c_str(), rc);
    std::uint8_t header[kStoreHeaderSize];
    encode_store_header(geometry, header);
    Status status = detail::pwrite_all(fd, header, sizeof header, 0, path.c_str());
    if (!status.ok()) return status;
    if (::fdatasync(fd) != 0) return detail::io_error("cannot fdatasync", path.c_str(), errno);
    for (Area& area : areas) area = Area();
    own_area = -1;
    slots.assign(geometry.slot_count, Slot());
    return Status();
  }
};

Store::~Store() { close(); }

Store::Store(Store&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      schema_(std::exchange(other.schema_, nullptr)),
      options_(other.options_),
      last_sequence_(std::exchange(other.last_sequence_, 0)),
      impl_(std::exchange(other.impl_, nullptr)) {}

Store& Store::operator=(Store&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    schema_ = std::exchange(other.schema_, nullptr);
    options_ = other.options_;
    last_sequence_ = std::exchange(other.last_sequence_, 0);
    impl_ = std::exchange(other.impl_, nullptr);
  }
  return *this;
}

void Store::close() {
  if (fd_ >= 0) ::close(fd_);  // also releases the flock
  fd_ = -1;
  delete impl_;
  impl_ = nullptr;
  schema_ = nullptr;
  last_sequence_ = 0;
}

Status Store::open(const char* path, const StoreOptions& options, Store& out) {
  const Schema* schema = nullptr;
  Status status = detail::program_schema(schema);
  if (!status.ok()) return status;
  return open(path, *schema, options, out);
}

Status Store::open(const char* path, const Schema& schema, const StoreOptions& options,
                   Store& out) {
  out.close();
  Status status = validate_options(options);
  if (!status.ok()) return status;
  const detail::SchemaBlob& blob = detail::schema_blob(schema);

  bool created = true;
  int fd = ::open(path, O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0 && errno == EEXIST) {
    created = false;
    fd = ::open(path, O_RDWR | O_NOFOLLOW | O_CLOEXEC);
  }
  if (fd < 0) {
    if (errno == ELOOP) {
      return Status(Error::Io, "cannot open store %s: it is a symbolic link, which symcr does "
                    "not follow", path);
    }
    return detail::io_error("cannot open store", path, errno);
  }
  // Adopt the descriptor now: every early return below closes it through `out`.
  out.fd_ = fd;
  out.impl_ = new Impl();
  Impl& impl = *out.impl_;
  impl.path = path;
  auto fail = [&out](const Status& failure) {
    out.close();
    return failure;
  };

  struct stat info {};
  if (::fstat(fd, &info) != 0) return fail(detail::io_error("cannot stat", path, errno));
  if (!S_ISREG(info.st_mode)) return fail(Status(Error::Io, "%s is not a regular file", path));
  // One writer per store: two processes saving into one ring would overwrite each other.
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EWOULDBLOCK) {
      return fail(Status(Error::Io, "store %s is open elsewhere (locked by another Store)",
                         path));
    }
    return fail(detail::io_error("cannot lock", path, errno));
  }

  std::uint8_t header[kStoreHeaderSize] = {};
  std::size_t got = 0;
  status = detail::pread_full(fd, header, sizeof header, 0, got, path);
  if (!status.ok()) return fail(status);
  const Geometry wanted = geometry_for(options, blob.bytes.size());
  // Blank: just created, or an initialisation that did not get to write its header.
  const bool blank = created || all_zero(header, got);
  if (blank) {
    impl.geometry = wanted;
  } else {
    if (got < kStoreHeaderSize) {
      return fail(Status(Error::Truncated, "%s: store header truncated", path));
    }
    status = decode_store_header(header, path, impl.geometry);
    if (!status.ok()) return fail(status);
    if (static_cast<std::uint64_t>(info.st_size) < impl.geometry.file_size()) {
      return fail(Status(Error::Truncated, "%s: %lld bytes, the store needs %llu", path,
                         static_cast<long long>(info.st_size),
                         static_cast<unsigned long long>(impl.geometry.file_size())));
    }
  }
  impl.slots.assign(impl.geometry.slot_count, Impl::Slot());
  impl.size_buffers();

  if (blank) {
    status = impl.initialise(fd);
    if (status.ok() && created) status = detail::sync_parent_directory(path);
    if (!status.ok()) return fail(status);
  } else {
    for (int i = 0; i < 2 && status.ok(); ++i) status = impl.load_area(fd, i);
    if (status.ok()) status = impl.scan_slots(fd);
    if (!status.ok()) return fail(status);
    const Geometry& existing = impl.geometry;
    if (existing.slot_count != wanted.slot_count || existing.slot_size != wanted.slot_size) {
      // Another geometry: keep a store that holds checkpoints, reuse one that holds none.
      if (impl.newest_valid_slot() >= 0) {
        return fail(Status(Error::Incompatible,
                           "store %s has %u slots of %u bytes holding checkpoints; %u slots of "
                           "%u bytes were requested (open it with its geometry or remove it)",
                           path, existing.slot_count, existing.slot_size, wanted.slot_count,
                           wanted.slot_size));
      }
      impl.geometry = wanted;
      impl.size_buffers();
      status = impl.initialise(fd);
      if (!status.ok()) return fail(status);
    }
  }
  impl.own_area = impl.area_for_hash(blob.hash);
  const int newest = impl.newest_valid_slot();
  out.last_sequence_ = newest >= 0 ? impl.slots[static_cast<std::size_t>(newest)].sequence : 0;
  out.schema_ = &schema;
  out.options_ = options;
  return Status();
}

Status Store::save() {
  if (!is_open()) return Status(Error::Io, "the store is not open");
  Impl& impl = *impl_;
  const std::uint64_t sequence = last_sequence_ + 1;
  Status status = detail::encode_record(*schema_, /*inline_schema=*/false, sequence, impl.record);
  if (!status.ok()) return status;
  if (impl.record.size() > impl.geometry.slot_size) {
    return Status(Error::TooLarge,
                  "%s: a checkpoint of %zu bytes does not fit a slot of %u bytes; nothing was "
                  "written (open the store with a larger slot_size)",
                  impl.path.c_str(), impl.record.size(), impl.geometry.slot_size);
  }
  if (impl.own_area < 0) {
    status = impl.write_own_area(fd_, *schema_, options_.durability);
    if (!status.ok()) return status;
  }
  // The oldest slot: an invalid one, else the lowest sequence. With two or more slots it is
  // never the newest valid one, so a torn write costs at most this checkpoint.
  std::uint32_t target = 0;
  for (std::uint32_t i = 0; i < impl.slots.size(); ++i) {
    if (impl.slots[i].state != SlotState::Valid) {
      target = i;
      break;
    }
    if (impl.slots[i].sequence < impl.slots[target].sequence) target = i;
  }
  Impl::Slot& slot = impl.slots[target];
  slot = Impl::Slot{SlotState::Corrupt, 0, -1};  // until the write completes
  status = detail::pwrite_all(fd_, impl.record.data(), impl.record.size(),
                              static_cast<off_t>(impl.geometry.slot_offset(target)),
                              impl.path.c_str());
  if (!status.ok()) return status;
  slot = Impl::Slot{SlotState::Valid, sequence, impl.own_area};
  last_sequence_ = sequence;
  if (options_.durability == Durability::Fdatasync && ::fdatasync(fd_) != 0) {
    return detail::io_error("cannot fdatasync", impl.path.c_str(), errno);
  }
  return Status();
}

Report Store::restore_latest(const RestoreOptions& options) {
  Report report;
  if (!is_open()) {
    report.set_status(Status(Error::Io, "the store is not open"));
    return report;
  }
  Impl& impl = *impl_;
  Status status = impl.scan_slots(fd_);
  if (!status.ok()) {
    report.set_status(status);
    return report;
  }
  impl.newest_first.clear();
  for (std::uint32_t i = 0; i < impl.slots.size(); ++i) {
    if (impl.slots[i].state == SlotState::Valid) impl.newest_first.push_back(i);
    if (impl.slots[i].state == SlotState::Valid && impl.slots[i].sequence > last_sequence_) {
      last_sequence_ = impl.slots[i].sequence;
    }
  }
  std::sort(impl.newest_first.begin(), impl.newest_first.end(),
            [&impl](std::uint32_t a, std::uint32_t b) {
              return impl.slots[a].sequence > impl.slots[b].sequence;
            });

  // Valid slots whose payload the engine still rejected as corrupt (after its CRC passed: a
  // writer bug or a collision), and the last such message.
  unsigned rejected = 0;
  Status last_rejection;
  for (const std::uint32_t i : impl.newest_first) {
    const detail::RecordView* record = &impl.newest_view;
    int area_index = impl.slots[i].area;
    if (static_cast<int>(i) != impl.newest_scanned) {  // a fallback: read it again
      Impl::Slot reread;
      status = impl.read_slot(fd_, i, reread);
      if (!status.ok()) {
        report.set_status(status);
        return report;
      }
      if (reread.state != SlotState::Valid) continue;
      record = &impl.view;
      area_index = reread.area;
    }
    const Impl::Area& area = impl.areas[area_index];
    report = detail::restore_record(*record, area.schema.schema(), area.hash, *schema_,
                                    options);
    const Error error = report.status().error();
    if (error != Error::Corrupt && error != Error::Truncated) return report;
    ++rejected;
    last_rejection = report.status();
  }

  unsigned empty = 0, corrupt = 0, unknown = 0, future = 0;
  for (const Impl::Slot& slot : impl.slots) {
    empty += slot.state == SlotState::Empty;
    corrupt += slot.state == SlotState::Corrupt;
    unknown += slot.state == SlotState::UnknownSchema;
    future += slot.state == SlotState::FutureVersion;
  }
  report.clear();
  report.set_status(Status(
      Error::NoValidSlot,
      "%s: no restorable checkpoint in %u slots (%u empty, %u corrupt or torn, %u with an "
      "unknown schema, %u from a future format, %u rejected by restore%s%s)",
      impl.path.c_str(), impl.geometry.slot_count, empty, corrupt, unknown, future, rejected,
      rejected ? ": " : "", rejected ? last_rejection.message() : ""));
  return report;
}

}  // namespace symcr
