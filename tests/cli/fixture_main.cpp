// The CLI fixture program: one build (v0, v1, ...) of a small program linking the runtime,
// used to produce real checkpoints, stores and schema files, and damaged copies of them.
//   fixture checkpoint <path> <seed>        single-file checkpoint
//   fixture signed <path> <seed>            the same, authenticated with the key of
//                                           id 7, whose bytes are "fixture-key"
//   fixture store <path> <saves>            4-slot store after <saves> saves (seeds 1..saves)
//   fixture store-more <path> <saves>       <saves> more saves into an existing store
//   fixture schema <path>                   this build's schema file
//   fixture flip <path> <offset>            invert one byte
//   fixture truncate <path> <size>          cut the file
//   fixture flip-newest-slot <path>         invert a payload byte of the store's newest slot
//   fixture restore-unconfirmed <path> <n>  <n> starts that restore from the store with the
//                                           crash-loop fallback (depth 3) and never confirm
//                                           (the fifth after four gives up: no restore)
//   fixture rotated-store <path>           4-slot store in the middle of a key rotation: two
//                                           saves signed with key id 7 ("fixture-key"), then
//                                           two with id 8 ("another-key") holding 7 as well
//   fixture signed-store <path> <saves>    <saves> more saves into a store (created if
//                                           missing), authenticated with key id 7: its
//                                           freshness counter is <path>.fresh
//   fixture flip-resign <path> <offset>     invert one byte of a single-file checkpoint, then
//                                           fix its schema hash and checksum: a hostile file
//                                           that passes the integrity checks
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "crc32c.hpp"
#include "file_io.hpp"
#include "fixture_tables.hpp"
#include "schema_blob.hpp"
#include "schema_file.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/symcr.hpp"

namespace {

int fail(const char* what, const symcr::Status& status) {
  std::fprintf(stderr, "fixture: %s: %s: %s\n", what, symcr::error_name(status.error()),
               status.message());
  return 1;
}

bool flip_byte(const char* path, long offset) {
  const int fd = ::open(path, O_RDWR);
  if (fd < 0) return false;
  unsigned char byte = 0;
  bool ok = ::pread(fd, &byte, 1, offset) == 1;
  byte = static_cast<unsigned char>(~byte);
  ok = ok && ::pwrite(fd, &byte, 1, offset) == 1;
  ::close(fd);
  return ok;
}

// The slot with the highest sequence among those whose record header has the magic.
bool flip_newest_slot(const char* path) {
  const int fd = ::open(path, O_RDONLY);
  if (fd < 0) return false;
  std::uint8_t header[36];
  bool ok = ::pread(fd, header, sizeof header, 0) == sizeof header;
  const std::uint32_t slot_count = symcr::format::load32(header + 12);
  const std::uint32_t slot_size = symcr::format::load32(header + 16);
  const std::uint64_t slots_offset = symcr::format::load64(header + 24);
  long newest_offset = -1;
  std::uint64_t newest_sequence = 0;
  for (std::uint32_t i = 0; ok && i < slot_count; ++i) {
    std::uint8_t record[56];
    const long offset = static_cast<long>(slots_offset + std::uint64_t{i} * slot_size);
    if (::pread(fd, record, sizeof record, offset) != sizeof record) ok = false;
    if (!ok || std::memcmp(record, "SYMCRCKP", 8) != 0) continue;
    const std::uint64_t sequence = symcr::format::load64(record + 16);
    if (newest_offset < 0 || sequence > newest_sequence) {
      newest_offset = offset;
      newest_sequence = sequence;
    }
  }
  ::close(fd);
  // 60: the fifth byte of the payload (store records carry no inline schema).
  return ok && newest_offset >= 0 && flip_byte(path, newest_offset + 60);
}

bool flip_and_resign(const char* path, long offset) {
  std::vector<std::uint8_t> bytes;
  if (!symcr::detail::read_regular_file(path, 1u << 30, bytes).ok()) return false;
  if (offset < 0 || static_cast<std::size_t>(offset) >= bytes.size() || bytes.size() < 56) {
    return false;
  }
  bytes[static_cast<std::size_t>(offset)] ^= 0xFF;
  using namespace symcr::detail;
  const std::uint16_t header_size = symcr::format::load16(bytes.data() + 10);
  const std::uint32_t schema_size = symcr::format::load32(bytes.data() + 40);
  if (std::size_t{header_size} + schema_size <= bytes.size()) {
    symcr::format::store64(bytes.data() + 32,
                           symcr::format::fnv1a64(bytes.data() + header_size, schema_size));
  }
  symcr::format::store32(bytes.data() + 48, 0);
  symcr::format::store32(bytes.data() + 48, crc32c(bytes.data(), bytes.size()));
  return write_file_atomically(path, bytes.data(), bytes.size(), symcr::Durability::PageCache)
      .ok();
}

}  // namespace

// Saves `saves` times into the store at `path` (4 slots of 4096 bytes, created if missing).
int save_into_store(const char* path, long saves) {
  symcr::Store store;
  symcr::StoreOptions options;
  options.slots = 4;
  options.slot_size = 4096;
  symcr::Status status = symcr::Store::open(path, cli_fixture::schema(), options, store);
  if (!status.ok()) return fail("open store", status);
  for (long seed = 1; seed <= saves; ++seed) {
    cli_fixture::fill_state(static_cast<int>(seed));
    status = store.save();
    if (!status.ok()) return fail("save", status);
  }
  return 0;
}

int rotated_store(const char* path) {
  static const std::uint8_t old_key[] = {'f', 'i', 'x', 't', 'u', 'r', 'e', '-', 'k', 'e', 'y'};
  static const std::uint8_t new_key[] = {'a', 'n', 'o', 't', 'h', 'e', 'r', '-', 'k', 'e', 'y'};
  const symcr::CheckpointKey before[] = {{7, old_key, sizeof old_key}};
  const symcr::CheckpointKey during[] = {{8, new_key, sizeof new_key},
                                         {7, old_key, sizeof old_key}};
  ::unlink(path);
  symcr::Status status = symcr::set_checkpoint_keys(before, 1);
  if (!status.ok()) return fail("keys", status);
  if (save_into_store(path, 2) != 0) return 1;
  status = symcr::set_checkpoint_keys(during, 2);
  if (!status.ok()) return fail("keys", status);
  return save_into_store(path, 2);
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s checkpoint|store|schema|flip|truncate|flip-newest-slot ...\n",
                 argv[0]);
    return 2;
  }
  const char* command = argv[1];
  const char* path = argv[2];
  const long number = argc > 3 ? std::strtol(argv[3], nullptr, 10) : 0;
  if (std::strcmp(command, "signed") == 0) {
    static const std::uint8_t key[] = {'f', 'i', 'x', 't', 'u', 'r', 'e', '-', 'k', 'e', 'y'};
    const symcr::CheckpointKey fixture_key{7, key, sizeof key};
    const symcr::Status keyed = symcr::set_checkpoint_keys(&fixture_key, 1);
    if (!keyed.ok()) return fail("keys", keyed);
    cli_fixture::fill_state(static_cast<int>(number));
    const symcr::Status status = symcr::checkpoint(cli_fixture::schema(), path);
    return status.ok() ? 0 : fail("signed", status);
  }
  if (std::strcmp(command, "checkpoint") == 0) {
    cli_fixture::fill_state(static_cast<int>(number));
    const symcr::Status status = symcr::checkpoint(cli_fixture::schema(), path);
    return status.ok() ? 0 : fail("checkpoint", status);
  }
  const bool more = std::strcmp(command, "store-more") == 0;
  if (std::strcmp(command, "store") == 0 || more) {
    if (!more) ::unlink(path);
    return save_into_store(path, number);
  }
  if (std::strcmp(command, "rotated-store") == 0) return rotated_store(path);
  if (std::strcmp(command, "signed-store") == 0) {
    static const std::uint8_t key[] = {'f', 'i', 'x', 't', 'u', 'r', 'e', '-', 'k', 'e', 'y'};
    const symcr::CheckpointKey fixture_key{7, key, sizeof key};
    const symcr::Status keyed = symcr::set_checkpoint_keys(&fixture_key, 1);
    if (!keyed.ok()) return fail("keys", keyed);
    return save_into_store(path, number);
  }
  if (std::strcmp(command, "restore-unconfirmed") == 0) {
    symcr::StoreOptions options;
    options.slots = 4;
    options.slot_size = 4096;
    options.fallback_depth = 3;
    for (long start = 0; start < number; ++start) {
      symcr::Store store;
      symcr::Status status = symcr::Store::open(path, cli_fixture::schema(), options, store);
      if (status.ok()) status = store.restore_latest().status();
      // NoValidSlot: the fallback gave up, which is what enough such starts are for.
      if (!status.ok() && status.error() != symcr::Error::NoValidSlot) {
        return fail("restore", status);
      }
    }
    return 0;
  }
  if (std::strcmp(command, "schema") == 0) {
    const symcr::Status status = symcr::detail::write_schema_file(cli_fixture::schema(), path);
    return status.ok() ? 0 : fail("schema", status);
  }
  if (std::strcmp(command, "flip") == 0) return flip_byte(path, number) ? 0 : 1;
  if (std::strcmp(command, "truncate") == 0) return ::truncate(path, number) == 0 ? 0 : 1;
  if (std::strcmp(command, "flip-resign") == 0) return flip_and_resign(path, number) ? 0 : 1;
  if (std::strcmp(command, "flip-newest-slot") == 0) return flip_newest_slot(path) ? 0 : 1;
  std::fprintf(stderr, "fixture: unknown command %s\n", command);
  return 2;
}
