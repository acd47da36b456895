// The store's restore journal (restore_journal.hpp, docs/format.md §4).
#include "restore_journal.hpp"

#include <algorithm>
#include <cstring>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "record.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {
namespace {

using format::kJournalMagic;
using format::kLegacyJournalMagic;
constexpr std::size_t kChecked = format::kJournalCrcOffset;  // the CRC covers what precedes it
constexpr std::size_t kLegacyChecked = format::kLegacyJournalCrcOffset;

// The seal's MAC (format::kJournalSeal*): the first 24 bytes of the HMAC-SHA-256 of the journal
// and the seal's fields before it (192 bits; truncated to fit between the copies).
constexpr char kSealDomain[] = "symcr restore journal";
constexpr std::size_t kSealSigned = format::kJournalSize + format::kJournalSealMacOffset;
constexpr std::size_t kSealMacSize = format::kJournalSealSize - format::kJournalSealMacOffset;

bool ranges_hold(const RestoreJournal& journal) {
  return journal.suspect_low <= journal.suspect_high &&
         journal.crashed_low <= journal.crashed_high &&
         journal.highest_sequence() <= format::kMaxRecordSequence;
}

// Whether the copy at `data` carries a seal that verifies for `seal`; `why` says otherwise.
bool seal_holds(const std::uint8_t* data, const JournalSeal& seal, std::uint64_t& freshness,
                std::uint64_t& newest, std::string& why) {
  const std::uint8_t* s = data + kRestoreJournalSize;
  if (format::load32(s + format::kJournalSealSealedOffset) != 1) {
    why = "it carries no MAC (written without keys)";
    return false;
  }
  const OwnedKey* key = seal.keys->find(format::load32(s + format::kJournalSealKeyIdOffset));
  if (key == nullptr) {
    why = "its MAC is made with key id " +
          std::to_string(format::load32(s + format::kJournalSealKeyIdOffset)) +
          ", which this program does not hold";
    return false;
  }
  std::uint8_t mac[format::kSha256Size];
  store_item_mac(*key, kSealDomain, seal.store_id, data, kSealSigned, mac);
  if (!format::equal_macs(mac, s + format::kJournalSealMacOffset, kSealMacSize)) {
    why = "its MAC does not verify (forged, or another store's)";
    return false;
  }
  freshness = format::load64(s + format::kJournalSealFreshnessOffset);
  newest = format::load64(s + format::kJournalSealNewestOffset);
  if (freshness > format::kMaxRecordSequence || newest > format::kMaxRecordSequence) {
    why = "its freshness value is beyond the sequence range";
    return false;
  }
  return true;
}

// One copy: whether it holds a journal, and which.
bool decode_copy(const std::uint8_t* data, RestoreJournal& out) {
  if (std::memcmp(data, kJournalMagic, sizeof kJournalMagic) != 0 ||
      format::load32(data + kChecked) != crc32c(data, kChecked)) {
    return false;
  }
  RestoreJournal journal;
  journal.generation = format::load64(data + format::kJournalGenerationOffset);
  journal.unconfirmed = format::load64(data + format::kJournalUnconfirmedOffset);
  journal.suspect_low = format::load64(data + format::kJournalSuspectLowOffset);
  journal.suspect_high = format::load64(data + format::kJournalSuspectHighOffset);
  journal.given_up_through = format::load64(data + format::kJournalGivenUpThroughOffset);
  journal.crashed_low = format::load64(data + format::kJournalCrashedLowOffset);
  journal.crashed_high = format::load64(data + format::kJournalCrashedHighOffset);
  journal.fallbacks = format::load32(data + format::kJournalFallbacksOffset);
  journal.depth = format::load32(data + format::kJournalDepthOffset);
  if (!ranges_hold(journal)) return false;  // not ours to trust
  out = journal;
  return true;
}

bool decode_legacy(const std::uint8_t* data, RestoreJournal& out) {
  if (std::memcmp(data, kLegacyJournalMagic, sizeof kLegacyJournalMagic) != 0 ||
      format::load32(data + kLegacyChecked) != crc32c(data, kLegacyChecked)) {
    return false;
  }
  RestoreJournal journal;
  journal.unconfirmed = format::load64(data + format::kLegacyJournalUnconfirmedOffset);
  journal.suspect_low = format::load64(data + format::kLegacyJournalSuspectLowOffset);
  journal.suspect_high = format::load64(data + format::kLegacyJournalSuspectHighOffset);
  journal.given_up_through = format::load64(data + format::kLegacyJournalGivenUpThroughOffset);
  journal.fallbacks = format::load32(data + format::kLegacyJournalFallbacksOffset);
  if (!ranges_hold(journal)) return false;
  out = journal;
  return true;
}

}  // namespace

bool RestoreJournal::same_state(const RestoreJournal& o) const {
  return unconfirmed == o.unconfirmed && suspect_low == o.suspect_low &&
         suspect_high == o.suspect_high && given_up_through == o.given_up_through &&
         crashed_low == o.crashed_low && crashed_high == o.crashed_high &&
         fallbacks == o.fallbacks && depth == o.depth;
}

const char* RestoreJournal::exclusion_reason(std::uint64_t sequence) const {
  if (gave_up_on(sequence)) {
    return "crash-loop fallback: given up on (its restores were never confirmed, down to the "
           "fallback depth or the oldest checkpoint; the program started afresh since)";
  }
  if (crashed(sequence)) {
    return "crash-loop fallback: it crashed the program, or was saved after a restore that did "
           "(an older checkpoint restored since was confirmed)";
  }
  if (sequence == suspect_low) {
    return "crash-loop fallback: suspect, the last start restored it and stopped before "
           "Store::confirm() (a crash, or a stop too early)";
  }
  return "crash-loop fallback: suspect, restored, or saved after a restore, that was never "
         "confirmed";
}

std::uint64_t RestoreJournal::highest_sequence() const {
  return std::max({unconfirmed, suspect_high, given_up_through, crashed_high});
}

bool RestoreJournal::record_crash(std::uint64_t newest, std::uint32_t depth) {
  if (unconfirmed != 0) {
    // The suspect range only grows downwards within one crash loop: each fallback restores an
    // older checkpoint than the last suspect one.
    suspect_low = suspect_high == 0 ? unconfirmed : std::min(suspect_low, unconfirmed);
    suspect_high = std::max({suspect_high, unconfirmed, newest});
    unconfirmed = 0;
  }
  ++fallbacks;
  return fallbacks <= depth;
}

bool RestoreJournal::count_crash(std::uint64_t newest, std::uint32_t depth_now) {
  if (unconfirmed == 0) return false;
  if (!record_crash(newest, depth_now)) give_up(newest);
  return true;
}

void RestoreJournal::give_up(std::uint64_t newest) {
  given_up_through = std::max({given_up_through, suspect_high, crashed_high, newest});
  unconfirmed = 0;
  suspect_low = suspect_high = 0;
  crashed_low = crashed_high = 0;
  fallbacks = 0;
}

void RestoreJournal::confirm() {
  if (suspect_high != 0) {
    // The confirmed restore is older than every suspect, and nothing between it and them is
    // restorable: a crashed range above it merges with them. One below it is given up on with
    // everything older, so that one range is enough to remember.
    if (crashed_high == 0) {
      crashed_low = suspect_low;
      crashed_high = suspect_high;
    } else if (crashed_high > unconfirmed) {
      crashed_low = std::min(crashed_low, suspect_low);
      crashed_high = std::max(crashed_high, suspect_high);
    } else {
      given_up_through = std::max(given_up_through, crashed_high);
      crashed_low = suspect_low;
      crashed_high = suspect_high;
    }
  }
  unconfirmed = 0;
  suspect_low = suspect_high = 0;
  fallbacks = 0;
}

void encode_restore_journal(const RestoreJournal& journal, std::uint8_t* out,
                            const JournalSeal* seal) {
  std::memcpy(out, kJournalMagic, sizeof kJournalMagic);
  format::store64(out + format::kJournalGenerationOffset, journal.generation);
  format::store64(out + format::kJournalUnconfirmedOffset, journal.unconfirmed);
  format::store64(out + format::kJournalSuspectLowOffset, journal.suspect_low);
  format::store64(out + format::kJournalSuspectHighOffset, journal.suspect_high);
  format::store64(out + format::kJournalGivenUpThroughOffset, journal.given_up_through);
  format::store64(out + format::kJournalCrashedLowOffset, journal.crashed_low);
  format::store64(out + format::kJournalCrashedHighOffset, journal.crashed_high);
  format::store32(out + format::kJournalFallbacksOffset, journal.fallbacks);
  format::store32(out + format::kJournalDepthOffset, journal.depth);
  format::store32(out + kChecked, crc32c(out, kChecked));
  std::uint8_t* s = out + kRestoreJournalSize;
  std::memset(s, 0, kRestoreJournalSealSize);
  if (seal == nullptr || seal->keys == nullptr) return;
  const OwnedKey& key = seal->keys->signing();
  format::store32(s + format::kJournalSealKeyIdOffset, key.id);
  format::store32(s + format::kJournalSealSealedOffset, 1);
  format::store64(s + format::kJournalSealFreshnessOffset, journal.freshness);
  format::store64(s + format::kJournalSealNewestOffset, journal.newest);
  std::uint8_t mac[format::kSha256Size];
  store_item_mac(key, kSealDomain, seal->store_id, out, kSealSigned, mac);
  std::memcpy(s + format::kJournalSealMacOffset, mac, kSealMacSize);
}

RestoreJournal read_restore_journal(const std::uint8_t* page, std::size_t size,
                                    const JournalSeal* seal, std::string* distrust) {
  const bool verify = seal != nullptr && seal->keys != nullptr;
  RestoreJournal current;
  bool found = false;
  std::string why;
  for (const std::uint64_t offset : kRestoreJournalOffsets) {
    RestoreJournal copy;
    if (offset + kRestoreJournalSize > size || !decode_copy(page + offset, copy)) continue;
    if (verify) {
      std::string copy_why;
      if (offset + kRestoreJournalCopySize > size ||
          !seal_holds(page + offset, *seal, copy.freshness, copy.newest, copy_why)) {
        if (!copy.empty()) why = copy_why;
        continue;
      }
    }
    if (!found || copy.generation > current.generation) {
      current = copy;
      found = true;
    }
  }
  if (verify) {
    if (distrust != nullptr) *distrust = found ? std::string() : why;
    if (found || !why.empty()) return found ? current : RestoreJournal();
  }
  // The earlier versions' journal counts only in a store this version never wrote a journal
  // into (both copies blank): once it has, that journal is stale.
  bool copies_blank = true;
  for (const std::uint64_t offset : kRestoreJournalOffsets) {
    for (std::size_t i = 0; i < kRestoreJournalSize && offset + i < size; ++i) {
      copies_blank = copies_blank && page[offset + i] == 0;
    }
  }
  if (!found && copies_blank && kLegacyRestoreJournalOffset + kLegacyRestoreJournalSize <= size) {
    decode_legacy(page + kLegacyRestoreJournalOffset, current);
    if (verify && !current.empty()) {
      if (distrust != nullptr) *distrust = "it is an earlier version's, which carries no MAC";
      return RestoreJournal();
    }
  }
  return current;
}

}  // namespace symcr::detail
