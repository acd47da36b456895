// survey_store and its renderings.
#include "store_survey.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "authentication.hpp"
#include "file_io.hpp"
#include "freshness.hpp"
#include "header_fields.hpp"
#include "values.hpp"

namespace symcr::cli {

namespace {

std::string& counter_file_given() {
  static std::string path;
  return path;
}

// The counter's value for `store` (keys set), or why it cannot be known: a missing counter is
// RolledBack, in the words of a program's restore, which refuses the store then.
Status read_counter(const detail::StoreReader& store, const detail::KeyRing& keys,
                    std::uint64_t& value, std::string& path) {
  path = counter_file_of(store.path());
  if (::access(path.c_str(), F_OK) != 0 && errno == ENOENT) {
    return Status(Error::RolledBack, "the freshness counter %s is missing", path.c_str());
  }
  std::vector<std::uint8_t> bytes;
  Status status = detail::read_regular_file(path.c_str(), detail::kCounterFileSize, bytes);
  if (!status.ok()) return status;
  status = detail::decode_counter_file(bytes.data(), bytes.size(), store.store_id(), keys, value);
  if (!status.ok()) {
    return Status(Error::RolledBack, "the freshness counter %s cannot be trusted: %s", path.c_str(),
                  status.message());
  }
  return Status();
}

std::string count_text(std::size_t count, const char* what) {
  return std::to_string(count) + (count == 1 ? " checkpoint " : " checkpoints ") + what;
}

std::string nothing_restored_text(const StoreSurvey& survey, std::uint64_t pending,
                                  std::uint32_t depth) {
  std::size_t passed_over = 0, unauthenticated = 0, unusable = 0;
  for (const SlotSurvey& slot : survey.slots) {
    if (slot.passed_over) {
      ++passed_over;
    } else if (slot.unauthenticated) {
      ++unauthenticated;
    } else if (slot.written && !slot.restorable) {
      ++unusable;
    }
  }
  std::string text = "nothing would be restored: ";
  if (passed_over == 0 && unauthenticated == 0) {
    return text + "no slot holds a restorable checkpoint";
  }
  if (survey.gives_up) {
    text += "the next start counts the restore of #" + std::to_string(pending) +
            ", never confirmed, as a crash past the fallback depth " + std::to_string(depth) +
            " and gives up on every checkpoint through #" +
            std::to_string(survey.next_start_journal.given_up_through) + "; ";
  }
  std::string counts;
  if (passed_over) counts += count_text(passed_over, "passed over by the crash-loop fallback");
  if (unauthenticated) {
    counts += (counts.empty() ? "" : ", ") +
              count_text(unauthenticated, "unauthenticated with the keys given");
  }
  if (unusable) counts += (counts.empty() ? "" : ", ") + count_text(unusable, "unusable");
  return text + counts;
}

}  // namespace

void use_counter_file(const std::string& path) { counter_file_given() = path; }

std::string counter_file_of(const std::string& store_path) {
  return counter_file_given().empty() ? store_path + ".fresh" : counter_file_given();
}

StoreSurvey survey_store(const detail::StoreReader& store) {
  StoreSurvey survey;
  const detail::KeySnapshot keys = detail::current_keys();
  survey.next_start_journal = store.journal_at_next_start(&survey.counts_crash);
  const detail::RestoreJournal& journal = survey.next_start_journal;
  // count_crash() leaves fallbacks at 0 only when it gave up.
  survey.gives_up = survey.counts_crash && journal.fallbacks == 0;
  const std::uint64_t pending = store.journal().unconfirmed;
  const std::vector<detail::StoreSlot>& slots = store.slots();
  std::vector<std::uint8_t> bytes;
  for (std::uint32_t i = 0; i < slots.size(); ++i) {
    const detail::StoreSlot& slot = slots[i];
    SlotSurvey s;
    s.index = i;
    s.state = detail::store_slot_state_name(slot.state);
    s.written = slot.state != detail::StoreSlotState::Empty;
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
      // Every slot's MAC is checked with the keys given, as a restore's scan checks them.
      const Status authentic =
          status.ok()
              ? detail::check_authentication(keys.get(), bytes.data(), view, store.binding(i, area))
              : Status();
      if (status.ok() && authentic.ok()) {
        status = check_payload(store.area(area).schema(), view.payload, view.payload_size);
      }
      s.restorable = status.ok() && authentic.ok();
      if (s.restorable && journal.excludes(slot.header.sequence)) {
        s.passed_over = true;
        s.problem = journal.exclusion_reason(slot.header.sequence);
      }
      if (!authentic.ok()) {
        s.state = detail::store_slot_state_name(detail::StoreSlotState::Unauthenticated);
        s.problem = authentic.message();
        s.damaged = true;
        s.unauthenticated = true;
      } else if (!status.ok()) {
        s.state = "corrupt-payload";
        s.problem = status.message();
        s.damaged = true;
      }
    }
    survey.slots.push_back(std::move(s));
  }
  if (keys) {
    std::vector<bool> authentic(survey.slots.size(), false);
    for (const SlotSurvey& s : survey.slots) {
      authentic[s.index] = s.has_header && !s.unauthenticated && s.area >= 0 &&
                           slots[s.index].state == detail::StoreSlotState::Valid;
    }
    std::uint64_t counted = 0;
    std::string path;
    Status status = read_counter(store, *keys, counted, path);
    const bool holds_authentic =
        std::find(authentic.begin(), authentic.end(), true) != authentic.end() ||
        store.journal().freshness != 0;
    if (!status.ok()) {
      survey.freshness = status.message();
      survey.rolled_back = holds_authentic;
    } else {
      status = store.check_freshness(counted, authentic);
      survey.rolled_back = !status.ok();
      survey.freshness = status.ok() ? "fresh: the counter " + path + " says " +
                                           std::to_string(counted) + " was written"
                                     : status.message();
    }
    if (!store.journal_distrust().empty()) {
      survey.freshness += "; the restore journal is not trusted (" + store.journal_distrust() +
                          ") and reads as empty";
    }
  }
  for (const std::uint32_t i : store.valid_slots_newest_first()) {
    if (survey.rolled_back) break;
    const SlotSurvey& s = survey.slots[i];
    if (s.restorable && !s.passed_over) {
      survey.restore_latest_slot = i;
      break;
    }
    survey.skipped.push_back(SkippedCheckpoint{i, s.header.sequence, s.problem});
  }
  for (std::uint32_t i = 0; i < slots.size(); ++i) {
    if (slots[i].state != detail::StoreSlotState::Valid && survey.slots[i].written) {
      const SlotSurvey& s = survey.slots[i];
      survey.skipped.push_back(
          SkippedCheckpoint{i, s.has_header ? s.header.sequence : 0, s.problem});
    }
  }
  if (survey.rolled_back) {
    survey.restores_nothing_by_choice = true;
    survey.nothing_restored = "nothing would be restored: " + survey.freshness;
  } else if (!survey.restore_latest_slot) {
    for (const SlotSurvey& s : survey.slots) {
      survey.restores_nothing_by_choice |= s.passed_over || s.unauthenticated;
    }
    survey.nothing_restored = nothing_restored_text(survey, pending, store.journal().depth);
  }
  return survey;
}

namespace {

std::string range_text(std::uint64_t low, std::uint64_t high) {
  return low == high ? "#" + std::to_string(low)
                     : "#" + std::to_string(low) + " to #" + std::to_string(high);
}

// The exclusions a journal records (without its unconfirmed restore).
std::string exclusions_text(const detail::RestoreJournal& journal) {
  std::string text;
  const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : "; ") + part; };
  if (journal.suspect_high != 0) {
    add("suspect " + range_text(journal.suspect_low, journal.suspect_high) + " (" +
        std::to_string(journal.fallbacks) +
        (journal.fallbacks == 1 ? " fallback)" : " fallbacks)"));
  }
  if (journal.crashed_high != 0) {
    add("crashed " + range_text(journal.crashed_low, journal.crashed_high));
  }
  if (journal.given_up_through != 0) {
    add("given up through #" + std::to_string(journal.given_up_through));
  }
  return text;
}

std::string journal_text(const detail::RestoreJournal& journal) {
  if (journal.empty()) return "empty";
  std::string text = journal.unconfirmed != 0
                         ? "restore of #" + std::to_string(journal.unconfirmed) + " unconfirmed"
                         : "nothing unconfirmed";
  const std::string exclusions = exclusions_text(journal);
  if (!exclusions.empty()) text += "; " + exclusions;
  if (journal.depth != 0) text += "; fallback depth " + std::to_string(journal.depth);
  return text;
}

// What the next start does with the journal before it chooses a slot.
std::string next_start_text(const detail::StoreReader& store, const StoreSurvey& survey) {
  if (!survey.counts_crash) return "applies the journal as it is";
  const std::string crash = "counts the unconfirmed restore of #" +
                            std::to_string(store.journal().unconfirmed) + " as a crash";
  if (survey.gives_up) {
    return crash + ", past the fallback depth: gives up on every checkpoint through #" +
           std::to_string(survey.next_start_journal.given_up_through);
  }
  return crash + ": " + exclusions_text(survey.next_start_journal);
}

void write_journal_json(JsonWriter& json, const detail::RestoreJournal& journal) {
  json.object_begin();
  json.field("unconfirmed", journal.unconfirmed);
  json.field("suspect_low", journal.suspect_low);
  json.field("suspect_high", journal.suspect_high);
  json.field("crashed_low", journal.crashed_low);
  json.field("crashed_high", journal.crashed_high);
  json.field("given_up_through", journal.given_up_through);
  json.field("fallbacks", journal.fallbacks);
  json.field("depth", journal.depth);
  json.object_end();
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
  header.add({{"format_version"}, {std::to_string(symcr::format::kStoreFileFormatVersion)}});
  if (store.salvaged().empty()) {
    header.add({{"slots"},
                {std::to_string(g.slot_count) + " x " + std::to_string(g.slot_size) + " bytes"}});
  } else {
    header.add({{"slots"}, {store.salvaged(), Colour::Red}});
  }
  for (int i = 0; i < 2; ++i) {
    header.add({{"schema_area " + std::to_string(i)}, {area_text(store.area(i))}});
  }
  header.add({{"restore_journal"}, {journal_text(store.journal())}});
  if (!store.journal().empty()) header.add({{"next_start"}, {next_start_text(store, survey)}});
  if (!survey.freshness.empty()) {
    header.add(
        {{"freshness"}, {survey.freshness, survey.rolled_back ? Colour::Red : Colour::None}});
  }
  std::string restore_text = "none (" + survey.nothing_restored + ")";
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
  if (!store.salvaged().empty()) json.field("salvaged", store.salvaged());

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

  json.key_begin("restore_journal");
  write_journal_json(json, store.journal());
  json.key_end();
  if (!survey.freshness.empty()) {
    json.key_begin("freshness");
    json.object_begin();
    json.field("rolled_back", survey.rolled_back);
    json.field("detail", survey.freshness);
    json.object_end();
    json.key_end();
  }
  // The journal as the next start applies it, before it chooses a slot.
  json.key_begin("next_start");
  json.object_begin();
  json.field("counts_crash", survey.counts_crash);
  json.field("gives_up", survey.gives_up);
  json.key_begin("journal");
  write_journal_json(json, survey.next_start_journal);
  json.key_end();
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
  if (!survey.restore_latest_slot) json.field("nothing_restored", survey.nothing_restored);
}

}  // namespace symcr::cli
