#include "authentication.hpp"

#include <atomic>
#include <cstring>
#include <mutex>
#include <vector>

#include "little_endian.hpp"
#include "sha256.hpp"

namespace symcr {
namespace detail {
namespace {

struct OwnedKey {
  std::uint32_t id;
  std::vector<std::uint8_t> bytes;
};
using KeyRing = std::vector<OwnedKey>;

// The keys in force, read on every save and restore without a lock. A replaced ring is kept
// (never freed): a save or restore on another thread may still be reading it, and keys are set
// a few times in a process's life, not per checkpoint.
std::atomic<const KeyRing*> current_keys{nullptr};

std::mutex& keys_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Replaced rings, kept reachable for the process's life (see current_keys).
std::vector<const KeyRing*>& retired_rings() {
  static auto* rings = new std::vector<const KeyRing*>();
  return *rings;
}

// The MAC of `record` with its checksum and MAC fields read as zero.
void record_mac(const std::uint8_t* record, std::size_t size, const OwnedKey& key,
                std::uint8_t (&mac)[kSha256Size]) {
  static constexpr std::uint8_t kZero[kSha256Size] = {};
  HmacSha256 hmac(key.bytes.data(), key.bytes.size());
  hmac.update(record, kRecordChecksumOffset);
  hmac.update(kZero, 4);
  hmac.update(record + kRecordChecksumOffset + 4, kRecordMacOffset - kRecordChecksumOffset - 4);
  hmac.update(kZero, kSha256Size);
  hmac.update(record + kRecordMacOffset + kSha256Size, size - kRecordMacOffset - kSha256Size);
  hmac.finish(mac);
}

}  // namespace

bool keys_set() { return current_keys.load(std::memory_order_acquire) != nullptr; }

std::uint32_t signing_key_id() { return current_keys.load(std::memory_order_acquire)->front().id; }

void sign_record(std::uint8_t* record, std::size_t size) {
  const KeyRing& keys = *current_keys.load(std::memory_order_acquire);
  std::uint8_t mac[kSha256Size];
  record_mac(record, size, keys.front(), mac);
  std::memcpy(record + kRecordMacOffset, mac, sizeof mac);
}

Status check_authentication(const std::uint8_t* record, const RecordView& view) {
  const KeyRing* keys = current_keys.load(std::memory_order_acquire);
  if (keys == nullptr) return Status();
  const RecordHeader& header = view.header;
  if ((header.flags & kRecordAuthenticated) == 0) {
    return Status(Error::Unauthenticated,
                  "the checkpoint carries no MAC, and this program authenticates checkpoints: "
                  "refused");
  }
  const OwnedKey* key = nullptr;
  for (const OwnedKey& candidate : *keys) {
    if (candidate.id == header.key_id) key = &candidate;
  }
  if (key == nullptr) {
    return Status(Error::Unauthenticated,
                  "the checkpoint is authenticated with key id %u, which this program does not "
                  "hold: refused",
                  header.key_id);
  }
  std::uint8_t mac[kSha256Size];
  record_mac(record, view.record_size, *key, mac);
  if (!equal_macs(mac, record + kRecordMacOffset, kSha256Size)) {
    return Status(Error::Unauthenticated,
                  "the checkpoint's MAC does not verify with key id %u: it was changed after it "
                  "was written, or written with another key: refused",
                  header.key_id);
  }
  return Status();
}

}  // namespace detail

Status set_checkpoint_keys(const CheckpointKey* keys, std::size_t count) {
  if (count != 0 && keys == nullptr) return Status(Error::Unsupported, "no keys given");
  auto* ring = new detail::KeyRing();
  for (std::size_t i = 0; i < count; ++i) {
    if (keys[i].bytes == nullptr || keys[i].size == 0) {
      delete ring;
      return Status(Error::Unsupported, "checkpoint key %zu (id %u) is empty", i, keys[i].id);
    }
    for (const detail::OwnedKey& earlier : *ring) {
      if (earlier.id == keys[i].id) {
        delete ring;
        return Status(Error::Unsupported, "two checkpoint keys have id %u", keys[i].id);
      }
    }
    ring->push_back({keys[i].id, {keys[i].bytes, keys[i].bytes + keys[i].size}});
  }
  if (count == 0) {
    delete ring;
    ring = nullptr;
  }
  std::lock_guard<std::mutex> lock(detail::keys_mutex());
  const detail::KeyRing* previous = detail::current_keys.exchange(ring, std::memory_order_acq_rel);
  if (previous != nullptr) detail::retired_rings().push_back(previous);
  return Status();
}

}  // namespace symcr
