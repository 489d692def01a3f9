// follow_the_leader on the SDK test kit: a fake robot whose sensors the test sets.
#include "follow_the_leader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "swarmnet/testing.hpp"

namespace example::follow_the_leader {
namespace {

using namespace swarmnet;
using swarmnet::testing::FakeRobotContext;
using swarmnet::testing::plugin_args;

ReceivedMessage beacon_from_leader(double x, double y) {
  ReceivedMessage beacon;
  beacon.source = 0;
  beacon.destination = kBroadcast;
  const double xy[2] = {x, y};
  beacon.payload.resize(sizeof xy);
  std::memcpy(beacon.payload.data(), xy, sizeof xy);
  return beacon;
}

// A follower as examples/out_of_tree/scenario.yaml has them: top speed 2 m/s, axle 0.14 m, steps
// of 0.1 s (the defaults of FakeRobotContext are gentler and hid a controller that spun).
FakeRobotContext scenario_follower() {
  FakeRobotContext robot;
  robot.robot_id = 1;
  robot.max_speed = 2.0;
  robot.axle = 0.14;
  robot.step_length_s = 0.1;
  return robot;
}

double bearing_error(const FakeRobotContext& robot, const Vec2& target) {
  const Vec2 to = target - robot.pose_position;
  return std::remainder(std::atan2(to.y(), to.x()) - robot.pose_heading_rad,
                        2.0 * std::numbers::pi);
}

TEST(FollowTheLeader, TheLeaderBeaconsItsPositionEveryInterval) {
  FollowTheLeader leader(plugin_args<FollowTheLeader>({{"beacon_interval_s", 0.5}}));
  FakeRobotContext robot;  // robot 0: the leader by default
  robot.pose_position = Vec2(3.0, 4.0);
  leader.init(robot);
  for (int step = 0; step < 10; ++step) {  // 1 s in steps of 0.1 s
    leader.control_step(robot);
    robot.advance();
  }
  ASSERT_EQ(robot.sent.size(), 2U);
  EXPECT_EQ(robot.sent[0].destination, kBroadcast);
  double xy[2];
  std::memcpy(xy, robot.sent[0].payload.data(), sizeof xy);
  EXPECT_EQ(xy[0], 3.0);
  EXPECT_EQ(xy[1], 4.0);
  EXPECT_GT(robot.right_mps, robot.left_mps);  // a left-hand circle
}

TEST(FollowTheLeader, AFollowerWaitsThenDrivesTowardsTheBeacon) {
  FollowTheLeader follower(plugin_args<FollowTheLeader>());
  FakeRobotContext robot;
  robot.robot_id = 1;
  follower.init(robot);
  follower.control_step(robot);
  EXPECT_EQ(robot.left_mps, 0.0);  // nothing heard yet
  EXPECT_EQ(robot.right_mps, 0.0);

  robot.received.push_back(beacon_from_leader(20.0, 0.0));  // straight ahead, 20 m away
  follower.control_step(robot);
  EXPECT_GT(robot.left_mps, 0.0);
  EXPECT_GT(robot.right_mps, 0.0);
  EXPECT_EQ(robot.recorded.at("distance_to_leader_m").back(), 20.0);
}

// Started 20 m from the leader and facing off by 90 degrees (to either side), 172 or 17: the
// follower turns towards it at most 2 rad/s and never past its bearing, drives there and stops
// at follow_distance_m (5 m). The controller this replaced turned 1.14 rad a step and spun.
TEST(FollowTheLeader, AFollowerTurnsTowardsTheLeaderWithoutOvershootAndStopsAtTheDistance) {
  const Vec2 leader(20.0, 0.0);
  for (const double heading : {std::numbers::pi / 2, -std::numbers::pi / 2, 3.0, 0.3}) {
    SCOPED_TRACE(heading);
    FollowTheLeader follower(plugin_args<FollowTheLeader>({{"follow_distance_m", 5.0}}));
    FakeRobotContext robot = scenario_follower();
    robot.pose_heading_rad = heading;
    follower.init(robot);
    robot.received.push_back(beacon_from_leader(leader.x(), leader.y()));
    double error = bearing_error(robot, leader);
    double largest_turn = 0.0;
    int overshoots = 0;   // steps that left the heading past the leader's bearing
    int steps_worse = 0;  // steps that left the heading further from it
    double error_at_2_s = 0.0;
    int step = 0;
    for (; step < 300 && (robot.pose_position - leader).norm() > 5.0; ++step) {
      const double heading_before = robot.pose_heading_rad;
      follower.control_step(robot);
      robot.received.clear();  // the beacon was delivered once; the follower remembers it
      robot.advance();
      largest_turn =
          std::max(largest_turn, std::abs(std::remainder(robot.pose_heading_rad - heading_before,
                                                         2.0 * std::numbers::pi)));
      const double next = bearing_error(robot, leader);
      if (next * error < 0.0 && std::abs(next) > 1e-6) ++overshoots;
      if (std::abs(next) > std::abs(error) + 1e-9) ++steps_worse;
      error = next;
      if (step == 20) error_at_2_s = error;
    }
    EXPECT_LE(largest_turn, 2.0 * robot.step_length_s + 1e-9);
    EXPECT_EQ(overshoots, 0);
    EXPECT_EQ(steps_worse, 0);
    EXPECT_LT(std::abs(error_at_2_s), 0.01);  // facing the leader after 2 s
    // 15 m at 1.6 m/s after at most 2 s of turning: there within 12 s, and at most one step
    // (0.16 m) inside the follow distance.
    EXPECT_LT(step, 120);
    const double distance = (robot.pose_position - leader).norm();
    EXPECT_LE(distance, 5.0);
    EXPECT_GT(distance, 5.0 - 1.6 * robot.step_length_s - 1e-9);
    // And there it stays.
    const Vec2 arrived = robot.pose_position;
    for (int i = 0; i < 50; ++i) {
      follower.control_step(robot);
      robot.advance();
    }
    EXPECT_EQ(robot.pose_position, arrived);
  }
}

TEST(FollowTheLeader, AFollowerWithinTheFollowDistanceStopsAndDrivesOnWhenTheLeaderMoves) {
  FollowTheLeader follower(plugin_args<FollowTheLeader>({{"follow_distance_m", 5.0}}));
  FakeRobotContext robot = scenario_follower();
  robot.pose_heading_rad = 1.0;  // not facing the leader: it must not turn on the spot either
  follower.init(robot);
  robot.left_mps = robot.right_mps = 1.0;
  robot.received.push_back(beacon_from_leader(5.0, 0.0));  // exactly at the follow distance
  follower.control_step(robot);
  EXPECT_EQ(robot.left_mps, 0.0);
  EXPECT_EQ(robot.right_mps, 0.0);

  robot.received = {beacon_from_leader(8.0, 0.0)};  // the leader moved on
  follower.control_step(robot);
  EXPECT_GT(robot.left_mps, robot.right_mps);  // turns right, towards the leader
  EXPECT_GT(robot.left_mps + robot.right_mps, 0.0);
}

}  // namespace
}  // namespace example::follow_the_leader
