// The store's restore journal (docs/format.md §4, "Restore journal"): what the crash-loop
// fallback remembers from one start of the program to the next, kept in the store's header
// page. A restored state can itself make the program crash again; the journal records which
// checkpoint a start restored until the program confirms it, so that the next start can tell
// an unconfirmed restore (a crash, or a stop, before the state proved itself) and pass over
// that checkpoint and every one saved after it. Internal to the runtime.
#ifndef SYMCR_SRC_RESTORE_JOURNAL_HPP
#define SYMCR_SRC_RESTORE_JOURNAL_HPP

#include <cstddef>
#include <cstdint>

namespace symcr::detail {

inline constexpr std::uint64_t kRestoreJournalOffset = 64;  // in the store's header page
inline constexpr std::size_t kRestoreJournalSize = 48;

struct RestoreJournal {
  // The sequence a start restored that no confirm() has vouched for since; 0: none.
  std::uint64_t unconfirmed = 0;
  // Checkpoints suspected of crashing the program: sequences suspect_low … suspect_high
  // (inclusive), an unconfirmed restore and everything saved after it. 0 … 0: none.
  std::uint64_t suspect_low = 0;
  std::uint64_t suspect_high = 0;
  // The fallback gave up on every checkpoint with a sequence up to this one: never restored.
  std::uint64_t given_up_through = 0;
  // Unconfirmed restores in a row: how deep the fallback has gone.
  std::uint32_t fallbacks = 0;

  bool empty() const {
    return unconfirmed == 0 && suspect_high == 0 && given_up_through == 0 && fallbacks == 0;
  }
  bool suspects(std::uint64_t sequence) const {
    return suspect_high != 0 && sequence >= suspect_low && sequence <= suspect_high;
  }
  bool gave_up_on(std::uint64_t sequence) const { return sequence <= given_up_through; }
  bool excludes(std::uint64_t sequence) const { return suspects(sequence) || gave_up_on(sequence); }

  // A start found `unconfirmed` set: the checkpoint it names and every one saved after it, up
  // to `newest` (the store's highest valid sequence now), become suspect, and the fallback goes
  // one level deeper. False when that exceeds `depth`: the caller then gives up.
  bool record_crash(std::uint64_t newest, std::uint32_t depth);
  // Gives up on every checkpoint up to `newest`: the program starts from its initial state and
  // only checkpoints it saves from then on are restored again.
  void give_up(std::uint64_t newest);
  // The program vouched for its restored state: nothing is pending or suspect any more (what
  // was given up on stays so).
  void confirm();
};

void encode_restore_journal(const RestoreJournal& journal, std::uint8_t* out);  // Size bytes
// A journal whose magic or checksum does not hold (a store written before journals existed, or
// damaged bytes) reads as empty: the restore then behaves as without the fallback.
RestoreJournal decode_restore_journal(const std::uint8_t* data, std::size_t size);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_RESTORE_JOURNAL_HPP
