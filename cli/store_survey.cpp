// survey_store and its renderings.
#include "store_survey.hpp"

#include <algorithm>

#include "authentication.hpp"
#include "header_fields.hpp"
#include "values.hpp"

namespace symcr::cli {

StoreSurvey survey_store(const detail::StoreReader& store) {
  StoreSurvey survey;
  const std::vector<detail::StoreSlot>& slots = store.slots();
  std::vector<std::uint8_t> bytes;
  for (std::uint32_t i = 0; i < slots.size(); ++i) {
    const detail::StoreSlot& slot = slots[i];
    SlotSurvey s;
    s.index = i;
    s.state = detail::store_slot_state_name(slot.state);
    s.has_header = slot.state == detail::StoreSlotState::Valid ||
                   slot.state == detail::StoreSlotState::UnknownSchema;
    s.header = slot.header;
    s.area = slot.area;
    s.damaged = slot.state == detail::StoreSlotState::Corrupt ||
                slot.state == detail::StoreSlotState::FutureVersion;
    if (slot.state != detail::StoreSlotState::Valid) {
      s.problem = slot.problem.message();
    } else {
      detail::RecordView view;
      int area = -1;
      Status status = store.read_record(i, bytes, view, area);
      // With --key-file every slot's MAC is checked, as a restore would check the one it takes.
      const Status authentic =
          status.ok() ? detail::check_authentication(bytes.data(), view) : Status();
      if (status.ok() && authentic.ok()) {
        status = check_payload(store.area(area).schema(), view.payload, view.payload_size);
      }
      s.restorable = status.ok() && authentic.ok();
      const detail::RestoreJournal& journal = store.journal();
      if (s.restorable && journal.excludes(slot.header.sequence)) {
        s.passed_over = true;
        s.problem = journal.gave_up_on(slot.header.sequence)
                        ? "crash-loop fallback: given up on"
                        : "crash-loop fallback: suspect (a restore never confirmed)";
      }
      if (!authentic.ok()) {
        s.state = detail::store_slot_state_name(detail::StoreSlotState::Unauthenticated);
        s.problem = authentic.message();
        s.damaged = true;
      } else if (!status.ok()) {
        s.state = "corrupt-payload";
        s.problem = status.message();
        s.damaged = true;
      }
    }
    survey.slots.push_back(std::move(s));
  }
  for (const std::uint32_t i : store.valid_slots_newest_first()) {
    if (survey.slots[i].restorable && !survey.slots[i].passed_over) {
      survey.restore_latest_slot = i;
      break;
    }
  }
  return survey;
}

namespace {

std::string journal_text(const detail::RestoreJournal& journal) {
  if (journal.empty()) return "empty";
  std::string text = journal.unconfirmed != 0
                         ? "restore of #" + std::to_string(journal.unconfirmed) + " unconfirmed"
                         : "nothing unconfirmed";
  if (journal.suspect_high != 0) {
    text += "; suspect #" + std::to_string(journal.suspect_low) + " to #" +
            std::to_string(journal.suspect_high) + " (" + std::to_string(journal.fallbacks) +
            (journal.fallbacks == 1 ? " fallback)" : " fallbacks)");
  }
  if (journal.given_up_through != 0) {
    text += "; given up through #" + std::to_string(journal.given_up_through);
  }
  return text;
}

std::string area_text(const detail::StoreSchemaArea& area) {
  if (!area.valid) return "empty or invalid";
  return "hash " + hex64(area.hash) + ", " + std::to_string(area.size) + " bytes, " +
         std::to_string(area.schema().type_count) + " types, " +
         std::to_string(area.schema().root_count) + " roots";
}

Colour state_colour(const SlotSurvey& slot) {
  if (slot.passed_over) return Colour::Dim;
  if (slot.restorable) return Colour::Green;
  if (slot.damaged) return Colour::Red;
  return Colour::Dim;
}

}  // namespace

void print_store_overview(const std::string& path, const detail::StoreReader& store,
                          const StoreSurvey& survey, std::optional<std::uint32_t> selected) {
  const Terminal terminal = Terminal::for_stdout();
  const detail::StoreGeometry& g = store.geometry();
  Table header;
  header.add({{"store"}, {path}});
  header.add({{"format_version"}, {std::to_string(detail::kStoreFileFormatVersion)}});
  header.add(
      {{"slots"}, {std::to_string(g.slot_count) + " x " + std::to_string(g.slot_size) + " bytes"}});
  for (int i = 0; i < 2; ++i) {
    header.add({{"schema_area " + std::to_string(i)}, {area_text(store.area(i))}});
  }
  header.add({{"restore_journal"}, {journal_text(store.journal())}});
  std::string restore_text = "none (no restorable slot)";
  if (survey.restore_latest_slot) {
    const SlotSurvey& s = survey.slots[*survey.restore_latest_slot];
    restore_text =
        "slot " + std::to_string(s.index) + " (sequence " + std::to_string(s.header.sequence) + ")";
  }
  header.add({{"restore_latest"},
              {restore_text, survey.restore_latest_slot ? Colour::Green : Colour::Red}});
  print(header.render(terminal));
  print("\n");

  Table table;
  table.add({{"slot", Colour::Bold},
             {"state", Colour::Bold},
             {"sequence", Colour::Bold},
             {"time", Colour::Bold},
             {"payload", Colour::Bold},
             {"schema", Colour::Bold},
             {"note", Colour::Bold}});
  for (const SlotSurvey& s : survey.slots) {
    std::string note = s.problem;
    if (selected && *selected == s.index) note = note.empty() ? "<- shown" : note + " <- shown";
    table.add({{std::to_string(s.index)},
               {s.state, state_colour(s)},
               {s.has_header ? std::to_string(s.header.sequence) : "-"},
               {s.has_header ? utc_iso8601(s.header.timestamp_ns) : "-"},
               {s.has_header ? std::to_string(s.header.payload_size) : "-"},
               {s.area >= 0 ? "area " + std::to_string(s.area) : "-"},
               {note}});
  }
  print(table.render(terminal));
}

void write_store_json(JsonWriter& json, const detail::StoreReader& store,
                      const StoreSurvey& survey) {
  const detail::StoreGeometry& g = store.geometry();
  json.key_begin("geometry");
  json.object_begin();
  json.field("slot_count", g.slot_count);
  json.field("slot_size", g.slot_size);
  json.field("schema_area_size", g.schema_area_size);
  json.field("slots_offset", g.slots_offset);
  json.object_end();
  json.key_end();

  json.key_begin("schema_areas");
  json.array_begin();
  for (int i = 0; i < 2; ++i) {
    const detail::StoreSchemaArea& area = store.area(i);
    json.object_begin();
    json.field("index", i);
    json.field("valid", area.valid);
    if (area.valid) {
      json.field("hash", hex64(area.hash));
      json.field("size", area.size);
      json.field("types", area.schema().type_count);
      json.field("roots", area.schema().root_count);
    }
    json.object_end();
  }
  json.array_end();
  json.key_end();

  const detail::RestoreJournal& journal = store.journal();
  json.key_begin("restore_journal");
  json.object_begin();
  json.field("unconfirmed", journal.unconfirmed);
  json.field("suspect_low", journal.suspect_low);
  json.field("suspect_high", journal.suspect_high);
  json.field("given_up_through", journal.given_up_through);
  json.field("fallbacks", journal.fallbacks);
  json.object_end();
  json.key_end();

  json.key_begin("slots");
  json.array_begin();
  for (const SlotSurvey& s : survey.slots) {
    json.object_begin();
    json.field("slot", s.index);
    json.field("state", s.state);
    json.field("restorable", s.restorable);
    json.field("passed_over", s.passed_over);
    if (s.has_header) {
      json.field("sequence", s.header.sequence);
      json.field("time", utc_iso8601(s.header.timestamp_ns));
      json.field("payload_size", s.header.payload_size);
      json.field("schema_hash", hex64(s.header.schema_hash));
    }
    if (s.area >= 0) json.field("schema_area", s.area);
    if (!s.problem.empty()) json.field("problem", s.problem);
    json.object_end();
  }
  json.array_end();
  json.key_end();

  json.field("restore_latest_slot", survey.restore_latest_slot
                                        ? JsonScalar::of_uint(*survey.restore_latest_slot)
                                        : JsonScalar::null());
}

}  // namespace symcr::cli
