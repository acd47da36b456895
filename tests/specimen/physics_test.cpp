#include "physics.hpp"

#include <gtest/gtest.h>

namespace {

world::WindModel calm() {
  world::WindModel wind;
  wind.gust_sigma = 0;
  return wind;
}

TEST(Physics, RestsOnTheGroundWithMotorsOff) {
  world::Physics physics(world::Airframe{}, calm(), 1);
  for (int i = 0; i < 400; ++i) physics.step({0, 0, 0, 0}, 0.0025);
  EXPECT_TRUE(physics.state().on_ground);
  EXPECT_DOUBLE_EQ(physics.state().position.z, 0.0);
  EXPECT_FALSE(physics.crashed());
}

TEST(Physics, EqualMotorsAboveHoverClimbStraightUp) {
  world::Airframe airframe;
  world::Physics physics(airframe, calm(), 1);
  const double hover = airframe.mass * 9.80665 / (4 * airframe.motor_thrust_max);
  const double u = hover * 1.2;
  for (int i = 0; i < 800; ++i) physics.step({u, u, u, u}, 0.0025);  // 2 s
  const auto& s = physics.state();
  EXPECT_LT(s.position.z, -1.0);  // up is negative down
  EXPECT_NEAR(s.position.x, 0.0, 1e-6);
  EXPECT_NEAR(s.position.y, 0.0, 1e-6);
  EXPECT_NEAR(s.rates.norm(), 0.0, 1e-9);
}

TEST(Physics, FrontMotorsFasterPitchTheNoseUp) {
  world::Airframe airframe;
  world::Physics physics(airframe, calm(), 1);
  for (int i = 0; i < 400; ++i) physics.step({0.6, 0.6, 0.6, 0.6}, 0.0025);
  // Motors 1 and 3 are in front.
  for (int i = 0; i < 20; ++i) physics.step({0.65, 0.55, 0.65, 0.55}, 0.0025);
  EXPECT_GT(physics.state().rates.y, 0.0);
}

TEST(Physics, FallingWithoutThrustCrashes) {
  world::Airframe airframe;
  world::Physics physics(airframe, calm(), 1);
  for (int i = 0; i < 1200; ++i) physics.step({0.8, 0.8, 0.8, 0.8}, 0.0025);  // climb 3 s
  ASSERT_FALSE(physics.state().on_ground);
  for (int i = 0; i < 4000 && !physics.state().on_ground; ++i) physics.step({0, 0, 0, 0}, 0.0025);
  EXPECT_TRUE(physics.crashed());
}

}  // namespace
