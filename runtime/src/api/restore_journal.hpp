// The store's restore journal (docs/format.md §4, "Restore journal"): what the crash-loop
// fallback remembers from one start of the program to the next, kept in the store's header
// page. A restored state can itself make the program crash again; the journal records which
// checkpoint a start restored until the program confirms it, so that the next start can tell
// an unconfirmed restore (a crash, or a stop, before the state proved itself) and pass over
// that checkpoint and every one saved after it. Each write puts it in two copies, so a write
// cut short leaves a readable journal, and so does a copy damaged later. Internal to the
// runtime.
#ifndef SYMCR_SRC_RESTORE_JOURNAL_HPP
#define SYMCR_SRC_RESTORE_JOURNAL_HPP

#include <cstddef>
#include <cstdint>
#include <string>

#include "symcr/format/store.hpp"

namespace symcr::detail {

struct KeyRing;

// The two copies, in the store's header page (its first sector), written together. Each is
// the journal (its own CRC) and its seal: with keys set, a MAC binding it to the store and
// carrying its freshness value (zero without keys). The layout is the format core's.
inline constexpr std::uint64_t kRestoreJournalOffsets[2] = {format::kJournalFirstCopyOffset,
                                                            format::kJournalSecondCopyOffset};
inline constexpr std::size_t kRestoreJournalSize = format::kJournalSize;
inline constexpr std::size_t kRestoreJournalSealSize = format::kJournalSealSize;
inline constexpr std::size_t kRestoreJournalCopySize = format::kJournalCopySize;
// Where the header page's journal bytes end.
inline constexpr std::size_t kRestoreJournalEnd = format::kJournalEnd;
// The single journal of stores written by earlier versions, read when neither copy holds one.
inline constexpr std::uint64_t kLegacyRestoreJournalOffset = format::kLegacyJournalOffset;
inline constexpr std::size_t kLegacyRestoreJournalSize = format::kLegacyJournalSize;

struct RestoreJournal {
  // Counts the journal's writes: the copy with the higher one is the current journal.
  std::uint64_t generation = 0;
  // The sequence a start restored that no confirm() has vouched for since; 0: none.
  std::uint64_t unconfirmed = 0;
  // Checkpoints suspected of crashing the program: sequences suspect_low … suspect_high
  // (inclusive), an unconfirmed restore and everything saved after it. 0 … 0: none.
  std::uint64_t suspect_low = 0;
  std::uint64_t suspect_high = 0;
  // The fallback gave up on every checkpoint with a sequence up to this one: never restored.
  std::uint64_t given_up_through = 0;
  // Suspects a confirmed fallback restore proved bad (they crashed, or were saved after a
  // restore that did): never restored again. 0 … 0: none.
  std::uint64_t crashed_low = 0;
  std::uint64_t crashed_high = 0;
  // Unconfirmed restores in a row: how deep the fallback has gone.
  std::uint32_t fallbacks = 0;
  // The fallback depth of the program that wrote the journal: how deep its next start goes.
  std::uint32_t depth = 0;
  // With keys: the freshness value the journal was sealed with (drawn from the store's
  // sequence space, so that saves after it number above it), and the newest authenticated
  // checkpoint it does not exclude that the store held when it was written; 0 without keys.
  std::uint64_t freshness = 0;
  std::uint64_t newest = 0;

  bool empty() const {
    return unconfirmed == 0 && suspect_high == 0 && given_up_through == 0 && crashed_high == 0 &&
           fallbacks == 0;
  }
  // Same state, whatever the generation.
  bool same_state(const RestoreJournal& other) const;
  bool suspects(std::uint64_t sequence) const {
    return suspect_high != 0 && sequence >= suspect_low && sequence <= suspect_high;
  }
  bool crashed(std::uint64_t sequence) const {
    return crashed_high != 0 && sequence >= crashed_low && sequence <= crashed_high;
  }
  bool gave_up_on(std::uint64_t sequence) const { return sequence <= given_up_through; }
  bool excludes(std::uint64_t sequence) const {
    return suspects(sequence) || crashed(sequence) || gave_up_on(sequence);
  }
  // Why a start passes over `sequence`, which excludes() (the report's and the CLI's words).
  const char* exclusion_reason(std::uint64_t sequence) const;
  // The highest sequence the journal names: a new checkpoint is numbered above it, so that
  // no exclusion covers it.
  std::uint64_t highest_sequence() const;

  // A start found `unconfirmed` set: the checkpoint it names and every one saved after it, up
  // to `newest` (the store's highest valid sequence now), become suspect, and the fallback goes
  // one level deeper. False when that exceeds `depth`: the caller then gives up.
  bool record_crash(std::uint64_t newest, std::uint32_t depth);
  // What a start does first when it finds `unconfirmed` set (a crash, or a stop, before
  // confirm()): record_crash(), and give_up() past `depth`. False when nothing was unconfirmed.
  bool count_crash(std::uint64_t newest, std::uint32_t depth);
  // Gives up on every checkpoint up to `newest`: the program starts from its initial state and
  // only checkpoints it saves from then on are restored again.
  void give_up(std::uint64_t newest);
  // The program vouched for its restored state: nothing is pending any more. Suspects of a
  // fallback become crashed (never restored again); what was given up on stays so.
  void confirm();
};

// How a journal is sealed and verified with keys set: the keys and the store's identity.
struct JournalSeal {
  const KeyRing* keys = nullptr;
  const std::uint8_t* store_id = nullptr;  // kStoreIdSize bytes
};

// Encodes `journal` as one copy (kRestoreJournalCopySize bytes, its generation included),
// sealed with `seal`'s signing key and journal.freshness when given, else with a blank seal.
void encode_restore_journal(const RestoreJournal& journal, std::uint8_t* out,
                            const JournalSeal* seal = nullptr);
// The current journal of a store whose first `size` bytes are `page`: the copy with the
// higher generation of those whose magic and checksum hold, else the legacy journal of a store
// whose copies were never written, else an empty journal (a new store, or both copies damaged:
// the restore then behaves as without the fallback). With `seal` (keys set) only a copy whose
// seal verifies counts, the legacy journal never: a journal found but not trusted reads as
// empty, and `distrust` (when given) says why; it stays empty when nothing was passed over.
RestoreJournal read_restore_journal(const std::uint8_t* page, std::size_t size,
                                    const JournalSeal* seal = nullptr,
                                    std::string* distrust = nullptr);

// With keys set, a journal older than the one the newest authenticated checkpoint was saved
// under (`saved_under`, its record's journal freshness) is an older copy put back: why it is not
// trusted, or null when it is. One that holds nothing is read as it would be trusted (a save
// recovering a store refused as rolled back leaves one behind when no fallback depth writes the
// journal): stale, but no warning is due.
inline const char* stale_journal_reason(const RestoreJournal& journal, std::uint64_t saved_under) {
  if (journal.freshness >= saved_under) return nullptr;
  return "it is older than the journal the newest checkpoint was saved under (an older copy put "
         "back)";
}

}  // namespace symcr::detail

#endif  // SYMCR_SRC_RESTORE_JOURNAL_HPP
