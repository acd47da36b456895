#include "flight_judge.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geo.hpp"

namespace {

// Three route points 100 m apart going north from home.
world::Mission straight_mission() {
  world::Mission m;
  world::MissionItem home;
  home.lat = 45.0;
  home.lng = 7.0;
  m.items.push_back(home);
  for (int i = 1; i <= 3; ++i) {
    world::MissionItem wp;
    wp.seq = i;
    wp.lat = 45.0 + (100.0 * i) / (geo::kEarthRadius * geo::kDegToRad);
    wp.lng = 7.0;
    m.items.push_back(wp);
  }
  return m;
}

world::Home home_of(const world::Mission& m) {
  return {static_cast<std::int32_t>(std::lround(m.items[0].lat * 1e7)),
          static_cast<std::int32_t>(std::lround(m.items[0].lng * 1e7))};
}

void fly_to(world::FlightJudge& judge, double north_from, double north_to) {
  world::BodyState s;
  const double step = north_to > north_from ? 0.5 : -0.5;
  for (double n = north_from; (step > 0) ? n <= north_to : n >= north_to; n += step) {
    s.position = {n, 0, -10};
    judge.update(s, 0);
  }
}

TEST(FlightJudge, AcceptsTheRouteInOrder) {
  const world::Mission m = straight_mission();
  world::FlightJudge judge(m, home_of(m), 3.0);
  fly_to(judge, 0, 300);
  std::string why;
  EXPECT_TRUE(judge.route_flown_in_order(why)) << why;
}

TEST(FlightJudge, RejectsARevisit) {
  const world::Mission m = straight_mission();
  world::FlightJudge judge(m, home_of(m), 3.0);
  fly_to(judge, 0, 150);
  fly_to(judge, 150, 50);  // back over point 1
  fly_to(judge, 50, 300);
  std::string why;
  EXPECT_FALSE(judge.route_flown_in_order(why));
  EXPECT_NE(why.find("revisited"), std::string::npos) << why;
}

TEST(FlightJudge, RejectsAMissedPoint) {
  const world::Mission m = straight_mission();
  world::FlightJudge judge(m, home_of(m), 3.0);
  fly_to(judge, 0, 250);
  std::string why;
  EXPECT_FALSE(judge.route_flown_in_order(why));
  EXPECT_NE(why.find("reached 2 of 3"), std::string::npos) << why;
}

}  // namespace
