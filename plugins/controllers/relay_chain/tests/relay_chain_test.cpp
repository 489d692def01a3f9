// relay_chain on fake robots (SDK test kit): roles from ids, the link judgement, and the three
// modes' decisions from the neighbour tables and route answers the test writes.
#include "relay_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "lane_drive.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::relay_chain {
namespace {

using testing::FakeRobotContext;
using testing::ParamOverrides;
using testing::plugin_args;

RadioNeighbor heard(RobotId id, double rssi_dbm, std::uint32_t unicasts = 0,
                    std::uint32_t first_acks = 0) {
  RadioNeighbor n;
  n.id = id;
  n.rssi_dbm = rssi_dbm;
  n.rssi_smoothed_dbm = rssi_dbm;
  n.frames = 3;
  n.unicasts = unicasts;
  n.first_attempt_acks = first_acks;
  return n;
}

TEST(ChainRole, BaseLeaderAndRelaysInChainOrder) {
  EXPECT_EQ(chain_role(0, 5).role, Role::base);
  const ChainRole leader = chain_role(1, 5);
  EXPECT_EQ(leader.role, Role::leader);
  EXPECT_EQ(leader.upstream, 4U);  // the last relay
  const ChainRole first = chain_role(2, 5);
  EXPECT_EQ(first.role, Role::relay);
  EXPECT_EQ(first.relay_index, 1U);
  EXPECT_EQ(first.upstream, 0U);  // the base
  EXPECT_EQ(chain_role(4, 5).upstream, 3U);
  EXPECT_EQ(chain_role(1, 2).upstream, 0U);  // no relays: the leader hangs on the base
  EXPECT_THROW((void)chain_role(0, 1), std::invalid_argument);
  EXPECT_THROW((void)chain_role(5, 5), std::invalid_argument);
}

TEST(LinkJudge, UnheardWeakOrGoodFromRssiAndFirstAttemptShare) {
  const LinkCriteria criteria{-85.0, 0.5, 4};
  const std::vector<RadioNeighbor> table = {heard(0, -80.0), heard(2, -86.0), heard(3, -70.0, 8, 3),
                                            heard(4, -70.0, 3, 0)};
  EXPECT_EQ(judge_link(table, 0, criteria), LinkState::good);
  EXPECT_EQ(judge_link(table, 1, criteria), LinkState::unheard);
  EXPECT_EQ(judge_link(table, 2, criteria), LinkState::weak);       // below the threshold
  EXPECT_EQ(judge_link(table, 3, criteria), LinkState::weak);       // 3 of 8 at the first attempt
  EXPECT_EQ(judge_link(table, 4, criteria), LinkState::good);       // too few exchanges to judge
  EXPECT_EQ(judge_link(table, 0, criteria, 6.0), LinkState::weak);  // with hysteresis
}

TEST(LaneDrive, TurnsAroundWithoutOvershootAndStopsAtTheTarget) {
  FakeRobotContext robot;
  robot.max_speed = 2.0;
  robot.pose_heading_rad = std::numbers::pi;  // facing away from the goal
  double previous = std::numbers::pi;
  for (int i = 0; i < 30; ++i) {
    drive_lane(robot, 50.0, 0.0, 2.0);
    robot.advance();
    const double error = std::abs(robot.pose_heading_rad);
    // While turning round the error only shrinks; then it steers back onto the lane gently.
    if (previous > 0.1) {
      EXPECT_LE(error, previous + 1e-9) << "step " << i;
    }
    previous = error;
  }
  EXPECT_LT(previous, 0.1);
  for (int i = 0; i < 400; ++i) {
    drive_lane(robot, 50.0, 0.0, 2.0);
    robot.advance();
  }
  EXPECT_NEAR(robot.pose_position.x(), 50.0, kArrivedM + 0.2);
  EXPECT_NEAR(robot.pose_position.y(), 0.0, 0.1);
  EXPECT_EQ(robot.left_mps, 0.0);
  EXPECT_EQ(robot.right_mps, 0.0);
}

class RelayChainTest : public ::testing::Test {
 protected:
  void SetUp() override {
    robot.robots = 4;  // base 0, leader 1, relays 2 and 3
    robot.max_speed = 2.0;
    robot.world = Arena{2000.0, 100.0, {}};
    robot.pose_position = Vec2(10.0, 50.0);
  }
  RelayChain& make(RobotId id, const ParamOverrides& overrides = {}) {
    robot.robot_id = id;
    controller = std::make_unique<RelayChain>(plugin_args<RelayChain>(overrides));
    controller->init(robot);
    return *controller;
  }
  void run(double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / robot.step_length_s));
    for (int i = 0; i < steps; ++i) {
      controller->control_step(robot);
      robot.advance();
    }
  }
  double travelled() const { return robot.pose_position.x() - 10.0; }

  FakeRobotContext robot;
  std::unique_ptr<RelayChain> controller;
};

TEST_F(RelayChainTest, GeometricRelaysDriveToTheirSlotsWithoutTheRadio) {
  make(3, {{"mode", std::string("geometric")}, {"spacing_m", 40.0}});
  robot.neighbors_enabled = false;  // geometry alone: neighbors() is never asked
  run(40.0);
  EXPECT_NEAR(travelled(), 80.0, 1.0);  // relay 2 of the chain: 2 x 40 m
  ASSERT_EQ(robot.recorded.count("anchor_distance_m"), 1U);
  EXPECT_NEAR(robot.recorded.at("anchor_distance_m")[0], 80.0, 1.0);
}

TEST_F(RelayChainTest, NoRelaysMode_RelaysStayAndTheLeaderGoesOneRange) {
  make(2, {{"mode", std::string("none")}});
  run(5.0);
  EXPECT_EQ(travelled(), 0.0);
  robot.pose_position = Vec2(10.0, 50.0);
  robot.time = {};
  make(1, {{"mode", std::string("none")}, {"spacing_m", 20.0}});
  run(30.0);
  EXPECT_NEAR(travelled(), 20.0, 1.0);
}

TEST_F(RelayChainTest, ALinkAwareRelayAnchorsWhereItsUpstreamGrowsWeak) {
  make(2, {{"grace_s", 1.0}});  // relay 1: its upstream is the base
  robot.radio_neighbors = {heard(0, -70.0)};
  run(5.0);
  const double moving = travelled();
  EXPECT_GT(moving, 5.0);  // still advancing: the link is good
  EXPECT_EQ(robot.recorded.count("anchor_distance_m"), 0U);
  robot.radio_neighbors = {heard(0, -88.0)};
  run(0.2);
  ASSERT_EQ(robot.recorded.count("anchor_distance_m"), 1U);
  const double anchored = travelled();
  run(5.0);
  EXPECT_NEAR(travelled(), anchored, 0.3);  // it stays
  // Heard a little better than the threshold: not good enough with the hysteresis; it stays.
  robot.radio_neighbors = {heard(0, -84.0)};
  run(2.0);
  EXPECT_NEAR(travelled(), anchored, 0.3);
  EXPECT_FALSE(robot.sampled.at("upstream_rssi_dbm").empty());
}

TEST_F(RelayChainTest, AnUnheardUpstreamStopsAnAdvancingRelayOnlyAfterLostAfter) {
  make(2, {{"grace_s", 0.0}, {"lost_after_s", 2.0}});
  robot.radio_neighbors = {heard(0, -60.0)};
  run(2.0);
  robot.radio_neighbors = {};  // a few missed frames
  run(1.5);
  EXPECT_EQ(robot.recorded.count("anchor_distance_m"), 0U);  // still going
  robot.radio_neighbors = {heard(0, -60.0)};
  run(1.0);
  robot.radio_neighbors = {};
  run(2.2);
  ASSERT_EQ(robot.recorded.count("anchor_distance_m"), 1U);  // gone for good: it stops
}

TEST_F(RelayChainTest, AnAnchoredRelayWhoseUpstreamFallsSilentBacksOff) {
  make(3, {{"grace_s", 0.0}, {"lost_after_s", 2.0}});  // relay 2: upstream is robot 2
  robot.radio_neighbors = {heard(2, -70.0)};
  run(10.0);
  robot.radio_neighbors = {heard(2, -90.0)};
  run(0.2);
  const double anchored = travelled();
  robot.radio_neighbors = {};  // robot 2 unheard
  run(1.5);
  EXPECT_NEAR(travelled(), anchored, 0.3);  // not yet lost_after_s
  run(3.0);
  EXPECT_LT(travelled(), anchored - 1.0);  // backing towards the base
  EXPECT_EQ(robot.recorded.at("retreats").size(), 1U);
  robot.radio_neighbors = {heard(2, -75.0)};  // good again, with margin
  run(0.2);
  const double back = travelled();
  run(3.0);
  EXPECT_NEAR(travelled(), back, 0.3);
  EXPECT_EQ(robot.recorded.at("anchor_distance_m").size(), 2U);
}

TEST_F(RelayChainTest, ARelayBackAtTheBaseWaitsThereInsteadOfRetreatingAgain) {
  make(3, {{"grace_s", 0.0}, {"lost_after_s", 1.0}});
  robot.radio_neighbors = {heard(2, -70.0)};
  run(3.0);
  robot.radio_neighbors = {heard(2, -90.0)};
  run(0.2);
  robot.radio_neighbors = {};  // its upstream gone for good: back to where it started
  run(20.0);
  EXPECT_NEAR(travelled(), 0.0, kArrivedM + 0.2);
  EXPECT_EQ(robot.recorded.at("retreats").size(), 1U);
  EXPECT_EQ(robot.recorded.at("anchor_distance_m").size(), 2U);
}

TEST_F(RelayChainTest, TheLeaderReportsAsksItsRouteAndWaitsForItsLink) {
  make(1, {{"grace_s", 0.0}});  // upstream: the last relay, robot 3
  robot.radio_neighbors = {heard(3, -70.0)};
  robot.routes[0] = Route{RouteStatus::valid, 3, 3, {}};
  run(3.15);
  // Reports at 1, 2 and 3 s, unicast to the base with a send report.
  ASSERT_EQ(robot.sent.size(), 3U);
  EXPECT_EQ(robot.sent[0].destination, 0U);
  EXPECT_TRUE(robot.sent[0].options.report);
  EXPECT_EQ(robot.sent[0].options.hop_limit, 0U);
  EXPECT_GE(robot.route_asks.size(), 30U);  // every step
  EXPECT_EQ(robot.recorded.at("route_to_base").front(), 1.0);
  EXPECT_EQ(robot.sampled.at("route_to_base").size(), 4U);  // at 0, 1, 2, 3 s
  robot.radio_neighbors = {heard(3, -95.0)};
  robot.routes[0] = Route{RouteStatus::none, kNoNode, 0, {}};
  run(0.2);
  const double waiting = travelled();
  run(3.0);
  EXPECT_NEAR(travelled(), waiting, 0.3);
  EXPECT_EQ(robot.recorded.at("route_to_base").back(), 0.0);
  robot.radio_neighbors = {heard(3, -70.0)};  // the chain caught up: on it goes
  run(2.0);
  EXPECT_GT(travelled(), waiting + 2.0);
}

TEST_F(RelayChainTest, TheBaseCountsTheLeadersReports) {
  make(0);
  ReceivedMessage report;
  report.source = 1;
  report.destination = 0;
  robot.received = {report, report};
  controller->control_step(robot);
  EXPECT_EQ(robot.recorded.at("reports_received").size(), 2U);
  EXPECT_EQ(robot.left_mps, 0.0);
}

}  // namespace
}  // namespace swarmnet::relay_chain
