// tether on the SDK test kit: the test sets the radio neighbour table, the send reports and the
// route answers a run's network half would give, and checks what the controller does with them.
#include "tether.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "swarmnet/testing.hpp"

namespace example::tether {
namespace {

using namespace swarmnet;
using swarmnet::testing::FakeRobotContext;
using swarmnet::testing::plugin_args;

RadioNeighbor heard(RobotId id, double rssi_dbm) {
  RadioNeighbor n;
  n.id = id;
  n.rssi_dbm = rssi_dbm;
  n.rssi_smoothed_dbm = rssi_dbm;
  n.frames = 3;
  return n;
}

class TetherTest : public ::testing::Test {
 protected:
  void SetUp() override {
    robot.robot_id = 3;
    robot.max_speed = 2.0;
    robot.step_length_s = 0.1;
  }
  void make(const swarmnet::testing::ParamOverrides& overrides = {}) {
    controller = std::make_unique<Tether>(plugin_args<Tether>(overrides));
    controller->init(robot);
  }
  void run(double seconds) {
    for (double t = 0.0; t < seconds - 1e-9; t += robot.step_length_s) {
      controller->control_step(robot);
      robot.advance();
    }
  }
  FakeRobotContext robot;
  std::unique_ptr<Tether> controller;
};

TEST_F(TetherTest, BeaconsGoOneHopAndCheckInsToTheAnchorAskForReports) {
  make({{"beacon_interval_s", 0.5}, {"check_in_interval_s", 1.0}, {"anchor", 0}});
  run(1.0);
  std::vector<FakeRobotContext::Sent> beacons;
  std::vector<FakeRobotContext::Sent> check_ins;
  for (const auto& sent : robot.sent) {
    (sent.destination == kBroadcast ? beacons : check_ins).push_back(sent);
  }
  ASSERT_EQ(beacons.size(), 2U);
  for (const auto& b : beacons) {
    EXPECT_EQ(b.options.hop_limit, 1U);
    EXPECT_FALSE(b.options.report);
  }
  ASSERT_EQ(check_ins.size(), 1U);
  EXPECT_EQ(check_ins[0].destination, 0U);
  EXPECT_EQ(check_ins[0].options.hop_limit, 0U);
  EXPECT_TRUE(check_ins[0].options.report);
  SendReport acknowledged;
  acknowledged.outcome = SendOutcome::acknowledged;
  SendReport dropped;
  dropped.outcome = SendOutcome::dropped;
  dropped.reason = DropReason::no_route;
  robot.reports = {acknowledged, dropped};
  run(0.1);
  EXPECT_EQ(robot.recorded.at("check_ins_acknowledged").size(), 1U);
  EXPECT_EQ(robot.recorded.at("check_ins_dropped").size(), 1U);
}

TEST_F(TetherTest, ARouteToTheAnchorLongerThanMaxHopsStopsIt) {
  make({{"anchor", 0}, {"max_hops", 3}, {"grace_s", 0.0}});
  robot.radio_neighbors = {heard(1, -60.0), heard(2, -60.0)};
  robot.routes[0] = Route{RouteStatus::valid, 2, 3, {}};
  run(1.0);
  EXPECT_FALSE(controller->stopped());
  robot.routes[0] = Route{RouteStatus::valid, 2, 4, {}};
  run(0.1);
  EXPECT_TRUE(controller->stopped());
}

TEST_F(TetherTest, DrivesWhileItHearsEnoughRobotsWellAndStopsForGoodWhenNot) {
  make({{"min_neighbors", 2}, {"rssi_floor_dbm", -75.0}, {"grace_s", 0.0}});
  robot.radio_neighbors = {heard(1, -60.0), heard(2, -70.0)};
  run(2.0);
  EXPECT_FALSE(controller->stopped());
  EXPECT_GT(robot.left_mps, 0.0);
  robot.radio_neighbors = {heard(1, -60.0), heard(2, -80.0)};  // one is weak now
  run(0.1);
  EXPECT_TRUE(controller->stopped());
  EXPECT_EQ(robot.left_mps, 0.0);
  ASSERT_EQ(robot.recorded.at("stopped_at_m").size(), 1U);
  robot.radio_neighbors = {heard(1, -60.0), heard(2, -60.0)};  // a tether does not stretch back
  run(1.0);
  EXPECT_EQ(robot.left_mps, 0.0);
}

TEST_F(TetherTest, NoStoppingWithinTheGraceTimeWhileTheTablesFill) {
  make({{"grace_s", 1.0}});
  run(0.9);  // nobody heard yet
  EXPECT_FALSE(controller->stopped());
  run(0.2);
  EXPECT_TRUE(controller->stopped());
}

TEST_F(TetherTest, RecordsWhetherTheAnchorIsRoutableOnceAnswered) {
  make({{"anchor", 0}, {"grace_s", 100.0}});
  run(0.1);  // no answer yet: pending, nothing recorded
  EXPECT_EQ(robot.recorded.count("route_to_anchor"), 0U);
  robot.routes[0] = Route{RouteStatus::valid, 2, 2, {}};
  run(0.1);
  robot.routes[0] = Route{RouteStatus::none, kNoNode, 0, {}};
  run(0.1);
  EXPECT_EQ(robot.recorded.at("route_to_anchor"), (std::vector<double>{1.0, 0.0}));
  EXPECT_FALSE(robot.route_asks.empty());
}

TEST_F(TetherTest, TheAnchorStaysAndAsksNoRoute) {
  robot.robot_id = 0;
  make({{"anchor", 0}});
  run(3.0);
  EXPECT_EQ(robot.left_mps, 0.0);
  EXPECT_EQ(robot.right_mps, 0.0);
  EXPECT_TRUE(robot.route_asks.empty());
}

}  // namespace
}  // namespace example::tether
