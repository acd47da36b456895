// v0: values v1's types cannot hold (out of range, an enumerator v1 lacks, a string not valid
// UTF-8) inside container elements, optionals, unique_ptrs, variants and heap objects, each
// beside values that fit.
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "check.hpp"

enum class Phase { Idle, Climb, Gone };

struct Cell {
  int id;
  int millivolts;
};

struct Node {
  int value;
  int tag;
  Node* next;
};

struct Gauge {
  int reading;
};

struct Pack {
  std::vector<int> samples;
  std::map<int, int> by_id;
  std::map<int, double> gains;
  std::vector<Cell> cells;
  Cell* last_cell;  // the element after the one v1 leaves out
  std::vector<Phase> phases;
  std::vector<std::string> names;
  std::vector<std::optional<int>> maybe;
  std::list<std::vector<int>> batches;
  std::optional<Cell> spare;
  std::optional<Cell> backup;
  std::unique_ptr<Cell> owned;
  std::variant<int, Cell> either;
  Node* chain;
  std::shared_ptr<Gauge> gauge;
};

SYMCR_CHECKPOINT Pack pack;

int main(int argc, char** argv) {
  pack.samples = {1, 300, 2};
  pack.by_id = {{1, 10}, {1000, 20}, {2, 30}};
  pack.gains = {{1, 0.5}, {2, 1e300}};
  pack.cells = {{1, 3}, {2, 40000}, {3, 4}};
  pack.last_cell = &pack.cells[2];
  pack.phases = {Phase::Idle, Phase::Gone, Phase::Climb};
  pack.names = {"ok", "bad\xff", "fine"};
  pack.maybe = {5, 70000, std::nullopt};
  pack.batches = {{1, 300, 2}, {4}};
  pack.spare = Cell{9, 40000};
  pack.backup = Cell{9, 40000};
  pack.owned.reset(new Cell{9, 40000});
  pack.either = Cell{9, 40000};
  Node* second = new Node{2, 300, nullptr};
  pack.chain = new Node{1, 5, second};
  pack.gauge = std::make_shared<Gauge>(Gauge{500});
  return xv::save(argc, argv);
}
