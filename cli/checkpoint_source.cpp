// Loading checkpoints for the CLI from files and store slots.
#include "checkpoint_source.hpp"

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "authentication.hpp"
#include "file_io.hpp"
#include "header_fields.hpp"
#include "parsed_schema.hpp"
#include "schema_file.hpp"
#include "store_survey.hpp"
#include "values.hpp"

namespace symcr::cli {
namespace {

Status with_path(const std::string& path, const Status& status) {
  if (status.ok() || std::strncmp(status.message(), path.c_str(), path.size()) == 0) {
    return status;  // already names the file
  }
  return Status(status.error(), "%s: %s", path.c_str(), status.message());
}

}  // namespace

std::string resolve_links(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : path;
}

Status detect_file_kind(const std::string& path, FileKind& out) {
  // O_NONBLOCK: a FIFO must be refused, not waited on for a writer. O_NOFOLLOW: a program
  // refuses a checkpoint or store behind a symlink, so the CLI does too.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOFOLLOW);
  if (fd < 0 && errno == ELOOP) {
    const Status refused = detail::open_error("cannot open", path.c_str(), ELOOP);
    return Status(Error::Io, "%s; a program refuses it too: give the path it points to, %s",
                  refused.message(), resolve_links(path).c_str());
  }
  if (fd < 0) return detail::open_error("cannot open", path.c_str(), errno);
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int error_number = errno;
    ::close(fd);
    return detail::io_error("cannot stat", path.c_str(), error_number);
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    return Status(Error::Io, "%s is not a regular file", path.c_str());
  }
  std::uint8_t magic[8] = {};
  std::size_t got = 0;
  const Status status = detail::pread_full(fd, magic, sizeof magic, 0, got, path.c_str());
  ::close(fd);
  if (!status.ok()) return status;
  if (detail::looks_like_store(magic, got)) {
    out = FileKind::Store;
    return Status();
  }
  if (got == sizeof magic && std::memcmp(magic, symcr::format::kRecordMagic, sizeof magic) == 0) {
    out = FileKind::Record;
    return Status();
  }
  if (got < sizeof magic &&
      std::memcmp(magic, symcr::format::kRecordMagic, got) == 0) {  // a checkpoint cut short
    out = FileKind::Record;
    return Status();
  }
  // A store whose header is damaged, magic included, is still restored by a program from the
  // checkpoints its open finds by scanning: so is it read here.
  detail::StoreReader salvaged;
  if (salvaged.open(path.c_str()).ok() && !salvaged.salvaged().empty()) {
    out = FileKind::Store;
    return Status();
  }
  return Status(Error::NotACheckpoint, "%s is not a symcr checkpoint or store (bad magic)",
                path.c_str());
}

Status load_record_file(const std::string& path, LoadedCheckpoint& out,
                        const std::string& writer_schema) {
  out.path = path;
  out.from_store = false;
  std::uint64_t trailing = 0;
  Status status = detail::read_record_file(path.c_str(), out.bytes, trailing);
  if (!status.ok()) return with_path(path, status);
  status = detail::parse_record(out.bytes.data(), out.bytes.size(), out.record);
  if (!status.ok()) return with_path(path, status);
  if (out.record.schema == nullptr && writer_schema.empty()) {
    return Status(Error::SchemaUnknown,
                  "%s: the record references schema %016llx by hash (a store slot's or a "
                  "device's record) and carries no schema of its own: give the schema file of "
                  "the build that wrote it (--writer-schema)",
                  path.c_str(), static_cast<unsigned long long>(out.record.header.schema_hash));
  }
  if (out.record.schema == nullptr) {
    status = detail::read_schema_file(resolve_links(writer_schema).c_str(), out.inline_schema);
    if (!status.ok()) return status;
    if (out.inline_schema.hash() != out.record.header.schema_hash) {
      return Status(Error::SchemaUnknown,
                    "%s names schema %016llx, but %s is schema %016llx: not the build that "
                    "wrote it",
                    path.c_str(), static_cast<unsigned long long>(out.record.header.schema_hash),
                    writer_schema.c_str(),
                    static_cast<unsigned long long>(out.inline_schema.hash()));
    }
  } else {
    status =
        detail::parse_schema(out.record.schema, out.record.header.schema_size, out.inline_schema);
    if (!status.ok()) return with_path(path, status);
  }
  out.writer = &out.inline_schema.schema();
  out.writer_hash = out.record.header.schema_hash;
  return Status();
}

Status load_checkpoint(const std::string& path, std::optional<std::uint32_t> slot,
                       LoadedCheckpoint& out, const std::string& writer_schema) {
  FileKind kind = FileKind::Record;  // set on success; g++ -O3 cannot tell it is
  Status status = detect_file_kind(path, kind);
  if (!status.ok()) return status;
  if (kind == FileKind::Record) {
    if (slot) {
      return Status(Error::Io, "%s is a single-file checkpoint, which has no slots", path.c_str());
    }
    status = load_record_file(path, out, writer_schema);
    if (!status.ok()) return status;
    if (out.record.payload_size == 0) {
      return Status(Error::Corrupt, "%s is a schema file, which holds no values", path.c_str());
    }
    return with_path(path, check_payload(*out.writer, out.record.payload, out.record.payload_size));
  }

  out.path = path;
  out.from_store = true;
  out.store.reset(new detail::StoreReader());
  status = out.store->open(path.c_str(), counter_file_of(path).c_str());
  if (!status.ok()) return status;
  std::uint32_t index = 0;
  if (slot) {
    index = *slot;
  } else {
    const StoreSurvey survey = survey_store(*out.store);
    out.skipped = survey.skipped;
    if (!survey.restore_latest_slot) {
      out.restores_nothing = survey.restores_nothing_by_choice;
      return Status(survey.rolled_back ? Error::RolledBack : Error::NoValidSlot, "%s: %s",
                    path.c_str(), survey.nothing_restored.c_str());
    }
    index = *survey.restore_latest_slot;
  }
  int area_index = -1;
  status = out.store->read_record(index, out.bytes, out.record, area_index);
  if (status.ok()) {
    const detail::StoreSchemaArea& area = out.store->area(area_index);
    out.writer = &area.schema();
    out.writer_hash = area.hash;
    out.slot = index;
    out.area = area_index;
    status = check_payload(*out.writer, out.record.payload, out.record.payload_size);
  }
  if (!status.ok()) {
    out.writer = nullptr;
    return Status(status.error(), "%s: slot %u: %s", path.c_str(), index, status.message());
  }
  return Status();
}

Status use_key_files(const std::vector<KeyFile>& keys) {
  if (keys.empty()) return Status();
  std::vector<std::vector<std::uint8_t>> bytes(keys.size());
  std::vector<CheckpointKey> ring;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Status read =
        detail::read_regular_file(resolve_links(keys[i].path).c_str(), 1 << 16, bytes[i]);
    if (!read.ok()) return Status(read.error(), "--key-file: %s", read.message());
    ring.push_back(CheckpointKey{keys[i].id, bytes[i].data(), bytes[i].size()});
  }
  const Status set = set_checkpoint_keys(ring.data(), ring.size());
  if (!set.ok()) return Status(set.error(), "--key-file: %s", set.message());
  return Status();
}

Status read_key_ring(const std::string& path, std::vector<KeyFile>& keys) {
  std::vector<std::uint8_t> bytes;
  const Status read = detail::read_regular_file(resolve_links(path).c_str(), 1 << 20, bytes);
  if (!read.ok()) return Status(read.error(), "--key-ring: %s", read.message());
  const std::string text(bytes.begin(), bytes.end());
  const std::size_t slash = path.rfind('/');
  const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::size_t line_start = 0;
  for (unsigned line = 1; line_start < text.size(); ++line) {
    std::size_t end = text.find('\n', line_start);
    if (end == std::string::npos) end = text.size();
    std::string entry = text.substr(line_start, end - line_start);
    line_start = end + 1;
    const std::size_t hash = entry.find('#');
    if (hash != std::string::npos) entry.erase(hash);
    const std::size_t first = entry.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const std::size_t id_end = entry.find_first_of(" \t", first);
    const std::size_t file =
        id_end == std::string::npos ? std::string::npos : entry.find_first_not_of(" \t", id_end);
    const std::string id = entry.substr(first, id_end - first);
    char* parsed_end = nullptr;
    const unsigned long value = std::strtoul(id.c_str(), &parsed_end, 10);
    if (file == std::string::npos || id.empty() || *parsed_end != '\0' || value > UINT32_MAX) {
      return Status(Error::Corrupt,
                    "--key-ring %s: line %u is not \"<id> <key file>\" (an id of 0 to "
                    "4294967295)",
                    path.c_str(), line);
    }
    std::string key_path = entry.substr(file);
    key_path.erase(key_path.find_last_not_of(" \t\r") + 1);
    if (key_path[0] != '/') key_path = directory + key_path;
    keys.push_back({static_cast<std::uint32_t>(value), key_path});
  }
  return Status();
}

Status check_authentic(const LoadedCheckpoint& checkpoint) {
  const detail::KeySnapshot keys = detail::current_keys();
  const std::uint8_t* record = checkpoint.bytes.data();
  return checkpoint.from_store
             ? detail::check_authentication(
                   keys.get(), record, checkpoint.record,
                   checkpoint.store->binding(checkpoint.slot, checkpoint.area))
             : detail::check_standalone_authentication(keys.get(), record, checkpoint.record);
}

std::string describe_checkpoint(const LoadedCheckpoint& c) {
  std::string text = c.path;
  if (c.from_store) text += " slot " + std::to_string(c.slot);
  text += " (sequence " + std::to_string(c.record.header.sequence) + ", " +
          utc_iso8601(c.record.header.timestamp_ns) + ", schema " + hex64(c.writer_hash) + ")";
  return text;
}

}  // namespace symcr::cli
