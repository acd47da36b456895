// v0: pointers into heap objects met, in the save's traversal, before the pointer to the
// object itself, after it, and both inside containers; into a heap object's own container
// elements; at the object's first field (the same address as the object); and into a Node
// that is a member of a heap Outer met later still. Each must come back pointing into the
// restored object, never at a copy.
#include <vector>

#include "check.hpp"

struct Node {
  int id;
  int value;
  std::vector<int> samples;
};

struct Outer {
  int tag;
  Node inner;
};

struct Item {
  int a;
  int b;
};

struct Bag {
  std::vector<Item> items;
};

struct Link {
  int* field;
  Node* node;
};

struct Graph {
  int* value_before;        // &before->value: met before `before`
  int* id_before;           // &before->id: the Node's own address, as an int*
  int* sample_before;       // &before->samples[1]: in the Node's vector, before the Node
  Node* before;
  Node* after;
  int* value_after;         // &after->value: met after `after`
  std::vector<Link> links;  // links[0].field = &linked->value, links[1].node = linked
  int* deepest;             // &outer->inner.value: before the Node, itself before its Outer
  Node* inner;              // &outer->inner
  Outer* outer;
  int* item_b;              // &bag->items[1].b: before the Item, itself before its Bag
  Item* item;               // &bag->items[1]
  Bag* bag;
};

SYMCR_CHECKPOINT Graph graph;

int main(int argc, char** argv) {
  Node* before = new Node{1, 10, {100, 101, 102}};
  Node* after = new Node{2, 20, {200}};
  Node* linked = new Node{3, 30, {}};
  Outer* outer = new Outer{4, Node{5, 50, {500, 501}}};
  Bag* bag = new Bag{{Item{6, 60}, Item{7, 70}}};
  graph.value_before = &before->value;
  graph.id_before = &before->id;
  graph.sample_before = &before->samples[1];
  graph.before = before;
  graph.after = after;
  graph.value_after = &after->value;
  graph.links = {Link{&linked->value, nullptr}, Link{nullptr, linked}};
  graph.deepest = &outer->inner.value;
  graph.inner = &outer->inner;
  graph.outer = outer;
  graph.item_b = &bag->items[1].b;
  graph.item = &bag->items[1];
  graph.bag = bag;
  const int result = xv::save(argc, argv);
  delete before;
  delete after;
  delete linked;
  delete outer;
  delete bag;
  return result;
}
