#include "authentication.hpp"

#include <atomic>
#include <cstring>
#include <mutex>

#include "symcr/format/bytes.hpp"

namespace symcr {
namespace detail {
namespace {

// The keys in force. Saves and restores copy the pointer under the mutex (a few nanoseconds,
// once per operation) and then read their own snapshot without it.
std::mutex& keys_mutex() {
  static std::mutex mutex;
  return mutex;
}
KeySnapshot& keys_in_force() {
  static auto* keys = new KeySnapshot();  // never destroyed: saves may run during exit
  return *keys;
}

constexpr char kRecordDomain[] = "symcr record MAC 2";

// The MAC of `record` with its checksum and MAC fields read as zero, bound to `binding`.
void record_mac(const std::uint8_t* record, std::size_t size, const OwnedKey& key,
                const RecordBinding& binding, std::uint8_t (&mac)[format::kSha256Size]) {
  static constexpr std::uint8_t kZero[format::kSha256Size] = {};
  format::HmacSha256 hmac(key.bytes.data(), key.bytes.size());
  hmac.update(kRecordDomain, sizeof kRecordDomain);
  hmac.update(binding.store_id, kStoreIdSize);
  std::uint8_t location[8];
  format::store64(location, binding.location);
  hmac.update(location, sizeof location);
  hmac.update(binding.schema_digest, format::kSha256Size);
  hmac.update(record, format::kRecordChecksumOffset);
  hmac.update(kZero, 4);
  hmac.update(record + format::kRecordChecksumOffset + 4,
              format::kRecordMacOffset - format::kRecordChecksumOffset - 4);
  hmac.update(kZero, format::kSha256Size);
  hmac.update(record + format::kRecordMacOffset + format::kRecordMacSize,
              size - format::kRecordMacOffset - format::kRecordMacSize);
  hmac.finish(mac);
}

}  // namespace

KeyRing::~KeyRing() {
  for (OwnedKey& key : keys) {
    // Through a volatile pointer: a store the compiler cannot drop as dead.
    volatile std::uint8_t* bytes = key.bytes.data();
    for (std::size_t i = 0; i < key.bytes.size(); ++i) bytes[i] = 0;
  }
}

const OwnedKey* KeyRing::find(std::uint32_t id) const {
  for (const OwnedKey& key : keys) {
    if (key.id == id) return &key;
  }
  return nullptr;
}

KeySnapshot current_keys() {
  std::lock_guard<std::mutex> lock(keys_mutex());
  return keys_in_force();
}

namespace {
std::atomic<std::uint64_t> schema_digests{0};
}  // namespace

void schema_digest(const std::uint8_t* schema, std::size_t size,
                   std::uint8_t (&digest)[format::kSha256Size]) {
  schema_digests.fetch_add(1, std::memory_order_relaxed);
  format::Sha256 sha;
  sha.update(schema, size);
  sha.finish(digest);
}

std::uint64_t schema_digest_count() { return schema_digests.load(std::memory_order_relaxed); }

void sign_record(const KeyRing& keys, std::uint8_t* record, std::size_t size,
                 const RecordBinding& binding) {
  std::uint8_t mac[format::kSha256Size];
  record_mac(record, size, keys.signing(), binding, mac);
  std::memcpy(record + format::kRecordMacOffset, mac, sizeof mac);
}

Status check_authentication(const KeyRing* keys, const std::uint8_t* record, const RecordView& view,
                            const RecordBinding& binding) {
  if (keys == nullptr) return Status();
  const RecordHeader& header = view.header;
  if ((header.flags & format::kRecordAuthenticated) == 0) {
    return Status(Error::Unauthenticated,
                  "the checkpoint carries no MAC, and this program authenticates checkpoints: "
                  "refused");
  }
  if (header.mac_version != format::kRecordMacVersion) {
    return Status(Error::Unauthenticated,
                  "the checkpoint's MAC is of version %u, which binds neither its store, its "
                  "slot nor its schema's SHA-256 (this build makes and accepts version %u): "
                  "refused",
                  header.mac_version, format::kRecordMacVersion);
  }
  const OwnedKey* key = keys->find(header.key_id);
  if (key == nullptr) {
    return Status(Error::Unauthenticated,
                  "the checkpoint is authenticated with key id %u, which this program does not "
                  "hold: refused",
                  header.key_id);
  }
  std::uint8_t mac[format::kSha256Size];
  record_mac(record, view.record_size, *key, binding, mac);
  if (!format::equal_macs(mac, record + format::kRecordMacOffset, format::kSha256Size)) {
    return Status(Error::Unauthenticated,
                  "the checkpoint's MAC does not verify with key id %u: it was changed after it "
                  "was written, written with another key, or moved from another slot or "
                  "store: refused",
                  header.key_id);
  }
  return Status();
}

Status check_standalone_authentication(const KeyRing* keys, const std::uint8_t* record,
                                       const RecordView& view) {
  RecordBinding standalone;
  if (keys != nullptr && view.schema != nullptr) {
    schema_digest(view.schema, view.header.schema_size, standalone.schema_digest);
  }
  return check_authentication(keys, record, view, standalone);
}

void store_item_mac(const OwnedKey& key, const char* domain, const std::uint8_t* store_id,
                    const std::uint8_t* bytes, std::size_t size,
                    std::uint8_t (&mac)[format::kSha256Size]) {
  format::HmacSha256 hmac(key.bytes.data(), key.bytes.size());
  hmac.update(domain, std::strlen(domain) + 1);
  hmac.update(store_id, kStoreIdSize);
  hmac.update(bytes, size);
  hmac.finish(mac);
}

}  // namespace detail

Status set_checkpoint_keys(const CheckpointKey* keys, std::size_t count) {
  if (count != 0 && keys == nullptr) return Status(Error::Unsupported, "no keys given");
  std::shared_ptr<detail::KeyRing> ring;
  if (count != 0) ring = std::make_shared<detail::KeyRing>();
  for (std::size_t i = 0; i < count; ++i) {
    if (keys[i].bytes == nullptr || keys[i].size == 0) {
      return Status(Error::Unsupported, "checkpoint key %zu (id %u) is empty", i, keys[i].id);
    }
    if (ring->find(keys[i].id) != nullptr) {
      return Status(Error::Unsupported, "two checkpoint keys have id %u", keys[i].id);
    }
    ring->keys.push_back({keys[i].id, {keys[i].bytes, keys[i].bytes + keys[i].size}});
  }
  detail::KeySnapshot previous;
  {
    std::lock_guard<std::mutex> lock(detail::keys_mutex());
    previous = std::move(detail::keys_in_force());
    detail::keys_in_force() = std::move(ring);
  }
  return Status();  // `previous` is wiped here unless a save or restore still holds it
}

}  // namespace symcr
