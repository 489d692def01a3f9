// diffusion: avoidance decisions on a fake robot, and motion in real worlds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <vector>

#include "robot/robot_world.hpp"
#include "robot_test_support.hpp"

namespace swarmnet {
namespace {

using test::FakeRobotContext;
using test::make_choice;
using test::make_scenario;
using test::Overrides;

class DiffusionTest : public ::testing::Test {
 protected:
  PluginInstance<Controller> make(const Overrides& overrides, std::uint64_t seed = 1) {
    PluginArgs args;
    args.params = make_choice(loader_, "diffusion", PluginKind::controller, overrides).params;
    args.seed = seed;
    return loader_.create<Controller>("diffusion", args);
  }

  PluginLoader loader_;
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

// In an open arena a robot without random turns covers speed * time in a straight line.
TEST_F(DiffusionTest, RobotInAnOpenArenaKeepsMovingAtSpeed) {
  Scenario scenario = make_scenario(loader_, 1, 200.0, 200.0);
  scenario.robots.placement = Rect{99, 99, 101, 101};
  scenario.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller,
                  {{"turn_interval_s", 0.0}, {"speed_mps", 0.8}}));
  RobotWorld world(scenario, loader_);
  const Vec2 start = world.bodies()[0].position;
  std::vector<AppMessage> sent;
  for (int i = 0; i < 500; ++i) world.step({}, sent);
  EXPECT_NEAR((world.bodies()[0].position - start).norm(), 0.8 * 50.0, 1e-9);
}

// With random turns a robot still moves at full speed between turns: every step either covers
// speed * dt or turns in place, and most steps move.
TEST_F(DiffusionTest, RandomWalkMovesAtSpeedBetweenTurns) {
  Scenario scenario = make_scenario(loader_, 1, 400.0, 400.0);
  scenario.robots.placement = Rect{199, 199, 201, 201};
  scenario.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller, {{"turn_interval_s", 5.0}}));
  RobotWorld world(scenario, loader_);
  std::vector<AppMessage> sent;
  int moving = 0;
  int turning = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 before = world.bodies()[0].position;
    world.step({}, sent);
    const double moved = (world.bodies()[0].position - before).norm();
    if (std::abs(moved - 0.1) < 1e-9) {
      ++moving;
    } else if (moved < 1e-12) {
      ++turning;
    } else {
      ADD_FAILURE() << "step " << i << " moved " << moved;
    }
  }
  EXPECT_EQ(moving + turning, 2000);
  EXPECT_GT(moving, 1600);
  EXPECT_GT(turning, 20);  // about 40 turns in 200 s
}

// A robot heading for a wall turns away before touching it, the shorter way round.
TEST_F(DiffusionTest, AvoidsAWallAheadWithoutTouchingIt) {
  Scenario scenario = make_scenario(loader_, 1, 20.0, 200.0, 3);
  scenario.robots.placement = Rect{10, 99, 10.5, 101};
  scenario.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller, {{"turn_interval_s", 0.0}}));
  RobotWorld world(scenario, loader_);
  std::vector<AppMessage> sent;
  const double r = scenario.robots.radius_m;
  for (int i = 0; i < 3000; ++i) {
    world.step({}, sent);
    const Vec2& p = world.bodies()[0].position;
    // The walls at x = 0 and x = 20 are met at an angle: the robot turns before touching.
    ASSERT_GT(std::min(p.x(), 20.0 - p.x()) - r, 0.05) << "step " << i;
  }
}

// Robots in a small box keep moving: no robot spends long without making progress, and each
// covers ground in every window.
TEST_F(DiffusionTest, RobotsInABoxNeverGetStuck) {
  Scenario scenario = make_scenario(loader_, 30, 8.0, 8.0, 5);
  scenario.arena.obstacles.push_back(Rect{3.5, 3.5, 4.5, 4.5});
  scenario.robots.controllers.push_back(make_choice(loader_, "diffusion", PluginKind::controller));
  RobotWorld world(scenario, loader_);
  std::vector<AppMessage> sent;
  const std::size_t n = world.robot_count();
  std::vector<double> window_path(n, 0.0);
  std::vector<Vec2> window_start(n);
  for (std::size_t i = 0; i < n; ++i) window_start[i] = world.bodies()[i].position;
  double min_window_path = 1e9;
  double min_window_displacement = 1e9;
  std::vector<int> still_steps(n, 0);  // current run of steps without translation
  int longest_still = 0;
  for (int step = 1; step <= 6000; ++step) {  // 600 s
    std::vector<Vec2> before(n);
    for (std::size_t i = 0; i < n; ++i) before[i] = world.bodies()[i].position;
    world.step({}, sent);
    for (std::size_t i = 0; i < n; ++i) {
      const double moved = (world.bodies()[i].position - before[i]).norm();
      window_path[i] += moved;
      still_steps[i] = moved < 1e-6 ? still_steps[i] + 1 : 0;
      longest_still = std::max(longest_still, still_steps[i]);
    }
    if (step % 300 == 0) {  // 30 s windows
      for (std::size_t i = 0; i < n; ++i) {
        min_window_path = std::min(min_window_path, window_path[i]);
        min_window_displacement = std::min(min_window_displacement,
                                           (world.bodies()[i].position - window_start[i]).norm());
        window_path[i] = 0.0;
        window_start[i] = world.bodies()[i].position;
      }
    }
  }
  // At 1 m/s a free robot covers 30 m per window; avoidance and random turns cost some of it.
  EXPECT_GT(min_window_path, 10.0);
  EXPECT_GT(min_window_displacement, 0.1);
  // Turning in place among neighbours takes a few seconds at most; nobody is pinned.
  EXPECT_LT(longest_still, 100);  // 10 s
}

}  // namespace
}  // namespace swarmnet
