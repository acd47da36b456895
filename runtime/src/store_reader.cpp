// StoreReader (store_reader.hpp). Mirrors the validation rules of store.cpp, which keeps its
// own copy for the writing side; docs/format.md §4 is the contract both follow.
#include "store_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "crc32c.hpp"
#include "file_io.hpp"
#include "little_endian.hpp"

namespace symcr::detail {
namespace {

constexpr std::uint64_t kPageSize = 4096;
constexpr std::size_t kStoreHeaderSize = 36;   // 32 bytes of fields + their CRC
constexpr std::size_t kAreaHeaderSize = 16;    // u64 hash, u32 size, u32 crc
constexpr std::uint32_t kMaxSlots = 1u << 20;
constexpr std::uint32_t kMinSlotSize = 2 * kRecordHeaderSize;
constexpr std::uint32_t kMaxSlotSize = 1u << 30;

bool all_zero(const std::uint8_t* p, std::size_t n) {
  return std::all_of(p, p + n, [](std::uint8_t b) { return b == 0; });
}

}  // namespace

const char* store_slot_state_name(StoreSlotState state) {
  switch (state) {
    case StoreSlotState::Valid: return "valid";
    case StoreSlotState::Empty: return "empty";
    case StoreSlotState::Corrupt: return "corrupt";
    case StoreSlotState::UnknownSchema: return "unknown-schema";
    case StoreSlotState::FutureVersion: return "future-version";
  }
  return "?";
}

bool looks_like_store(const std::uint8_t* data, std::size_t size) {
  return size >= sizeof kStoreFileMagic &&
         std::memcmp(data, kStoreFileMagic, sizeof kStoreFileMagic) == 0;
}

StoreReader::~StoreReader() {
  if (fd_ >= 0) ::close(fd_);
}

Status StoreReader::open(const char* path) {
  path_ = path;
  fd_ = ::open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd_ < 0) return io_error("cannot open store", path, errno);
  struct stat info {};
  if (::fstat(fd_, &info) != 0) return io_error("cannot stat", path, errno);
  if (!S_ISREG(info.st_mode)) return Status(Error::Io, "%s is not a regular file", path);

  std::uint8_t h[kStoreHeaderSize] = {};
  std::size_t got = 0;
  Status status = pread_full(fd_, h, sizeof h, 0, got, path);
  if (!status.ok()) return status;
  if (got < sizeof kStoreFileMagic || std::memcmp(h, kStoreFileMagic, 8) != 0) {
    return Status(Error::NotACheckpoint, "%s is not a symcr store (bad magic)", path);
  }
  if (got < kStoreHeaderSize) return Status(Error::Truncated, "%s: store header truncated", path);
  const std::uint16_t version = le::load16(h + 8);
  if (version > kStoreFileFormatVersion) {
    return Status(Error::FutureVersion,
                  "%s was written by store format version %u; this build reads up to %u", path,
                  unsigned{version}, unsigned{kStoreFileFormatVersion});
  }
  if (le::load32(h + 32) != crc32c(h, 32)) {
    return Status(Error::Checksum, "%s: store header checksum mismatch", path);
  }
  StoreGeometry& g = geometry_;
  g.slot_count = le::load32(h + 12);
  g.slot_size = le::load32(h + 16);
  g.schema_area_size = le::load32(h + 20);
  g.slots_offset = le::load64(h + 24);
  if (version == 0 || g.slot_count < 2 || g.slot_count > kMaxSlots ||
      g.slot_size < kMinSlotSize || g.slot_size > kMaxSlotSize ||
      g.schema_area_size <= kAreaHeaderSize || g.schema_area_size % kPageSize != 0 ||
      g.slots_offset != kPageSize + 2 * std::uint64_t{g.schema_area_size}) {
    return Status(Error::Corrupt, "%s: invalid store header", path);
  }
  const std::uint64_t file_size = g.slots_offset + std::uint64_t{g.slot_count} * g.slot_size;
  if (static_cast<std::uint64_t>(info.st_size) < file_size) {
    return Status(Error::Truncated, "%s: %lld bytes, the store's geometry needs %llu", path,
                  static_cast<long long>(info.st_size),
                  static_cast<unsigned long long>(file_size));
  }
  for (int i = 0; i < 2; ++i) {
    status = load_area(i);
    if (!status.ok()) return status;
  }
  slots_.assign(g.slot_count, StoreSlot());
  std::vector<std::uint8_t> bytes;
  RecordView view;
  for (std::uint32_t i = 0; i < g.slot_count; ++i) {
    status = classify_slot(i, bytes, view, slots_[i]);
    if (!status.ok()) return status;
  }
  return Status();
}

Status StoreReader::load_area(int index) {
  StoreSchemaArea& area = areas_[index];
  area = StoreSchemaArea();
  const off_t offset = static_cast<off_t>(kPageSize + std::uint64_t(index) * geometry_.schema_area_size);
  std::uint8_t head[kAreaHeaderSize];
  std::size_t got = 0;
  Status status = pread_full(fd_, head, sizeof head, offset, got, path_.c_str());
  if (!status.ok()) return status;
  const std::uint32_t size = le::load32(head + 8);
  if (got < sizeof head || size == 0 || size > geometry_.schema_area_size - kAreaHeaderSize) {
    return Status();  // empty or damaged: no schema here
  }
  std::vector<std::uint8_t> bytes(size);
  status = pread_full(fd_, bytes.data(), size, offset + static_cast<off_t>(kAreaHeaderSize), got,
                      path_.c_str());
  if (!status.ok()) return status;
  const std::uint64_t hash = le::load64(head);
  const std::uint32_t crc = crc32c_extend(crc32c(head, 12), bytes.data(), size);
  if (got < size || crc != le::load32(head + 12) || fnv1a64(bytes.data(), size) != hash ||
      !parse_schema(bytes.data(), size, area.schema).ok()) {
    area = StoreSchemaArea();
    return Status();
  }
  area.valid = true;
  area.hash = hash;
  area.size = size;
  return Status();
}

Status StoreReader::classify_slot(std::uint32_t index, std::vector<std::uint8_t>& bytes,
                                  RecordView& view, StoreSlot& slot) const {
  slot = StoreSlot();
  const off_t offset = static_cast<off_t>(geometry_.slots_offset +
                                          std::uint64_t{index} * geometry_.slot_size);
  bytes.resize(kRecordHeaderSize);
  std::size_t got = 0;
  Status status = pread_full(fd_, bytes.data(), bytes.size(), offset, got, path_.c_str());
  if (!status.ok()) return status;
  if (got < kRecordHeaderSize || all_zero(bytes.data(), 8)) return Status();  // Empty
  // Read as much of the record as the header claims, bounded by the slot.
  const std::uint64_t claimed = std::uint64_t{le::load16(bytes.data() + 10)} +
                                le::load32(bytes.data() + 40) + le::load32(bytes.data() + 44);
  const std::size_t wanted = static_cast<std::size_t>(
      std::max<std::uint64_t>(kRecordHeaderSize, std::min<std::uint64_t>(claimed, geometry_.slot_size)));
  bytes.resize(wanted);
  if (wanted > got) {
    std::size_t more = 0;
    status = pread_full(fd_, bytes.data() + got, wanted - got, offset + static_cast<off_t>(got),
                        more, path_.c_str());
    if (!status.ok()) return status;
    got += more;
  }
  const Status parsed = parse_record(bytes.data(), got, view);
  if (!parsed.ok()) {
    slot.state = parsed.error() == Error::FutureVersion ? StoreSlotState::FutureVersion
                                                        : StoreSlotState::Corrupt;
    slot.problem = parsed;
    return Status();
  }
  slot.header = view.header;
  if (view.schema != nullptr) {
    slot.state = StoreSlotState::Corrupt;
    slot.problem = Status(Error::Corrupt, "a store slot's record carries an inline schema");
    return Status();
  }
  for (int i = 0; i < 2; ++i) {
    if (areas_[i].valid && areas_[i].hash == view.header.schema_hash) slot.area = i;
  }
  if (slot.area < 0) {
    slot.state = StoreSlotState::UnknownSchema;
    slot.problem = Status(Error::SchemaUnknown, "schema %016llx is in neither schema area",
                          static_cast<unsigned long long>(view.header.schema_hash));
    return Status();
  }
  slot.state = StoreSlotState::Valid;
  return Status();
}

std::vector<std::uint32_t> StoreReader::valid_slots_newest_first() const {
  std::vector<std::uint32_t> valid;
  for (std::uint32_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].state == StoreSlotState::Valid) valid.push_back(i);
  }
  std::stable_sort(valid.begin(), valid.end(), [this](std::uint32_t a, std::uint32_t b) {
    return slots_[a].header.sequence > slots_[b].header.sequence;
  });
  return valid;
}

Status StoreReader::read_record(std::uint32_t index, std::vector<std::uint8_t>& bytes,
                                RecordView& view, int& area) const {
  area = -1;
  if (index >= slots_.size()) {
    return Status(Error::Io, "%s has %zu slots; there is no slot %u", path_.c_str(),
                  slots_.size(), index);
  }
  StoreSlot slot;
  Status status = classify_slot(index, bytes, view, slot);
  if (!status.ok()) return status;
  if (slot.state == StoreSlotState::Empty) {
    return Status(Error::NoValidSlot, "slot %u is empty", index);
  }
  if (slot.state != StoreSlotState::Valid) return slot.problem;
  area = slot.area;
  return Status();
}

}  // namespace symcr::detail
