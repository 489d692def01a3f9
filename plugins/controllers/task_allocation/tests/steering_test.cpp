// steering: go-to-point and avoidance on a fake differential drive.
#include "steering.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "swarmnet/testing.hpp"

namespace swarmnet::task_allocation {
namespace {

using testing::FakeRobotContext;

TEST(TaskAllocationSteeringTest, TargetAheadDrivesAtFullSpeed) {
  const WheelSpeeds w = steer_to(Vec2(0, 0), 0.0, Vec2(100, 0), 5.0, 0.14, 0.1);
  EXPECT_DOUBLE_EQ(w.left_mps, 5.0);
  EXPECT_DOUBLE_EQ(w.right_mps, 5.0);
}

TEST(TaskAllocationSteeringTest, TargetBehindTurnsInPlace) {
  const WheelSpeeds w = steer_to(Vec2(0, 0), 0.0, Vec2(-100, 1), 5.0, 0.14, 0.1);
  EXPECT_DOUBLE_EQ(w.left_mps, -w.right_mps);
  EXPECT_GT(w.right_mps, 0.0);  // target on the left: counter-clockwise
}

TEST(TaskAllocationSteeringTest, SmallErrorSteersProportionally) {
  const WheelSpeeds left = steer_to(Vec2(0, 0), 0.0, Vec2(100, 10), 5.0, 0.14, 0.1);
  EXPECT_GT(left.right_mps, left.left_mps);
  EXPECT_GT(left.left_mps, 0.0);
  EXPECT_LE(left.right_mps, 5.0);
  const WheelSpeeds more = steer_to(Vec2(0, 0), 0.0, Vec2(100, 30), 5.0, 0.14, 0.1);
  EXPECT_GT(more.right_mps - more.left_mps, left.right_mps - left.left_mps);
}

TEST(TaskAllocationSteeringTest, ReachesAPointBehindIt) {
  FakeRobotContext robot;
  robot.max_speed = 5.0;
  robot.world = Arena{500.0, 500.0, {}};
  robot.pose_position = Vec2(100.0, 100.0);
  robot.pose_heading_rad = 0.3;
  const Vec2 target(40.0, 180.0);  // 100 m away, behind on the left
  Steering steering;
  int steps = 0;
  while ((robot.pose_position - target).norm() > 1.0 && steps < 1000) {
    steering.drive(robot, target);
    robot.advance();
    ++steps;
  }
  // 100 m at 5 m/s is 200 steps of 0.1 s, plus the turn.
  EXPECT_LT(steps, 260);
}

TEST(TaskAllocationSteeringTest, TurnsAwayFromAnObstacleAheadAndBacksOffWhenClose) {
  FakeRobotContext robot;
  robot.max_speed = 5.0;
  Steering steering;
  robot.rays[1] = 0.4;  // front-left (15 degrees)
  steering.drive(robot, Vec2(100.0, 0.0));
  EXPECT_GT(robot.left_mps, robot.right_mps);  // clockwise, to the right
  EXPECT_NEAR(robot.left_mps + robot.right_mps, 0.0, 1e-12);

  Steering close;
  FakeRobotContext near;
  near.max_speed = 5.0;
  near.rays[0] = 0.1;
  close.drive(near, Vec2(100.0, 0.0));
  EXPECT_LT(near.left_mps + near.right_mps, 0.0);  // backing off
}

TEST(TaskAllocationSteeringTest, AfterAvoidingItDrivesStraightForAMetre) {
  FakeRobotContext robot;
  robot.max_speed = 5.0;
  Steering steering;
  robot.rays[23] = 0.3;
  steering.drive(robot, Vec2(0.0, 100.0));
  robot.advance();
  robot.clear_rays();
  steering.drive(robot, Vec2(0.0, 100.0));  // target on the left, but it escapes straight first
  EXPECT_EQ(robot.left_mps, 5.0);
  EXPECT_EQ(robot.right_mps, 5.0);
  robot.advance();
  robot.advance();
  robot.advance();  // 0.3 s > 1 m / 5 m/s
  steering.drive(robot, Vec2(0.0, 100.0));
  EXPECT_NE(robot.left_mps, robot.right_mps);
}

}  // namespace
}  // namespace swarmnet::task_allocation
