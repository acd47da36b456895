// Mission files: the "QGC WPL 110" text format of QGroundControl and MAVProxy (see
// specimen/missions/README.md), and the route measures the experiment reports.
#ifndef WORLD_MISSION_FILE_HPP
#define WORLD_MISSION_FILE_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace world {

struct MissionItem {
  int seq = 0;
  int current = 0;
  int frame = 3;  // MAV_FRAME_GLOBAL_RELATIVE_ALT
  int command = 16;
  double param[4] = {0, 0, 0, 0};
  double lat = 0, lng = 0;  // degrees
  double alt = 0;           // m above home
  int autocontinue = 1;
};

struct Mission {
  std::string name;
  std::vector<MissionItem> items;  // items[0] is home

  // The points the vehicle must fly over, in order: waypoints, and a LAND's location.
  std::vector<const MissionItem*> route_points() const;
  // Sum of great-circle legs between consecutive route points, metres.
  double route_length_m() const;
  // Largest distance between any two route points, metres.
  double route_extent_m() const;
  // The first DO_CHANGE_SPEED, else the autopilot's default (5 m/s).
  double cruise_speed_ms() const;
};

// Parses `path`; on failure returns false with a "file:line: message" in `error`.
bool load_mission(const std::string& path, Mission& out, std::string& error);

}  // namespace world

#endif  // WORLD_MISSION_FILE_HPP
