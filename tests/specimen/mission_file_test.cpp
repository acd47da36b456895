#include "mission_file.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace {

world::Mission load(const std::string& name) {
  world::Mission mission;
  std::string error;
  EXPECT_TRUE(world::load_mission(std::string(SPECIMEN_MISSIONS_DIR) + "/" + name, mission, error))
      << error;
  return mission;
}

TEST(MissionFile, IstarIsSixWaypointsOnA130MetreRoute) {
  const world::Mission m = load("istar.waypoints");
  EXPECT_EQ(m.route_points().size(), 6u);
  EXPECT_NEAR(m.route_length_m(), 130.0, 2.0);
}

TEST(MissionFile, BusRouteIs21WaypointsOver7550MetresAnd4720Across) {
  const world::Mission m = load("busroute.waypoints");
  EXPECT_EQ(m.route_points().size(), 21u);
  EXPECT_NEAR(m.route_length_m(), 7550.0, 10.0);
  EXPECT_NEAR(m.route_extent_m(), 4720.0, 10.0);
  EXPECT_DOUBLE_EQ(m.cruise_speed_ms(), 12.0);
}

TEST(MissionFile, ErrorsNameTheLine) {
  const std::string path = ::testing::TempDir() + "bad.waypoints";
  {
    std::ofstream out(path);
    out << "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\t1\n2\t0\t3\t16\t0\t0\t0\t0\t1\t2\t3\t1\n";
  }
  world::Mission mission;
  std::string error;
  EXPECT_FALSE(world::load_mission(path, mission, error));
  EXPECT_NE(error.find(":3: sequence number 2, expected 1"), std::string::npos) << error;
  std::remove(path.c_str());
}

TEST(MissionFile, RequiresTheHeader) {
  const std::string path = ::testing::TempDir() + "noheader.waypoints";
  {
    std::ofstream out(path);
    out << "0\t1\t0\t16\t0\t0\t0\t0\t1\t2\t3\t1\n";
  }
  world::Mission mission;
  std::string error;
  EXPECT_FALSE(world::load_mission(path, mission, error));
  EXPECT_NE(error.find("QGC WPL 110"), std::string::npos) << error;
  std::remove(path.c_str());
}

}  // namespace
