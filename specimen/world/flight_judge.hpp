// Decides, from the world's true positions only, whether a flight succeeded: every route point
// visited in order, none visited twice, landed near the end of the route, not crashed.
#ifndef WORLD_FLIGHT_JUDGE_HPP
#define WORLD_FLIGHT_JUDGE_HPP

#include <string>
#include <vector>

#include "mission_file.hpp"
#include "physics.hpp"
#include "sensors.hpp"

namespace world {

class FlightJudge {
 public:
  // `radius_m`: how close counts as a visit. Points are north/east metres from home.
  FlightJudge(const Mission& mission, const Home& home, double radius_m);

  void update(const BodyState& state, double time_s);
  const std::vector<int>& visits() const { return visits_; }  // route point indices, in order
  std::size_t route_size() const { return points_.size(); }
  // The visits form exactly 0, 1, ..., n-1.
  bool route_flown_in_order(std::string& why) const;
  // Horizontal distance from the vehicle to the last route point.
  double distance_to_end(const BodyState& state) const;
  double max_distance_from_route() const { return max_off_route_m_; }

 private:
  struct Point {
    double north, east;
  };
  std::vector<Point> points_;
  std::vector<bool> inside_;
  std::vector<int> visits_;
  double radius_m_;
  double max_off_route_m_ = 0;
};

}  // namespace world

#endif  // WORLD_FLIGHT_JUDGE_HPP
