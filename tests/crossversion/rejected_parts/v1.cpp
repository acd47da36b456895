// v1: narrower integers, an enum without Gone, UTF-16 strings. A value v1 rejects is never
// replaced by a value-initialised stand-in: the container element holding it is left out, the
// optional, unique_ptr or variant holding it keeps v1's value, the heap object holding it is
// not created and each pointer to it keeps v1's value.
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "check.hpp"

enum class Phase : std::uint8_t { Idle, Climb };

struct Cell {
  int id;
  std::int16_t millivolts;
};

struct Node {
  int value;
  std::int8_t tag;
  Node* next;
};

struct Gauge {
  std::int8_t reading;
};

struct Pack {
  std::vector<std::int8_t> samples;
  std::map<std::int8_t, int> by_id;
  std::map<int, float> gains;
  std::vector<Cell> cells;
  Cell* last_cell = nullptr;
  std::vector<Phase> phases;
  std::vector<std::u16string> names;
  std::vector<std::optional<std::int16_t>> maybe;
  std::list<std::vector<std::int8_t>> batches;
  std::optional<Cell> spare;
  std::optional<Cell> backup{Cell{7, 7}};
  std::unique_ptr<Cell> owned{new Cell{7, 7}};
  std::variant<int, Cell> either{Cell{7, 7}};
  Node* chain = nullptr;
  std::shared_ptr<Gauge> gauge{std::make_shared<Gauge>(Gauge{7})};
};

SYMCR_CHECKPOINT Pack pack;

namespace {

bool left_out(const symcr::Report& report, const char* path) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.decision == symcr::Decision::Rejected &&
        e.detail == "left out of its container: a value in it was rejected") {
      return true;
    }
  }
  std::fprintf(stderr, "no 'left out' entry for %s\n", path);
  return false;
}

// Entries at `path` whose detail starts with `detail`.
int entries_at(const symcr::Report& report, const char* path, const char* detail = "") {
  int count = 0;
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.detail.compare(0, std::strlen(detail), detail) == 0) ++count;
  }
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  const Cell* const owned_before = pack.owned.get();
  const Gauge* const gauge_before = pack.gauge.get();
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(!report.lossless());

  // Container elements: left out whole, the others keep their order.
  XV_CHECK((pack.samples == std::vector<std::int8_t>{1, 2}));
  XV_CHECK(xv::decided(report, "pack.samples[1]", symcr::Decision::Rejected));
  XV_CHECK(entries_at(report, "pack.samples[1]") == 1);  // the value's own entry says it all
  XV_CHECK((pack.by_id == std::map<std::int8_t, int>{{1, 10}, {2, 30}}));
  XV_CHECK(entries_at(report, "pack.by_id[2].first", "1000 out of range of int8") == 1);
  XV_CHECK(left_out(report, "pack.by_id[2]"));
  XV_CHECK((pack.gains == std::map<int, float>{{1, 0.5f}}));
  XV_CHECK(left_out(report, "pack.gains[1]"));
  XV_CHECK(pack.cells.size() == 2 && pack.cells[0].id == 1 && pack.cells[0].millivolts == 3 &&
           pack.cells[1].id == 3 && pack.cells[1].millivolts == 4);
  XV_CHECK(entries_at(report, "pack.cells[1].millivolts", "40000 out of range of int16") == 1);
  XV_CHECK(left_out(report, "pack.cells[1]"));
  XV_CHECK(pack.last_cell == &pack.cells[1]);  // re-indexed past the left-out element
  XV_CHECK((pack.phases == std::vector<Phase>{Phase::Idle, Phase::Climb}));
  XV_CHECK(entries_at(report, "pack.phases[1]", "enum Gone not in this build") == 1);
  XV_CHECK((pack.names == std::vector<std::u16string>{u"ok", u"fine"}));
  XV_CHECK(xv::decided(report, "pack.names[1]", symcr::Decision::Rejected));
  XV_CHECK(pack.maybe.size() == 2 && pack.maybe[0] == std::int16_t{5} && !pack.maybe[1]);
  XV_CHECK(entries_at(report, "pack.maybe[1]", "70000 out of range of int16") == 1);
  // An inner container leaves out its own element; the outer element stays.
  XV_CHECK(
      (pack.batches == std::list<std::vector<std::int8_t>>{std::vector<std::int8_t>{1, 2}, {4}}));
  XV_CHECK(entries_at(report, "pack.batches[0]", "left out") == 0);

  // Holders keep v1's value: nothing emplaced, made or switched.
  XV_CHECK(!pack.spare);
  XV_CHECK(pack.backup && pack.backup->id == 7 && pack.backup->millivolts == 7);
  XV_CHECK(pack.owned.get() == owned_before && pack.owned->id == 7 && pack.owned->millivolts == 7);
  XV_CHECK(pack.either.index() == 1 && std::get<1>(pack.either).id == 7 &&
           std::get<1>(pack.either).millivolts == 7);
  XV_CHECK(xv::decided(report, "pack.owned.millivolts", symcr::Decision::Rejected));

  // Heap objects: the one holding a rejected value is not created; what points to it keeps
  // v1's value (the new node's own value-initialised null).
  XV_CHECK(pack.chain != nullptr && pack.chain->value == 1 && pack.chain->tag == 5 &&
           pack.chain->next == nullptr);
  XV_CHECK(pack.gauge.get() == gauge_before && pack.gauge->reading == 7);
  XV_CHECK(entries_at(report, "pack.gauge",
                      "pointer not restored: heap object of type Gauge holds a value this "
                      "build rejects") == 1);
  return xv::failures() == 0 ? 0 : 1;
}
