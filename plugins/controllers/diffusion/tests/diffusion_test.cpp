// diffusion's avoidance and random-walk decisions on a fake robot (SDK test kit).
#include "diffusion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <set>
#include <vector>

#include "swarmnet/testing.hpp"

namespace swarmnet::diffusion {
namespace {

using testing::FakeRobotContext;
using testing::ParamOverrides;
using testing::plugin_args;
using Overrides = ParamOverrides;

class DiffusionTest : public ::testing::Test {
 protected:
  static std::unique_ptr<Controller> make(const Overrides& overrides, std::uint64_t seed = 1) {
    return std::make_unique<Diffusion>(plugin_args<Diffusion>(overrides, seed));
  }
};

// With 24 rays, ray k has bearing 15k degrees: k = 1..3 are front-left, 21..23 front-right.
const Overrides kNoRandomTurns{{"turn_interval_s", 0.0}};

TEST_F(DiffusionTest, ClearFrontDrivesStraightAtSpeed) {
  auto controller = make({{"turn_interval_s", 0.0}, {"speed_mps", 0.6}});
  FakeRobotContext robot;
  controller->init(robot);
  controller->control_step(robot);
  EXPECT_EQ(robot.left_mps, 0.6);
  EXPECT_EQ(robot.right_mps, 0.6);
}

TEST_F(DiffusionTest, TurnsAwayFromTheCloserSide) {
  auto controller = make(kNoRandomTurns);
  FakeRobotContext robot;
  controller->init(robot);
  robot.rays[2] = 0.3;  // front-left
  controller->control_step(robot);
  EXPECT_GT(robot.left_mps, 0.0);  // clockwise: to the right
  EXPECT_LT(robot.right_mps, 0.0);
  EXPECT_EQ(robot.left_mps, -robot.right_mps);

  auto other = make(kNoRandomTurns);
  FakeRobotContext mirror;
  other->init(mirror);
  mirror.rays[22] = 0.3;  // front-right
  other->control_step(mirror);
  EXPECT_LT(mirror.left_mps, 0.0);  // counter-clockwise: to the left
  EXPECT_GT(mirror.right_mps, 0.0);
}

TEST_F(DiffusionTest, KeepsItsTurnUntilTheFrontIsClear) {
  auto controller = make(kNoRandomTurns);
  FakeRobotContext robot;
  controller->init(robot);
  robot.rays[1] = 0.2;
  robot.rays[23] = 0.4;
  controller->control_step(robot);
  ASSERT_GT(robot.left_mps, 0.0);  // right turn
  // The obstacle now reads closer on the right; the turn direction does not flip.
  robot.clear_rays();
  robot.rays[23] = 0.1;
  controller->control_step(robot);
  EXPECT_GT(robot.left_mps, 0.0);
  robot.clear_rays();
  controller->control_step(robot);
  EXPECT_EQ(robot.left_mps, 1.0);
  EXPECT_EQ(robot.right_mps, 1.0);
}

TEST_F(DiffusionTest, IgnoresThingsOutsideTheFrontSectorOrBeyondAvoidDistance) {
  auto controller = make(kNoRandomTurns);
  FakeRobotContext robot;
  controller->init(robot);
  robot.rays[6] = 0.01;   // 90 degrees: alongside
  robot.rays[12] = 0.01;  // behind
  robot.rays[0] = 0.55;   // ahead, but farther than avoid_distance_m
  controller->control_step(robot);
  EXPECT_EQ(robot.left_mps, robot.right_mps);
  robot.rays[3] = 0.49;  // 45 degrees: on the sector's edge, inside
  controller->control_step(robot);
  EXPECT_NE(robot.left_mps, robot.right_mps);
}

TEST_F(DiffusionTest, RangeShorterThanAvoidDistanceMeansClear) {
  auto controller = make(kNoRandomTurns);
  FakeRobotContext robot;
  robot.range_m = 0.3;  // below avoid_distance_m = 0.5: a reading of 0.3 means nothing seen
  robot.clear_rays();
  controller->init(robot);
  controller->control_step(robot);
  EXPECT_EQ(robot.left_mps, robot.right_mps);
}

TEST_F(DiffusionTest, SymmetricObstaclePicksARandomSidePerRobot) {
  std::set<double> sides;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    auto controller = make(kNoRandomTurns, seed);
    FakeRobotContext robot;
    controller->init(robot);
    robot.rays[0] = 0.3;
    robot.rays[1] = robot.rays[23] = 0.35;
    controller->control_step(robot);
    ASSERT_NE(robot.left_mps, robot.right_mps);
    sides.insert(robot.left_mps > 0 ? 1.0 : -1.0);
  }
  EXPECT_EQ(sides.size(), 2U);
}

// Random turns come at exponential intervals with the configured mean and end at headings spread
// uniformly around the circle.
TEST_F(DiffusionTest, RandomTurnsAtTheConfiguredMeanInterval) {
  auto controller = make({{"turn_interval_s", 10.0}});
  FakeRobotContext robot;
  controller->init(robot);
  int turns = 0;
  bool turning = false;
  Vec2 heading_sum = Vec2::Zero();
  for (int step = 0; step < 40000; ++step) {  // 4000 s: 400 turns expected
    controller->control_step(robot);
    const bool now_turning = robot.left_mps != robot.right_mps;
    if (now_turning && !turning) ++turns;
    if (turning && !now_turning) {
      heading_sum += Vec2(std::cos(robot.pose_heading_rad), std::sin(robot.pose_heading_rad));
    }
    turning = now_turning;
    robot.advance();
  }
  // A Poisson count of mean 400 has standard deviation 20; a turn drawn while the previous one
  // is still under way (they last at most about 1 s) merges with it, a few percent of them.
  EXPECT_GT(turns, 330);
  EXPECT_LT(turns, 450);
  // Uniform headings: the mean resultant length is about 1 / sqrt(turns), 0.05.
  EXPECT_LT(heading_sum.norm() / turns, 0.15);
}

TEST_F(DiffusionTest, ResetReturnsToTheStateAfterInit) {
  auto controller = make({{"turn_interval_s", 1.0}});
  auto run = [&](FakeRobotContext& robot) {
    std::vector<double> commands;
    for (int step = 0; step < 300; ++step) {
      if (step % 37 == 0) robot.rays[step % 3 == 0 ? 0 : 2] = 0.2;
      if (step % 37 == 5) robot.clear_rays();
      controller->control_step(robot);
      commands.push_back(robot.left_mps);
      robot.advance();
    }
    return commands;
  };
  FakeRobotContext first;
  controller->init(first);
  const auto before = run(first);
  controller->reset();
  FakeRobotContext second;
  const auto after = run(second);
  EXPECT_EQ(before, after);
}

}  // namespace
}  // namespace swarmnet::diffusion
