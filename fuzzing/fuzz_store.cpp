// libFuzzer target (c): a checkpoint store file (docs/format.md §4) with several slots, opened
// and restored with restore_latest() into a test program's state.
//
// A store file is mostly zeros (two schema areas of at least 4 KiB, preallocated slots), so the
// input describes it compactly and the harness writes the file:
//   control byte: bits 0-3 reader world; bit 4 recompute every CRC/hash after mutation;
//                 bit 5 strict mode; bit 6 also list the store with the CLI's StoreReader;
//                 bit 7 open with another geometry than the header's (one slot more)
//   sections, each u16 length + bytes, in order:
//     0: the store header (bytes 0..35 of the file, zero-padded to 4096); bytes 36..39, when
//        present and not zero, a length to truncate the file to
//        (a damaged header, when not fixed, takes the recovery path that scans the slots);
//        byte 40, when present, bit 0: the reader authenticates checkpoints (fuzz_worlds.hpp's
//        key), and with bit 4 of the control byte slot records are signed again; byte 41,
//        when present, the crash-loop fallback depth of the writable open (bits 0-2; 0: off);
//        bytes 64..459, when present, the restore journal of earlier versions (64..111), the
//        journal's two copies (128..251, 256..379: 76 bytes and a 48-byte seal) and the
//        store's identity's two copies (400..427, 432..459) at those file offsets (their CRCs fixed, and with keys
//        the journal copies sealed again, with bit 4 of the control byte); bytes 512..767,
//        when present, the freshness counter file beside the store (its copies signed again
//        with bit 4 and keys; absent: no counter file)
//     1: schema area 0 (at 4096): u64 hash, u32 size, u32 crc32c, schema bytes
//     2: schema area 1 (at 4096 + schema_area_size)
//     3...: slot i's bytes (a record), at slots_offset + i * slot_size, cut at slot_size
// The file gets the size its header implies (sparse), capped at 4 MiB. Checked: a read-only
// open and restore write nothing; whatever a writable open decides (recover the header, keep a
// foreign geometry, grow a truncated file back), it restores what the read-only one restores
// and, when that was a checkpoint, changes no byte of the file past its header but the
// journal; with a fallback depth, the journal then names the checkpoint restored as
// unconfirmed (and none when nothing was restored), unless the store was refused as rolled
// back (keys set), which writes nothing.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "freshness.hpp"
#include "fuzz_worlds.hpp"
#include "restore_journal.hpp"
#include "schema_blob.hpp"
#include "store_reader.hpp"

namespace {

namespace le = symcr::format;

constexpr std::uint64_t kMaxFile = 4u << 20;

const std::string& store_path() {
  static const std::string kPath = [] {
    const char* dir = std::getenv("TMPDIR");
    std::string base = dir && *dir ? dir : "/tmp";
    char name[64];
    std::snprintf(name, sizeof name, "/symcr-fuzz-store-%d", static_cast<int>(getpid()));
    return base + name;
  }();
  return kPath;
}

[[noreturn]] void fail(const char* what, unsigned world, const symcr::Report& report) {
  std::fprintf(stderr, "symcr fuzz: %s (reader %s)\n%s\n", what, fuzz::world_name(world),
               report.to_text().c_str());
  std::abort();
}

std::vector<std::uint8_t> read_whole(const std::string& path) {
  std::vector<std::uint8_t> bytes;
  FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return bytes;
  std::uint8_t buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.insert(bytes.end(), buffer, buffer + n);
  std::fclose(file);
  return bytes;
}

void fix_area(std::vector<std::uint8_t>& area) {
  if (area.size() < 16) return;
  const std::uint32_t size = le::load32(area.data() + 8);
  if (size > area.size() - 16) return;
  le::store64(area.data(), symcr::format::fnv1a64(area.data() + 16, size));
  const std::uint32_t crc = symcr::detail::crc32c_extend(symcr::detail::crc32c(area.data(), 12),
                                                         area.data() + 16, size);
  le::store32(area.data() + 12, crc);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t control = data[0];
  const unsigned world = (control & 0x0f) % fuzz::kWorldCount;
  const bool fix = (control & 0x10) != 0;
  std::size_t at = 1;
  std::vector<std::vector<std::uint8_t>> sections;
  while (at + 2 <= size && sections.size() < 3 + 64) {
    const std::size_t length = le::load16(data + at);
    at += 2;
    const std::size_t take = length < size - at ? length : size - at;
    sections.emplace_back(data + at, data + at + take);
    at += take;
  }
  if (sections.empty()) return 0;
  fuzz::use_fuzz_key(sections[0].size() > 40 && (sections[0][40] & 1) != 0);

  std::vector<std::uint8_t> header(4096, 0);
  for (std::size_t i = 0; i < sections[0].size() && i < 36; ++i) header[i] = sections[0][i];
  if (fix) le::store32(header.data() + 32, symcr::detail::crc32c(header.data(), 32));
  // The journal's bytes (the earlier versions' single journal and both copies) and the store's
  // identity after them.
  constexpr std::size_t kJournalAt = symcr::detail::kLegacyRestoreJournalOffset;
  constexpr std::size_t kJournalEnd = symcr::detail::kRestoreJournalEnd;
  constexpr std::size_t kIdAt = symcr::detail::kStoreIdOffset;
  constexpr std::size_t kPageEnd = symcr::detail::kStoreHeaderPageRead;
  const std::uint32_t fallback_depth = sections[0].size() > 41 ? sections[0][41] & 7u : 0;
  for (std::size_t i = kJournalAt; i < sections[0].size() && i < kPageEnd; ++i) {
    header[i] = sections[0][i];
  }
  const symcr::detail::KeySnapshot keys = symcr::detail::current_keys();
  if (fix) {
    const auto seal = [&header](std::size_t at, std::size_t size) {
      le::store32(header.data() + at + size - 4, symcr::detail::crc32c(header.data() + at, size - 4));
    };
    seal(symcr::detail::kLegacyRestoreJournalOffset, symcr::detail::kLegacyRestoreJournalSize);
    seal(kIdAt, symcr::detail::kStoreIdCopySize);
    seal(symcr::detail::kStoreIdSecondCopy, symcr::detail::kStoreIdCopySize);
    std::uint8_t id[symcr::detail::kStoreIdSize];
    symcr::detail::read_store_id(header.data(), header.size(), id);
    for (const std::uint64_t copy : symcr::detail::kRestoreJournalOffsets) {
      seal(copy, symcr::detail::kRestoreJournalSize);
      // With keys, a copy that decodes is sealed again (its freshness as mutated).
      if (keys) {
        std::vector<std::uint8_t> alone(kJournalEnd, 0);
        std::copy(header.begin() + static_cast<std::ptrdiff_t>(copy),
                  header.begin() + static_cast<std::ptrdiff_t>(copy + symcr::detail::kRestoreJournalSize),
                  alone.begin() + static_cast<std::ptrdiff_t>(symcr::detail::kRestoreJournalOffsets[0]));
        symcr::detail::RestoreJournal journal =
            symcr::detail::read_restore_journal(alone.data(), alone.size());
        if (journal.empty() && journal.generation == 0) continue;
        journal.freshness = le::load64(header.data() + copy + symcr::detail::kRestoreJournalSize + 8);
        symcr::detail::JournalSeal journal_seal;
        journal_seal.keys = keys.get();
        journal_seal.store_id = id;
        symcr::detail::encode_restore_journal(journal, header.data() + copy, &journal_seal);
      }
    }
  }
  // The freshness counter file (none unless given).
  const std::string counter_path = store_path() + ".fresh";
  ::unlink(counter_path.c_str());
  if (sections[0].size() > 512) {
    std::vector<std::uint8_t> counter(sections[0].begin() + 512,
                                      sections[0].begin() + std::min<std::size_t>(sections[0].size(), 768));
    if (fix && keys && counter.size() >= 72) {
      // Each copy signed again for the identity and value it names.
      for (std::size_t at = 0; at + 72 <= counter.size(); at += 128) {
        symcr::detail::OwnedKey key = keys->signing();
        le::store32(counter.data() + at + 8, key.id);
        std::uint8_t mac[symcr::format::kSha256Size];
        symcr::detail::store_item_mac(key, "symcr freshness counter", counter.data() + at + 24,
                                      counter.data() + at, 40, mac);
        std::copy(mac, mac + sizeof mac, counter.data() + at + 40);
      }
    }
    FILE* file = std::fopen(counter_path.c_str(), "wb");
    if (file != nullptr) {
      (void)!std::fwrite(counter.data(), 1, counter.size(), file);
      std::fclose(file);
    }
  }
  const std::uint32_t slot_count = le::load32(header.data() + 12);
  const std::uint32_t slot_size = le::load32(header.data() + 16);
  const std::uint32_t area_size = le::load32(header.data() + 20);
  const std::uint64_t slots_offset = le::load64(header.data() + 24);
  const std::uint64_t file_size = slots_offset + std::uint64_t{slot_count} * slot_size;
  if (slot_count > 1024 || slots_offset > kMaxFile || file_size > kMaxFile || area_size > kMaxFile) {
    return 0;
  }

  const std::string& path = store_path();
  ::unlink(path.c_str());
  const int fd = ::open(path.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) {
    std::perror("symcr fuzz: cannot create the store file");
    std::abort();
  }
  auto put = [&](std::vector<std::uint8_t>& bytes, std::uint64_t offset, std::uint64_t limit) {
    const std::size_t n = bytes.size() < limit ? bytes.size() : static_cast<std::size_t>(limit);
    if (n && offset < kMaxFile) (void)!::pwrite(fd, bytes.data(), n, static_cast<off_t>(offset));
  };
  put(header, 0, 4096);
  for (int a = 0; a < 2; ++a) {
    if (sections.size() <= 1 + static_cast<std::size_t>(a)) break;
    std::vector<std::uint8_t>& area = sections[1 + a];
    if (fix) fix_area(area);
    put(area, 4096 + static_cast<std::uint64_t>(a) * area_size, area_size);
  }
  for (std::size_t s = 3; s < sections.size(); ++s) {
    const std::uint64_t slot = s - 3;
    if (slot >= slot_count) break;
    std::vector<std::uint8_t>& record = sections[s];
    symcr::detail::RecordBinding binding;
    // A slot's MAC binds the store, the slot's offset and its area's schema digest; a store
    // without an identity gets a new one from a writable open, so its slots are not signed.
    const bool has_id =
        symcr::detail::read_store_id(header.data(), header.size(), binding.store_id);
    if (fix && !has_id) {
      fuzz::use_fuzz_key(false);
      fuzz::fix_record_integrity(record.data(), record.size());
      fuzz::use_fuzz_key(keys != nullptr);
    } else if (fix) {
      binding.location = slots_offset + slot * slot_size;
      for (int a = 0; a < 2 && record.size() >= 40; ++a) {
        const std::vector<std::uint8_t>* area =
            sections.size() > 1 + static_cast<std::size_t>(a) ? &sections[1 + a] : nullptr;
        if (area == nullptr || area->size() < 16) continue;
        const std::uint32_t area_bytes = le::load32(area->data() + 8);
        if (area_bytes <= area->size() - 16 && le::load64(area->data()) == le::load64(record.data() + 32)) {
          symcr::detail::schema_digest(area->data() + 16, area_bytes, binding.schema_digest);
        }
      }
      fuzz::fix_record_integrity(record.data(), record.size(), &binding);
    }
    put(record, slots_offset + slot * slot_size, slot_size);
  }
  std::uint64_t length = file_size < 4096 ? 4096 : file_size;
  if (sections[0].size() >= 40 && le::load32(sections[0].data() + 36) != 0) {
    length = std::min<std::uint64_t>(length, le::load32(sections[0].data() + 36));
  }
  if (::ftruncate(fd, static_cast<off_t>(length)) != 0) std::perror("symcr fuzz: ftruncate");
  ::close(fd);
  const std::vector<std::uint8_t> file_before = read_whole(path);

  symcr::RestoreOptions restore_options;
  restore_options.strict = (control & 0x20) != 0;
  // What a read-only open restores, which must write nothing at all.
  fuzz::reset_world(world);
  bool restorable = false;
  {
    symcr::Store store;
    if (symcr::Store::open_readonly(path.c_str(), fuzz::world_schema(world), store).ok()) {
      restorable = store.restore_latest(restore_options).ok();
    }
  }
  if (read_whole(path) != file_before) {
    std::fprintf(stderr, "symcr fuzz: a read-only open or restore wrote into the store\n");
    std::abort();
  }

  fuzz::reset_world(world);
  const std::vector<std::uint8_t> before = fuzz::world_snapshot(world);
  bool restored = false;
  symcr::StoreOptions options;
  options.slots = (control & 0x80) ? slot_count + 1 : slot_count;
  options.slot_size = slot_size;
  options.fallback_depth = fallback_depth;
  const bool options_valid = symcr::detail::check_store_dimensions(options.slots, slot_size).ok();
  {
    symcr::Store store;
    const symcr::Status opened = symcr::Store::open(path.c_str(), fuzz::world_schema(world), options, store);
    if (opened.ok()) {
      const symcr::Report report = store.restore_latest(restore_options);
      restored = report.ok();
      (void)report.to_json();
      // A store refused as rolled back (keys set) is written nothing, its journal included.
      if (fallback_depth != 0 && !store.read_only() &&
          report.status().error() != symcr::Error::RolledBack) {
        const std::vector<std::uint8_t> now = read_whole(path);
        const symcr::detail::RestoreJournal journal =
            symcr::detail::read_restore_journal(now.data(), now.size());
        // The journal may go on naming an earlier start's restore only where this one recorded
        // nothing: it stopped on an error first (an exhausted sequence among them), or found
        // nothing to restore under a journal these keys do not trust (another key holder's).
        const bool journal_kept = now.size() >= kJournalEnd && file_before.size() >= kJournalEnd &&
                                  std::equal(now.begin() + kJournalAt, now.begin() + kJournalEnd,
                                             file_before.begin() + kJournalAt);
        // (A store left without an identity had one drawn for this open alone, which sealed
        // nothing: its journal is not trusted either.)
        std::string distrust;
        std::uint8_t id[symcr::detail::kStoreIdSize];
        const bool id_in_file = symcr::detail::read_store_id(now.data(), now.size(), id);
        symcr::detail::JournalSeal seal;
        seal.keys = keys.get();
        seal.store_id = id;
        (void)symcr::detail::read_restore_journal(now.data(), now.size(), &seal, &distrust);
        const bool recorded_nothing =
            !restored && journal_kept &&
            (report.status().error() != symcr::Error::NoValidSlot || (keys && !id_in_file) ||
             !distrust.empty());
        if (journal.unconfirmed != (restored ? report.sequence() : 0) && !recorded_nothing) {
          fail("the journal does not name the restore as unconfirmed", world, report);
        }
      }
      if (!report.ok() && fuzz::world_snapshot(world) != before) {
        fail("a refused restore modified the live state", world, report);
      }
      if (!fuzz::world_rules_hold(world)) fail("a restored value breaks the reader's rules", world, report);
    }
  }
  // With a fallback depth the writable open may count an unconfirmed restore as a crash, which
  // a read-only one (recording nothing) does not.
  if (restorable && options_valid && fallback_depth == 0 && !restored) {
    std::fprintf(stderr, "symcr fuzz: open() lost a checkpoint that open_readonly() restores\n");
    std::abort();
  }
  // A store holding a restorable checkpoint is never reinitialised: past its header, opening
  // and restoring change nothing that was there (a truncated file only grows back).
  const std::vector<std::uint8_t> file_after = read_whole(path);
  if (restorable && file_after.size() < file_before.size()) {
    std::fprintf(stderr, "symcr fuzz: opening shrank a store holding checkpoints\n");
    std::abort();
  }
  auto same_range = [&](std::size_t from, std::size_t to) {
    from = std::min(from, file_before.size());
    to = std::min(to, file_before.size());
    return std::equal(file_before.begin() + from, file_before.begin() + to,
                      file_after.begin() + from);
  };
  // A writable open writes damaged identity copies again.
  std::uint8_t id_before[symcr::detail::kStoreIdSize];
  bool had_id = false;
  const bool id_held =
      symcr::detail::read_store_id(file_before.data(), file_before.size(), id_before, &had_id);
  // Where neither copy held, in a store holding a checkpoint, the identity it writes is only
  // the one its counter file names (taken back), never a new one.
  if (restorable && !id_held && !same_range(kIdAt, kPageEnd)) {
    std::uint8_t id_after[symcr::detail::kStoreIdSize];
    std::uint8_t named[symcr::detail::kCounterCopyCount][symcr::detail::kStoreIdSize];
    const std::vector<std::uint8_t> counter_bytes = read_whole(counter_path);
    const std::size_t count =
        keys ? symcr::detail::store_ids_in_counter_file(counter_bytes.data(), counter_bytes.size(),
                                                        *keys, named)
             : 0;
    bool from_counter = false;
    if (symcr::detail::read_store_id(file_after.data(), file_after.size(), id_after)) {
      for (std::size_t i = 0; i < count; ++i) {
        from_counter = from_counter || std::memcmp(named[i], id_after, sizeof id_after) == 0;
      }
    }
    if (!from_counter) {
      std::fprintf(stderr, "symcr fuzz: an open wrote a new identity over a lost one\n");
      std::abort();
    }
  }
  if (restorable && !(same_range(36, kJournalAt) &&
                      (fallback_depth != 0 || same_range(kJournalAt, kJournalEnd)) &&
                      same_range(kJournalEnd, kIdAt) && (!had_id || same_range(kIdAt, kPageEnd)) &&
                      same_range(kPageEnd, file_before.size()))) {
    std::fprintf(stderr, "symcr fuzz: opening or restoring changed the store's bytes\n");
    std::abort();
  }
  fuzz::reset_world(world);

  if (control & 0x40) {
    symcr::detail::StoreReader reader;
    if (reader.open(path.c_str()).ok()) {
      std::vector<std::uint8_t> bytes;
      for (std::uint32_t index : reader.valid_slots_newest_first()) {
        symcr::detail::RecordView view;
        int area = -1;
        (void)reader.read_record(index, bytes, view, area);
      }
    }
  }
  ::unlink(path.c_str());
  ::unlink(counter_path.c_str());
  return 0;
}
