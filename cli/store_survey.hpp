// What a store holds, slot by slot, and which slot restore_latest() would take: the newest
// valid slot whose payload also decodes in full (restore falls back past corrupt payloads).
// Shared by inspect and verify.
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
  std::string state;            // valid, empty, corrupt, corrupt-payload, unknown-schema, ...
  std::string problem;          // why it is not restorable ("" when it is)
  bool has_header = false;      // header fields below are meaningful
  detail::RecordHeader header;
  int area = -1;
  bool restorable = false;
  bool damaged = false;         // written, and failed a check (not merely stale or empty)
  // Restorable, but the crash-loop fallback's journal excludes it: restore_latest() passes
  // over it (`problem` says why).
  bool passed_over = false;
};

struct StoreSurvey {
  std::vector<SlotSurvey> slots;
  std::optional<std::uint32_t> restore_latest_slot;
};

StoreSurvey survey_store(const detail::StoreReader& store);

// Geometry, schema areas and the slot table, `selected` marked.
void print_store_overview(const std::string& path, const detail::StoreReader& store,
                          const StoreSurvey& survey, std::optional<std::uint32_t> selected);
// Inside an open JSON object: "geometry", "schema_areas", "restore_journal", "slots",
// "restore_latest_slot".
void write_store_json(JsonWriter& json, const detail::StoreReader& store,
                      const StoreSurvey& survey);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_STORE_SURVEY_HPP
