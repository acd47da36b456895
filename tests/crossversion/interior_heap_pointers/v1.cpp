// v1: the Node gained a field and reordered its members, Outer too, and Graph's fields moved:
// every interior pointer of v0 (met before or after its heap object, inside containers, at the
// object's own address, through an enclosing heap object) points into the restored objects.
#include <vector>

#include "check.hpp"

struct Node {
  std::vector<int> samples;
  double weight = 0.5;  // new
  int value = -1;
  int id = -1;
};

struct Outer {
  Node inner;
  int tag = -1;
};

struct Item {
  int b = -1;
  int a = -1;
};

struct Bag {
  std::vector<Item> items;
};

struct Link {
  Node* node = nullptr;
  int* field = nullptr;
};

struct Graph {
  Node* before = nullptr;
  int* value_before = nullptr;
  int* id_before = nullptr;
  int* sample_before = nullptr;
  Node* after = nullptr;
  int* value_after = nullptr;
  std::vector<Link> links;
  Outer* outer = nullptr;
  Node* inner = nullptr;
  int* deepest = nullptr;
  Bag* bag = nullptr;
  Item* item = nullptr;
  int* item_b = nullptr;
};

SYMCR_CHECKPOINT Graph graph;

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(report.count(symcr::Decision::Rejected) == 0);
  const Graph& g = graph;
  XV_CHECK(g.before && g.after && g.outer);
  if (g.before) {
    XV_CHECK(g.before->id == 1 && g.before->value == 10 && g.before->weight == 0.5);
    XV_CHECK((g.before->samples == std::vector<int>{100, 101, 102}));
    XV_CHECK(g.value_before == &g.before->value);
    XV_CHECK(g.id_before == &g.before->id);
    XV_CHECK(g.before->samples.size() == 3 && g.sample_before == &g.before->samples[1]);
  }
  if (g.after) {
    XV_CHECK(g.after->id == 2 && g.after->value == 20);
    XV_CHECK(g.value_after == &g.after->value);
  }
  XV_CHECK(g.links.size() == 2);
  if (g.links.size() == 2) {
    const Node* linked = g.links[1].node;
    XV_CHECK(linked && linked->id == 3 && linked->value == 30);
    XV_CHECK(g.links[0].node == nullptr && g.links[1].field == nullptr);
    XV_CHECK(linked && g.links[0].field == &linked->value);
  }
  if (g.outer) {
    XV_CHECK(g.outer->tag == 4 && g.outer->inner.id == 5 && g.outer->inner.value == 50);
    XV_CHECK((g.outer->inner.samples == std::vector<int>{500, 501}));
    XV_CHECK(g.inner == &g.outer->inner);
    XV_CHECK(g.deepest == &g.outer->inner.value);
  }
  XV_CHECK(g.bag && g.bag->items.size() == 2);
  if (g.bag && g.bag->items.size() == 2) {
    XV_CHECK(g.bag->items[0].a == 6 && g.bag->items[1].b == 70);
    XV_CHECK(g.item == &g.bag->items[1]);
    XV_CHECK(g.item_b == &g.bag->items[1].b);
  }
  // Each object once: no copy was made for a pointer into it.
  XV_CHECK(g.before != g.after && g.inner != g.before);
  const int verdict = xv::verdict();
  // The heap objects the restore made are the program's, as v0's were v0's.
  Node* linked = graph.links.size() == 2 ? graph.links[1].node : nullptr;
  delete graph.before;
  delete graph.after;
  delete linked;
  delete graph.outer;
  delete graph.bag;
  return verdict;
}
