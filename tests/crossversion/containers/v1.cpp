// v1: the element type gained a field and members moved; contents must come back.
#include <array>
#include <cstdint>
#include <deque>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include "check.hpp"

struct Waypoint {
  float alt;
  double lon;
  double lat;
  int hold_seconds = 9;
};

struct Mission {
  std::vector<Waypoint> items;
  std::string name;
  std::map<std::string, int> counters;
  std::deque<int> recent;
  std::list<std::string> log;
  std::unordered_map<int, std::string> labels;
  std::set<int> visited;
  std::optional<double> home_alt;
  std::optional<int> empty = 4;
  std::variant<int, std::string> status;
  std::pair<int, float> range;
  std::tuple<int, double, char> triple;
  std::array<short, 3> trims;
  std::unique_ptr<Waypoint> rally;
  std::unique_ptr<Waypoint> none = std::make_unique<Waypoint>();
};

SYMCR_CHECKPOINT Mission mission;

int main(int argc, char** argv) {
  mission.items = {{0, 0, 0, 0}};
  mission.counters = {{"stale", 99}};
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(mission.name == "ISTAR route with a name longer than the small-string buffer");
  XV_CHECK(mission.items.size() == 3);
  if (mission.items.size() == 3) {
    XV_CHECK(mission.items[0].lat == 42.1 && mission.items[0].lon == -71.2);
    XV_CHECK(mission.items[2].alt == 40.0f);
    XV_CHECK(mission.items[1].hold_seconds == 9);  // added field: value-initialised element
  }
  XV_CHECK((mission.recent == std::deque<int>{7, 8, 9}));
  XV_CHECK((mission.log == std::list<std::string>{"armed", "takeoff"}));
  XV_CHECK((mission.counters == std::map<std::string, int>{{"laps", 3}, {"resets", 1}}));
  XV_CHECK(mission.labels.size() == 2 && mission.labels[1] == "one" &&
           mission.labels[2] == "two");
  XV_CHECK((mission.visited == std::set<int>{1, 3, 5}));
  XV_CHECK(mission.home_alt && *mission.home_alt == 12.5);
  XV_CHECK(!mission.empty);
  XV_CHECK(std::holds_alternative<std::string>(mission.status) &&
           std::get<std::string>(mission.status) == "cruising");
  XV_CHECK(mission.range.first == 4 && mission.range.second == 2.5f);
  XV_CHECK(std::get<0>(mission.triple) == 7 && std::get<1>(mission.triple) == 0.25 &&
           std::get<2>(mission.triple) == 'q');
  XV_CHECK((mission.trims == std::array<short, 3>{{-1, 0, 1}}));
  XV_CHECK(mission.rally && mission.rally->lat == 1.0 && mission.rally->alt == 3.0f);
  XV_CHECK(!mission.none);
  return xv::verdict();
}
