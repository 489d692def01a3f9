// follow_the_leader on the SDK test kit: a fake robot whose sensors the test sets.
#include "follow_the_leader.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "swarmnet/testing.hpp"

namespace example::follow_the_leader {
namespace {

using namespace swarmnet;
using swarmnet::testing::FakeRobotContext;
using swarmnet::testing::plugin_args;

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

  ReceivedMessage beacon;
  beacon.source = 0;
  beacon.destination = kBroadcast;
  const double xy[2] = {20.0, 0.0};  // straight ahead, 20 m away
  beacon.payload.resize(sizeof xy);
  std::memcpy(beacon.payload.data(), xy, sizeof xy);
  robot.received.push_back(beacon);
  follower.control_step(robot);
  EXPECT_GT(robot.left_mps, 0.0);
  EXPECT_GT(robot.right_mps, 0.0);
  EXPECT_EQ(robot.recorded.at("distance_to_leader_m").back(), 20.0);
}

}  // namespace
}  // namespace example::follow_the_leader
