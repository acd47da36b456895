// v0: standard containers and vocabulary types.
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
  double lat;
  double lon;
  float alt;
};

struct Mission {
  std::string name;
  std::vector<Waypoint> items;
  std::deque<int> recent;
  std::list<std::string> log;
  std::map<std::string, int> counters;
  std::unordered_map<int, std::string> labels;
  std::set<int> visited;
  std::optional<double> home_alt;
  std::optional<int> empty;
  std::variant<int, std::string> status;
  std::pair<int, float> range;
  std::tuple<int, double, char> triple;
  std::array<short, 3> trims;
  std::unique_ptr<Waypoint> rally;
  std::unique_ptr<Waypoint> none;
};

SYMCR_CHECKPOINT Mission mission;

int main(int argc, char** argv) {
  mission.name = "ISTAR route with a name longer than the small-string buffer";
  mission.items = {{42.1, -71.2, 30.0f}, {42.2, -71.3, 35.0f}, {42.3, -71.4, 40.0f}};
  mission.recent = {7, 8, 9};
  mission.log = {"armed", "takeoff"};
  mission.counters = {{"laps", 3}, {"resets", 1}};
  mission.labels = {{1, "one"}, {2, "two"}};
  mission.visited = {5, 1, 3};
  mission.home_alt = 12.5;
  mission.status = std::string("cruising");
  mission.range = {4, 2.5f};
  mission.triple = {7, 0.25, 'q'};
  mission.trims = {{-1, 0, 1}};
  mission.rally = std::make_unique<Waypoint>(Waypoint{1.0, 2.0, 3.0f});
  return xv::save(argc, argv);
}
