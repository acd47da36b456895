// Internal: authenticated checkpoints (docs/format.md §1 "Authentication", §4 "Freshness").
// With keys set (symcr::set_checkpoint_keys), every record this process writes carries an
// HMAC-SHA-256 made with the first key and naming it by id, and every checkpoint it restores
// must carry one that verifies with the key of that id. The MAC binds, besides the record's
// bytes, where the record lives (the store's identity and the slot) and the SHA-256 of its
// writer schema's bytes; a store's restore journal and freshness counter carry MACs too.
#ifndef SYMCR_SRC_AUTHENTICATION_HPP
#define SYMCR_SRC_AUTHENTICATION_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "record.hpp"
#include "symcr/format/sha256.hpp"
#include "symcr/format/store.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

struct OwnedKey {
  std::uint32_t id;
  std::vector<std::uint8_t> bytes;
};
// One consistent set of keys: the first signs. Its key bytes are wiped when the last save or
// restore reading it lets go.
struct KeyRing {
  std::vector<OwnedKey> keys;
  ~KeyRing();
  const OwnedKey& signing() const { return keys.front(); }
  const OwnedKey* find(std::uint32_t id) const;
};
// The keys in force, null when none: taken once per save or restore, so that a record is
// named and signed with the same key, whatever another thread sets meanwhile.
using KeySnapshot = std::shared_ptr<const KeyRing>;
KeySnapshot current_keys();

inline constexpr std::size_t kStoreIdSize = format::kStoreIdSize;
inline constexpr std::uint64_t kNoLocation = UINT64_MAX;

// Where a record lives and what its payload means, bound into its MAC: a record moved to
// another slot or another store, or read with another schema of the same FNV-1a hash, does
// not verify. A standalone checkpoint (a file or a buffer) has no store: an all-zero identity
// and kNoLocation. A slot is named by its offset in the store file (which a store recovered
// from a damaged header still knows).
struct RecordBinding {
  std::uint8_t store_id[kStoreIdSize] = {};
  std::uint64_t location = kNoLocation;
  std::uint8_t schema_digest[format::kSha256Size] = {};  // SHA-256 of the writer schema's bytes
};
void schema_digest(const std::uint8_t* schema, std::size_t size,
                   std::uint8_t (&digest)[format::kSha256Size]);
// How many schema_digest() calls this process made. Hashing a schema costs several times the
// rest of opening a store, so only keys make a store compute one (the tests check this).
std::uint64_t schema_digest_count();

// Writes the MAC of the complete record at `record` (its header laid out for authentication
// with `keys.signing()`'s id, the checksum not yet written) into the header.
void sign_record(const KeyRing& keys, std::uint8_t* record, std::size_t size,
                 const RecordBinding& binding);

// Whether a record parse_record accepted may be restored by a program holding `keys`: without
// keys (null), any; with keys, only an authenticated one whose MAC verifies with the key its
// header names, for `binding` (Error::Unauthenticated otherwise, saying which it is).
Status check_authentication(const KeyRing* keys, const std::uint8_t* record, const RecordView& view,
                            const RecordBinding& binding);

// check_authentication for a standalone checkpoint (a file or a buffer): bound to no store and
// to the SHA-256 of its inline schema.
Status check_standalone_authentication(const KeyRing* keys, const std::uint8_t* record,
                                       const RecordView& view);

// The MAC of a store's restore journal copy or freshness counter (`bytes`, `size`), made with
// `key` for the store `store_id`; `domain` tells the kinds apart.
void store_item_mac(const OwnedKey& key, const char* domain, const std::uint8_t* store_id,
                    const std::uint8_t* bytes, std::size_t size,
                    std::uint8_t (&mac)[format::kSha256Size]);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_AUTHENTICATION_HPP
