// v0: heap nodes in a cycle, a shared_ptr held twice, pointers into a root's fields.
#include <memory>

#include "check.hpp"

struct Node {
  int value;
  Node* next;
};

struct Target {
  double lat;
  double lon;
};

struct Nav {
  Target home;
  Target waypoints[3];
  Target* active;     // into this root's array
  double* lat_probe;  // into a field of a field
};

struct Shared {
  int refs;
};

struct Graph {
  Node* ring;
  std::shared_ptr<Shared> first;
  std::shared_ptr<Shared> second;
  Nav* nav;          // to another root
  int* outside;      // to something not checkpointed
};

SYMCR_CHECKPOINT Nav nav;
SYMCR_CHECKPOINT Graph graph;
int not_checkpointed = 5;

int main(int argc, char** argv) {
  Node* a = new Node{1, nullptr};
  Node* b = new Node{2, nullptr};
  Node* c = new Node{3, nullptr};
  a->next = b;
  b->next = c;
  c->next = a;
  graph.ring = a;
  graph.first = std::make_shared<Shared>(Shared{41});
  graph.second = graph.first;
  graph.nav = &nav;
  graph.outside = &not_checkpointed;
  nav.home = {1.5, 2.5};
  for (int i = 0; i < 3; ++i) nav.waypoints[i] = {10.0 + i, 20.0 + i};
  nav.active = &nav.waypoints[2];
  nav.lat_probe = &nav.home.lat;
  int status = xv::save(argc, argv);
  delete a;
  delete b;
  delete c;
  return status;
}
