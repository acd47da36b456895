// What a store holds, slot by slot, and which slot the program's next start would restore: the
// journal applied as that start applies it (StoreReader::journal_at_next_start), then the
// newest valid slot the journal does not exclude whose MAC verifies with the keys given and
// whose payload decodes in full (restore falls back past the others). The one decision that
// inspect, verify, plan, diff and convert share.
#ifndef SYMCR_CLI_STORE_SURVEY_HPP
#define SYMCR_CLI_STORE_SURVEY_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "json_writer.hpp"
#include "store_reader.hpp"
#include "terminal.hpp"

namespace symcr::cli {

struct SlotSurvey {
  std::uint32_t index = 0;
  std::string state;        // valid, empty, corrupt, corrupt-payload, unknown-schema, ...
  std::string problem;      // why it is not restorable ("" when it is)
  bool written = false;     // not empty
  bool has_header = false;  // header fields below are meaningful
  detail::RecordHeader header;
  int area = -1;
  bool restorable = false;
  bool damaged = false;          // written, and failed a check (not merely stale or empty)
  bool unauthenticated = false;  // sound, but its MAC fails with the keys given (damaged too)
  // Restorable, but the crash-loop fallback's journal (as the next start applies it)
  // excludes it: the next start passes over it (`problem` says why).
  bool passed_over = false;
};

struct StoreSurvey {
  std::vector<SlotSurvey> slots;
  // The journal after the next start counts a pending unconfirmed restore as a crash.
  detail::RestoreJournal next_start_journal;
  bool counts_crash = false;  // the next start counts a crash
  bool gives_up = false;      // ... past the fallback depth: it gives up on every checkpoint
  std::optional<std::uint32_t> restore_latest_slot;
  // As restore_latest()'s Report::skipped(): the slots passed over on the way to the one
  // restored (or to none), then those whose record is unusable.
  std::vector<SkippedCheckpoint> skipped;
  // Why nothing would be restored ("" when a slot would be).
  std::string nothing_restored;
  // Nothing would be restored although a slot holds a sound checkpoint: the crash-loop fallback
  // or the keys exclude it, as a restore that fails (not a store that cannot be read).
  bool restores_nothing_by_choice = false;
  // With keys: the freshness check against the counter (restore_latest()'s), in words, and
  // whether it finds the store rolled back (then nothing would be restored).
  std::string freshness;
  bool rolled_back = false;
};

// The freshness counter file the surveys check a store against (keys set): `path`, or when
// empty the program's default, the store's path with ".fresh" appended.
void use_counter_file(const std::string& path);
// That file for a store at `store_path`: the one given, else the default next to the store.
std::string counter_file_of(const std::string& store_path);

// Authentication uses the keys set with set_checkpoint_keys (none: any MAC is accepted, as by
// a program without keys), each slot bound to its store and place as a restore binds it; the
// journal counts only when its MAC verifies, and the store is checked against its counter.
StoreSurvey survey_store(const detail::StoreReader& store);

// Geometry, schema areas and the slot table, `selected` marked.
void print_store_overview(const std::string& path, const detail::StoreReader& store,
                          const StoreSurvey& survey, std::optional<std::uint32_t> selected);
// Inside an open JSON object: "geometry", "schema_areas", "restore_journal", "next_start",
// "slots", "restore_latest_slot" (and "nothing_restored" when none).
void write_store_json(JsonWriter& json, const detail::StoreReader& store,
                      const StoreSurvey& survey);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_STORE_SURVEY_HPP
