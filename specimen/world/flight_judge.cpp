#include "flight_judge.hpp"

#include <cmath>

#include "geo.hpp"

namespace world {

FlightJudge::FlightJudge(const Mission& mission, const Home& home, double radius_m)
    : radius_m_(radius_m) {
  for (const MissionItem* item : mission.route_points()) {
    Point p;
    geo::offset_ne(home.lat, home.lng, static_cast<std::int32_t>(std::lround(item->lat * 1e7)),
                   static_cast<std::int32_t>(std::lround(item->lng * 1e7)), p.north, p.east);
    points_.push_back(p);
  }
  inside_.assign(points_.size(), false);
}

void FlightJudge::update(const BodyState& state, double /*time_s*/) {
  double nearest = 1e18;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d = std::hypot(state.position.x - points_[i].north, state.position.y - points_[i].east);
    if (d < nearest) nearest = d;
    // A visit starts on entering the circle; leaving it needs twice the radius (hysteresis).
    if (!inside_[i] && d <= radius_m_) {
      inside_[i] = true;
      visits_.push_back(static_cast<int>(i));
    } else if (inside_[i] && d > 2 * radius_m_) {
      inside_[i] = false;
    }
  }
  // Distance from the route polyline, to notice fly-aways.
  double off = nearest;
  for (std::size_t i = 1; i < points_.size(); ++i) {
    const Point& a = points_[i - 1];
    const Point& b = points_[i];
    const double dx = b.north - a.north, dy = b.east - a.east;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((state.position.x - a.north) * dx + (state.position.y - a.east) * dy) / len2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double d = std::hypot(state.position.x - (a.north + t * dx), state.position.y - (a.east + t * dy));
    if (d < off) off = d;
  }
  // Take-off and a return to launch happen near home, which need not be on the route.
  off = std::fmin(off, std::hypot(state.position.x, state.position.y));
  if (off > max_off_route_m_) max_off_route_m_ = off;
}

bool FlightJudge::route_flown_in_order(std::string& why) const {
  for (std::size_t k = 0; k < visits_.size(); ++k) {
    if (visits_[k] != static_cast<int>(k)) {
      why = "visit " + std::to_string(k + 1) + " was route point " + std::to_string(visits_[k] + 1) +
            ", expected " + std::to_string(k + 1);
      if (visits_[k] < static_cast<int>(k)) why += " (revisited)";
      return false;
    }
  }
  if (visits_.size() != points_.size()) {
    why = "reached " + std::to_string(visits_.size()) + " of " + std::to_string(points_.size()) +
          " route points";
    return false;
  }
  return true;
}

double FlightJudge::distance_to_end(const BodyState& state) const {
  if (points_.empty()) return std::hypot(state.position.x, state.position.y);
  const Point& end = points_.back();
  return std::hypot(state.position.x - end.north, state.position.y - end.east);
}

}  // namespace world
