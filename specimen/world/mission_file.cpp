#include "mission_file.hpp"

#include <fstream>
#include <sstream>

#include "geo.hpp"
#include "messages.hpp"

namespace world {

std::vector<const MissionItem*> Mission::route_points() const {
  std::vector<const MissionItem*> points;
  for (std::size_t i = 1; i < items.size(); ++i) {
    const MissionItem& item = items[i];
    const bool has_position = item.lat != 0.0 || item.lng != 0.0;
    if (item.command == mav::CMD_NAV_WAYPOINT ||
        (item.command == mav::CMD_NAV_LAND && has_position)) {
      points.push_back(&item);
    }
  }
  return points;
}

double Mission::route_length_m() const {
  const auto points = route_points();
  double length = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    length += geo::haversine(points[i - 1]->lat, points[i - 1]->lng, points[i]->lat, points[i]->lng);
  }
  return length;
}

double Mission::route_extent_m() const {
  const auto points = route_points();
  double extent = 0;
  for (const MissionItem* a : points) {
    for (const MissionItem* b : points) {
      const double d = geo::haversine(a->lat, a->lng, b->lat, b->lng);
      if (d > extent) extent = d;
    }
  }
  return extent;
}

double Mission::cruise_speed_ms() const {
  for (const MissionItem& item : items) {
    if (item.command == mav::CMD_DO_CHANGE_SPEED && item.param[1] > 0) return item.param[1];
  }
  return 5.0;
}

bool load_mission(const std::string& path, Mission& out, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot open";
    return false;
  }
  out = Mission{};
  const std::size_t slash = path.find_last_of('/');
  out.name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  std::string line;
  int line_number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    if (!header_seen) {
      if (line.compare(start, 11, "QGC WPL 110") != 0) {
        error = path + ":" + std::to_string(line_number) + ": expected the header 'QGC WPL 110'";
        return false;
      }
      header_seen = true;
      continue;
    }
    std::istringstream fields(line);
    MissionItem item;
    if (!(fields >> item.seq >> item.current >> item.frame >> item.command >> item.param[0] >>
          item.param[1] >> item.param[2] >> item.param[3] >> item.lat >> item.lng >> item.alt >>
          item.autocontinue)) {
      error = path + ":" + std::to_string(line_number) + ": expected 12 fields";
      return false;
    }
    if (item.seq != static_cast<int>(out.items.size())) {
      error = path + ":" + std::to_string(line_number) + ": sequence number " +
              std::to_string(item.seq) + ", expected " + std::to_string(out.items.size());
      return false;
    }
    if (item.lat < -90 || item.lat > 90 || item.lng < -180 || item.lng > 180) {
      error = path + ":" + std::to_string(line_number) + ": latitude/longitude out of range";
      return false;
    }
    out.items.push_back(item);
  }
  if (!header_seen || out.items.size() < 2) {
    error = path + ": a mission needs the header, a home line and at least one command";
    return false;
  }
  if (out.items.size() > 255) {
    error = path + ": more than 255 items";
    return false;
  }
  return true;
}

}  // namespace world
