// v1: Node and Target reordered their fields and Nav its members; pointers must follow by
// name, the cycle and the sharing must survive.
#include <memory>

#include "check.hpp"

struct Node {
  Node* next;
  long value;
};

struct Target {
  double lon;
  double lat;
};

struct Nav {
  double* lat_probe;
  Target* active;
  Target waypoints[3];
  Target home;
};

struct Shared {
  int refs;
};

struct Graph {
  int* outside;
  Nav* nav;
  std::shared_ptr<Shared> second;
  std::shared_ptr<Shared> first;
  Node* ring;
};

SYMCR_CHECKPOINT Graph graph;
SYMCR_CHECKPOINT Nav nav;
int local_value = 9;

int main(int argc, char** argv) {
  graph.outside = &local_value;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  Node* a = graph.ring;
  XV_CHECK(a != nullptr);
  if (a && a->next && a->next->next) {
    XV_CHECK(a->value == 1 && a->next->value == 2 && a->next->next->value == 3);
    XV_CHECK(a->next->next->next == a);  // the cycle is kept
  }
  XV_CHECK(graph.first && graph.first == graph.second);  // sharing is kept
  XV_CHECK(graph.first && graph.first->refs == 41);
  XV_CHECK(graph.first.use_count() == 2);
  XV_CHECK(graph.nav == &nav);
  XV_CHECK(nav.active == &nav.waypoints[2]);
  XV_CHECK(nav.waypoints[2].lat == 12.0 && nav.waypoints[2].lon == 22.0);
  XV_CHECK(nav.lat_probe == &nav.home.lat);
  XV_CHECK(graph.outside == &local_value);  // pointed outside: kept this build's value
  if (a && a->next && a->next->next) {
    Node* b = a->next;
    Node* c = b->next;
    delete a;
    delete b;
    delete c;
  }
  return xv::verdict();
}
