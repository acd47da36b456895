// The store's restore journal (restore_journal.hpp, docs/format.md §4).
#include "restore_journal.hpp"

#include <algorithm>
#include <cstring>

#include "crc32c.hpp"
#include "little_endian.hpp"

namespace symcr::detail {
namespace {

constexpr std::uint8_t kJournalMagic[8] = {'S', 'Y', 'M', 'C', 'R', 'J', 'N', 'L'};
constexpr std::size_t kChecked = kRestoreJournalSize - 4;  // the CRC covers what precedes it

}  // namespace

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

void RestoreJournal::give_up(std::uint64_t newest) {
  given_up_through = std::max({given_up_through, suspect_high, newest});
  unconfirmed = 0;
  suspect_low = suspect_high = 0;
  fallbacks = 0;
}

void RestoreJournal::confirm() {
  unconfirmed = 0;
  suspect_low = suspect_high = 0;
  fallbacks = 0;
}

void encode_restore_journal(const RestoreJournal& journal, std::uint8_t* out) {
  std::memcpy(out, kJournalMagic, sizeof kJournalMagic);
  le::store64(out + 8, journal.unconfirmed);
  le::store64(out + 16, journal.suspect_low);
  le::store64(out + 24, journal.suspect_high);
  le::store64(out + 32, journal.given_up_through);
  le::store32(out + 40, journal.fallbacks);
  le::store32(out + kChecked, crc32c(out, kChecked));
}

RestoreJournal decode_restore_journal(const std::uint8_t* data, std::size_t size) {
  RestoreJournal journal;
  if (size < kRestoreJournalSize || std::memcmp(data, kJournalMagic, sizeof kJournalMagic) != 0 ||
      le::load32(data + kChecked) != crc32c(data, kChecked)) {
    return journal;
  }
  journal.unconfirmed = le::load64(data + 8);
  journal.suspect_low = le::load64(data + 16);
  journal.suspect_high = le::load64(data + 24);
  journal.given_up_through = le::load64(data + 32);
  journal.fallbacks = le::load32(data + 40);
  if (journal.suspect_low > journal.suspect_high) return RestoreJournal();  // not ours to trust
  return journal;
}

}  // namespace symcr::detail
