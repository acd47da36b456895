// Internal: what makes an authenticated store's state fresh (docs/format.md §4 "Freshness",
// docs/threat-model.md): the store's identity, in its header page, and the default
// FreshnessCounter, an authenticated file beside (or away from) the store.
#ifndef SYMCR_SRC_FRESHNESS_HPP
#define SYMCR_SRC_FRESHNESS_HPP

#include <sys/stat.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "authentication.hpp"
#include "restore_journal.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// The store's identity: 16 random bytes drawn when the store is created (or first opened for
// writing by a build that knows of it), kept in the header page after the journal copies, in
// two copies (magic, id, CRC each: the format core's layout), so that one damaged byte does
// not cost every checkpoint.
inline constexpr std::uint64_t kStoreIdOffset = format::kStoreIdFirstCopyOffset;
inline constexpr std::size_t kStoreIdCopySize = format::kStoreIdCopySize;
inline constexpr std::uint64_t kStoreIdSecondCopy = format::kStoreIdSecondCopyOffset;
inline constexpr std::size_t kStoreIdBlockSize =
    kStoreIdSecondCopy + kStoreIdCopySize - kStoreIdOffset;
inline constexpr std::size_t kStoreHeaderPageRead = kStoreIdOffset + kStoreIdBlockSize;
// A counter file holds its value in two copies.
inline constexpr std::size_t kCounterCopyCount = 2;

// Draws a new identity (getrandom, else /dev/urandom, else time and process id mixed).
void new_store_id(std::uint8_t (&id)[kStoreIdSize]);
// Both copies, kStoreIdBlockSize bytes to be written at kStoreIdOffset.
void encode_store_id(const std::uint8_t (&id)[kStoreIdSize], std::uint8_t* out);
// The identity in the first `size` bytes of a store, from the first copy that holds; false
// (and `id` all zero) when neither does. `both`, when given: whether both copies hold.
bool read_store_id(const std::uint8_t* page, std::size_t size, std::uint8_t (&id)[kStoreIdSize],
                   bool* both = nullptr);

// The freshness rule (keys set): a store is fresh when its newest authenticated checkpoint
// (`newest`, a sequence) is at least the counter's `counted` value, or when its authenticated
// journal is (the last thing written was the journal) and the store still holds the newest
// checkpoint that journal lets a start restore (`newest_allowed`, the newest authenticated one
// it does not exclude, at least `journal.newest`); RolledBack, saying what is older than what,
// otherwise.
Status freshness_verdict(const char* path, std::uint64_t newest, std::uint64_t newest_allowed,
                         const RestoreJournal& journal, std::uint64_t counted);
// The newest of `sequences` (authenticated checkpoints) that `journal` does not exclude.
template <typename Sequences>
std::uint64_t newest_allowed(const Sequences& sequences, const RestoreJournal& journal) {
  std::uint64_t newest = 0;
  for (const std::uint64_t sequence : sequences) {
    if (!journal.excludes(sequence) && sequence > newest) newest = sequence;
  }
  return newest;
}

// The default counter: a 256-byte file holding two copies of (magic, key id, value, store id,
// MAC), both written with one write, so that a cut write leaves the previous value or the new
// one. The MAC is made with the signing key of the keys in force; a copy verifies with any key
// the program holds. Never lowered. Through detail::file_system(), like the store.
// Refuses a counter file path that names something other than a counter the store could own:
// the store file itself (`store`: its fstat; the counter would be overwritten by the store
// and vice versa, so rollback would go unnoticed), or an existing entry that is not a regular
// file (a directory, a device, a symbolic link, which the counter never follows). A path
// that does not exist yet is fine if its folder does: the first save creates it.
Status check_counter_path(const char* counter, const struct stat& store, const char* store_path);

class FileFreshnessCounter final : public FreshnessCounter {
 public:
  FileFreshnessCounter(std::string path, const std::uint8_t (&store_id)[kStoreIdSize],
                       Durability durability);
  // The keys to sign and verify with: the store's snapshot for the operation under way.
  void use_keys(const KeyRing* keys) { keys_ = keys; }
  Status read(std::uint64_t& value) override;
  Status advance(std::uint64_t value) override;
  const std::string& path() const { return path_; }
  // For a store whose identity copies are both lost: the identities the counter file's copies
  // name under a MAC that verifies with these keys (at most one per copy, each once). Only the
  // one its checkpoints verify under is the store's: another store's genuine counter names
  // another.
  std::size_t store_ids(std::uint8_t (&ids)[kCounterCopyCount][kStoreIdSize]) const;
  // The identity the counter is bound to from now on.
  void use_store_id(const std::uint8_t (&id)[kStoreIdSize]);

 private:
  Status read_file(std::uint8_t (&bytes)[format::kCounterFileSize], std::size_t& got) const;

  std::string path_;
  std::uint8_t store_id_[kStoreIdSize];
  Durability durability_;
  const KeyRing* keys_ = nullptr;
  bool known_ = false;  // `value_` is what the file holds (read or written by this object)
  std::uint64_t value_ = 0;
};

// The distinct store identities named by the copies of a counter file's bytes whose MAC
// verifies with `keys`, and their count.
std::size_t store_ids_in_counter_file(const std::uint8_t* bytes, std::size_t size,
                                      const KeyRing& keys,
                                      std::uint8_t (&ids)[kCounterCopyCount][kStoreIdSize]);
// Decodes a counter file's bytes (at most 256) for `store_id` with `keys`: the higher value of
// the copies that verify. Corrupt or Unauthenticated, saying why, when none does.
Status decode_counter_file(const std::uint8_t* bytes, std::size_t size,
                           const std::uint8_t* store_id, const KeyRing& keys, std::uint64_t& value);
inline constexpr std::size_t kCounterFileSize = format::kCounterFileSize;

}  // namespace symcr::detail

#endif  // SYMCR_SRC_FRESHNESS_HPP
