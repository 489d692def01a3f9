// diffusion moving robots in real worlds (its decisions on a fake robot: the plugin's own tests).
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

using test::make_choice;
using test::make_settings;
using test::Overrides;

class DiffusionTest : public ::testing::Test {
 protected:
  PluginLoader loader_;
};

// In an open arena a robot without random turns covers speed * time in a straight line.
TEST_F(DiffusionTest, RobotInAnOpenArenaKeepsMovingAtSpeed) {
  RobotSettings settings = make_settings(loader_, 1, 200.0, 200.0);
  settings.robots.placement = Rect{99, 99, 101, 101};
  settings.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller,
                  {{"turn_interval_s", 0.0}, {"speed_mps", 0.8}}));
  RobotWorld world(settings, loader_);
  const Vec2 start = world.bodies()[0].position;
  std::vector<AppMessage> sent;
  for (int i = 0; i < 500; ++i) world.step({}, sent);
  EXPECT_NEAR((world.bodies()[0].position - start).norm(), 0.8 * 50.0, 1e-9);
}

// With random turns a robot still moves at full speed between turns: every step either covers
// speed * dt or turns in place, and most steps move.
TEST_F(DiffusionTest, RandomWalkMovesAtSpeedBetweenTurns) {
  RobotSettings settings = make_settings(loader_, 1, 400.0, 400.0);
  settings.robots.placement = Rect{199, 199, 201, 201};
  settings.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller, {{"turn_interval_s", 5.0}}));
  RobotWorld world(settings, loader_);
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
  RobotSettings settings = make_settings(loader_, 1, 20.0, 200.0, 3);
  settings.robots.placement = Rect{10, 99, 10.5, 101};
  settings.robots.controllers.push_back(
      make_choice(loader_, "diffusion", PluginKind::controller, {{"turn_interval_s", 0.0}}));
  RobotWorld world(settings, loader_);
  std::vector<AppMessage> sent;
  const double r = settings.robots.radius_m;
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
  RobotSettings settings = make_settings(loader_, 30, 8.0, 8.0, 5);
  settings.arena.obstacles.push_back(Rect{3.5, 3.5, 4.5, 4.5});
  settings.robots.controllers.push_back(make_choice(loader_, "diffusion", PluginKind::controller));
  RobotWorld world(settings, loader_);
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
