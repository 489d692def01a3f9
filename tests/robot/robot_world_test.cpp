// RobotWorld: construction, stepping, message ids, robot contexts and determinism.
#include "robot/robot_world.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/robot_context.hpp"
#include "robot_test_support.hpp"

namespace swarmnet {
namespace {

using test::make_choice;
using test::make_settings;

class RobotWorldTest : public ::testing::Test {
 protected:
  // 200 robots diffusing around an obstacle while a quarter of them send CBR traffic.
  RobotSettings busy_settings(std::uint64_t seed) {
    RobotSettings settings = make_settings(loader_, 200, 15.0, 15.0, seed);
    settings.arena.obstacles.push_back(Rect{6.0, 6.0, 9.0, 7.0});
    settings.robots.controllers.push_back(
        make_choice(loader_, "diffusion", PluginKind::controller, {{"turn_interval_s", 3.0}}));
    settings.robots.controllers.push_back(make_choice(loader_, "cbr", PluginKind::controller,
                                                      {{"fraction", 0.25}, {"start_s", 0.5}}));
    return settings;
  }

  PluginLoader loader_;
};

// Same bits in every pose and wheel field (not merely equal values: -0.0 != 0.0 here).
bool bitwise_equal(std::span<const RobotBody> a, std::span<const RobotBody> b) {
  if (a.size() != b.size()) return false;
  const auto bits = [](const RobotBody& body) {
    return std::array<std::uint64_t, 5>{std::bit_cast<std::uint64_t>(body.position.x()),
                                        std::bit_cast<std::uint64_t>(body.position.y()),
                                        std::bit_cast<std::uint64_t>(body.heading_rad),
                                        std::bit_cast<std::uint64_t>(body.left_mps),
                                        std::bit_cast<std::uint64_t>(body.right_mps)};
  };
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (bits(a[i]) != bits(b[i])) return false;
  }
  return true;
}

TEST_F(RobotWorldTest, SameScenarioGivesBitwiseIdenticalRuns) {
  RobotWorld first(busy_settings(21), loader_);
  RobotWorld second(busy_settings(21), loader_);
  RobotWorld other(busy_settings(22), loader_);
  ASSERT_TRUE(bitwise_equal(first.bodies(), second.bodies()));
  std::vector<AppMessage> sent_first;
  std::vector<AppMessage> sent_second;
  std::vector<AppMessage> sent_other;
  for (int i = 0; i < 500; ++i) {
    first.step({}, sent_first);
    second.step({}, sent_second);
    other.step({}, sent_other);
  }
  EXPECT_TRUE(bitwise_equal(first.bodies(), second.bodies()));
  EXPECT_FALSE(bitwise_equal(first.bodies(), other.bodies()));
  ASSERT_EQ(sent_first.size(), sent_second.size());
  for (std::size_t i = 0; i < sent_first.size(); ++i) {
    EXPECT_EQ(sent_first[i].message_id, sent_second[i].message_id);
    EXPECT_EQ(sent_first[i].source, sent_second[i].source);
    EXPECT_EQ(sent_first[i].destination, sent_second[i].destination);
    EXPECT_EQ(sent_first[i].payload, sent_second[i].payload);
  }
  // The robots did move.
  RobotWorld fresh(busy_settings(21), loader_);
  EXPECT_FALSE(bitwise_equal(first.bodies(), fresh.bodies()));
}

TEST_F(RobotWorldTest, TimeAdvancesByWholeSteps) {
  RobotSettings settings = make_settings(loader_, 3, 10.0, 10.0);
  settings.step_s = 0.05;
  RobotWorld world(settings, loader_);
  EXPECT_EQ(world.robot_count(), 3U);
  EXPECT_EQ(world.now(), kTimeZero);
  std::vector<AppMessage> sent;
  for (int i = 0; i < 1000; ++i) world.step({}, sent);
  EXPECT_EQ(world.step_index(), 1000U);
  EXPECT_EQ(world.now(), SimTime{50'000'000'000});
  EXPECT_TRUE(sent.empty());
}

TEST_F(RobotWorldTest, MessageIdsAscendFromZeroAcrossSteps) {
  RobotWorld world(busy_settings(3), loader_);
  std::vector<AppMessage> sent;
  std::vector<AppMessage> all;
  for (int i = 0; i < 50; ++i) {
    sent.clear();
    world.step({}, sent);
    // Within a step, robots run in ascending id.
    for (std::size_t k = 1; k < sent.size(); ++k) EXPECT_LE(sent[k - 1].source, sent[k].source);
    all.insert(all.end(), sent.begin(), sent.end());
  }
  ASSERT_FALSE(all.empty());
  for (std::size_t k = 0; k < all.size(); ++k) EXPECT_EQ(all[k].message_id, k);
}

// Two cbr entries on every robot, each message delivered to its destination: how many
// receptions the cbr entries record together after `steps` steps, and how many were sent.
std::pair<std::uint64_t, std::uint64_t> cbr_receptions(PluginLoader& loader,
                                                       std::vector<std::uint16_t> ports) {
  RobotSettings settings = make_settings(loader, 6, 10.0, 10.0);
  for (int entry = 0; entry < 2; ++entry) {
    settings.robots.controllers.push_back(
        make_choice(loader, "cbr", PluginKind::controller, {{"fraction", 1.0}, {"start_s", 0.0}}));
  }
  settings.robots.controller_ports = std::move(ports);
  RobotWorld world(settings, loader);
  std::vector<AppMessage> sent;
  std::vector<Delivery> deliveries;
  std::uint64_t total_sent = 0;
  for (int step = 0; step < 20; ++step) {
    std::vector<AppMessage> now;
    world.step(deliveries, now);
    deliveries.clear();
    for (const AppMessage& m : now) {
      deliveries.push_back({m.message_id, m.source, m.destination, m.destination, world.now(),
                            world.now(), 1, m.port, m.payload});
    }
    total_sent += now.size();
  }
  world.step(deliveries, sent);
  const auto& metrics = world.controller_metrics();
  const auto it = metrics.find("cbr_received");
  return {it == metrics.end() ? 0 : it->second.count, total_sent};
}

TEST_F(RobotWorldTest, EachControllerReceivesOnItsOwnPortUnlessTheyShareOne) {
  // Default ports 0 and 1: every message reaches the one entry that sent it.
  const auto [apart, sent_apart] = cbr_receptions(loader_, {});
  ASSERT_GT(sent_apart, 0U);
  EXPECT_EQ(apart, sent_apart);
  // Both on port 7: each message is in both entries' inboxes.
  const auto [shared, sent_shared] = cbr_receptions(loader_, {7, 7});
  EXPECT_EQ(sent_shared, sent_apart);
  EXPECT_EQ(shared, 2 * sent_shared);
}

TEST_F(RobotWorldTest, ControllersSeeProximityAndPlacementIsValid) {
  RobotSettings settings = make_settings(loader_, 40, 6.0, 6.0);
  RobotWorld world(settings, loader_);
  for (std::uint32_t r = 0; r < world.robot_count(); ++r) {
    ASSERT_EQ(world.proximity(r).size(), 24U);
    for (double reading : world.proximity(r)) {
      EXPECT_GE(reading, 0.0);
      EXPECT_LE(reading, settings.robots.proximity.range_m);
    }
  }
  const auto bodies = world.bodies();
  for (const auto& body : bodies) {
    EXPECT_EQ(body.radius_m, settings.robots.radius_m);
    EXPECT_EQ(body.axle_m, settings.robots.axle_m);
    EXPECT_EQ(body.max_speed_mps, settings.robots.max_speed_mps);
  }
}

TEST_F(RobotWorldTest, PlacementFailureNamesTheCounts) {
  RobotSettings settings = make_settings(loader_, 500, 2.0, 2.0);
  try {
    RobotWorld world(settings, loader_);
    FAIL() << "500 robots fit in 4 m^2";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("of 500 robots"), std::string::npos);
  }
}

class RobotContextTest : public ::testing::Test {
 protected:
  RobotContextTest() {
    state_.bodies.resize(3);
    for (auto& body : state_.bodies) body.max_speed_mps = 0.5;
    state_.arena = Arena{12.0, 8.0, {Rect{1.0, 1.0, 2.0, 2.0}}};
    for (auto& body : state_.bodies) body.axle_m = 0.2;
    state_.ports = {0, 4};
    state_.inboxes.resize(3 * state_.ports.size());
    state_.rays_per_robot = 2;
    state_.proximity = {1, 2, 3, 4, 5, 6};
    state_.outbox = &outbox_;
    state_.metrics = RobotMetrics(3);
  }
  RobotWorldState state_;
  std::vector<AppMessage> outbox_;
};

TEST_F(RobotContextTest, ControllersReadTheAxleTheArenaAndTheirPort) {
  WorldRobotContext robot(state_, 1);
  EXPECT_EQ(robot.axle_m(), 0.2);
  EXPECT_EQ(robot.arena().width_m, 12.0);
  EXPECT_EQ(robot.arena().height_m, 8.0);
  ASSERT_EQ(robot.arena().obstacles.size(), 1U);
  state_.current_port = 4;
  state_.current_port_index = 1;
  EXPECT_EQ(robot.port(), 4U);
  state_.inboxes[1 * 2 + 1].slots.resize(1);
  state_.inboxes[1 * 2 + 1].size = 1;
  EXPECT_EQ(robot.inbox().size(), 1U);  // robot 1's inbox for port 4
  std::vector<std::byte> payload(3, std::byte{1});
  EXPECT_EQ(robot.send(kBroadcast, payload), 0U);
  ASSERT_EQ(outbox_.size(), 1U);
  EXPECT_EQ(outbox_[0].port, 4U);  // the message goes to port 4 on its receivers
}

TEST_F(RobotContextTest, SendOptionsReachTheOutboxAndReportsTheirOwnPort) {
  WorldRobotContext robot(state_, 1);
  state_.current_port = 4;
  state_.current_port_index = 1;
  const std::vector<std::byte> payload(2, std::byte{7});
  robot.send(2, payload, SendOptions{1, true});
  robot.send(kBroadcast, payload);
  ASSERT_EQ(outbox_.size(), 2U);
  EXPECT_EQ(outbox_[0].hop_limit, 1U);
  EXPECT_TRUE(outbox_[0].report);
  EXPECT_EQ(outbox_[1].hop_limit, 0U);
  EXPECT_FALSE(outbox_[1].report);

  // Slots robot * ports + port index, ascending: robot 0 port 4, robot 1 port 0 and port 4.
  state_.send_report_slots = {1, 2, 3, 3};
  state_.send_reports.resize(4);
  for (std::size_t i = 0; i < 4; ++i) state_.send_reports[i].message_id = 10 + i;
  const auto mine = robot.send_reports();
  ASSERT_EQ(mine.size(), 2U);
  EXPECT_EQ(mine[0].message_id, 12U);
  EXPECT_EQ(mine[1].message_id, 13U);
  state_.current_port = 0;
  state_.current_port_index = 0;
  ASSERT_EQ(robot.send_reports().size(), 1U);
  EXPECT_EQ(robot.send_reports()[0].message_id, 11U);
  EXPECT_TRUE(WorldRobotContext(state_, 2).send_reports().empty());
}

TEST_F(RobotContextTest, WheelSpeedsAreClamped) {
  WorldRobotContext robot(state_, 1);
  robot.set_wheel_speeds(2.0, -3.0);
  EXPECT_EQ(state_.bodies[1].left_mps, 0.5);
  EXPECT_EQ(state_.bodies[1].right_mps, -0.5);
  robot.set_wheel_speeds(0.25, std::nan(""));
  EXPECT_EQ(state_.bodies[1].left_mps, 0.25);
  EXPECT_EQ(state_.bodies[1].right_mps, 0.0);
  EXPECT_EQ(state_.bodies[0].left_mps, 0.0);  // other robots untouched
}

TEST_F(RobotContextTest, ProximityIsTheRobotsOwnSlice) {
  WorldRobotContext robot(state_, 2);
  ASSERT_EQ(robot.proximity().size(), 2U);
  EXPECT_EQ(robot.proximity()[0], 5);
  EXPECT_EQ(robot.proximity()[1], 6);
}

TEST_F(RobotContextTest, SendStampsIdsAndRefusesBadMessages) {
  WorldRobotContext robot(state_, 1);
  std::vector<std::byte> payload(kMaxPayloadBytes, std::byte{7});
  EXPECT_EQ(robot.send(2, payload), 0U);
  EXPECT_EQ(robot.send(kBroadcast, payload), 1U);
  ASSERT_EQ(outbox_.size(), 2U);
  EXPECT_EQ(outbox_[0].source, 1U);
  EXPECT_EQ(outbox_[0].destination, 2U);
  EXPECT_EQ(outbox_[1].destination, kBroadcast);
  EXPECT_EQ(outbox_[1].payload, payload);

  payload.push_back(std::byte{0});
  try {
    robot.send(2, payload);
    FAIL();
  } catch (const std::invalid_argument& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find(std::to_string(kMaxPayloadBytes + 1)), std::string::npos) << text;
    EXPECT_NE(text.find(std::to_string(kMaxPayloadBytes)), std::string::npos) << text;
  }
  EXPECT_THROW(robot.send(3, {}), std::invalid_argument);
  EXPECT_THROW(robot.send(kNoNode, {}), std::invalid_argument);
  EXPECT_EQ(outbox_.size(), 2U);
  EXPECT_EQ(state_.next_message_id, 2U);
}

// route_to() answers from the previous batch's answers (sorted by robot, then destination) and
// notes each destination asked once per step, in asking order, for the next batch.
TEST_F(RobotContextTest, RouteToAnswersFromTheLastResultAndNotesEachAskOnce) {
  state_.route_asks.assign(3, {});
  state_.routes = {
      RouteAnswer{RouteQuery{1, 0}, Route{RouteStatus::valid, 0, 1, from_seconds(0.1)}},
      RouteAnswer{RouteQuery{1, 2}, Route{RouteStatus::none, kNoNode, 0, from_seconds(0.1)}},
      RouteAnswer{RouteQuery{2, 0}, Route{RouteStatus::valid, 1, 2, from_seconds(0.1)}}};
  WorldRobotContext robot(state_, 1);
  const Route to_zero = robot.route_to(0);
  EXPECT_EQ(to_zero.status, RouteStatus::valid);
  EXPECT_EQ(to_zero.next_hop, 0U);
  EXPECT_EQ(to_zero.hops, 1U);
  EXPECT_EQ(to_zero.as_of, from_seconds(0.1));
  EXPECT_EQ(robot.route_to(2).status, RouteStatus::none);
  EXPECT_EQ(robot.route_to(0).status, RouteStatus::valid);  // asked again: noted once
  EXPECT_EQ(state_.route_asks[1], (std::vector<RobotId>{0, 2}));
  // Robot 0 asked nothing before: pending, and noted.
  WorldRobotContext first(state_, 0);
  EXPECT_EQ(first.route_to(2).status, RouteStatus::pending);
  EXPECT_EQ(state_.route_asks[0], (std::vector<RobotId>{2}));
  EXPECT_TRUE(state_.route_asks[2].empty());
}

TEST_F(RobotContextTest, RouteToRefusesItselfNonRobotsAndTooManyDestinations) {
  state_.route_asks.assign(3, {});
  WorldRobotContext robot(state_, 1);
  EXPECT_THROW((void)robot.route_to(1), std::invalid_argument);
  EXPECT_THROW((void)robot.route_to(3), std::invalid_argument);
  EXPECT_THROW((void)robot.route_to(kBroadcast), std::invalid_argument);
  EXPECT_TRUE(state_.route_asks[1].empty());

  RobotWorldState crowd;
  crowd.bodies.resize(kMaxRouteQueriesPerRobot + 2);
  crowd.route_asks.assign(crowd.bodies.size(), {});
  WorldRobotContext asker(crowd, 0);
  for (RobotId d = 1; d <= kMaxRouteQueriesPerRobot; ++d) (void)asker.route_to(d);
  EXPECT_NO_THROW((void)asker.route_to(1));  // one already asked is still answered
  try {
    (void)asker.route_to(kMaxRouteQueriesPerRobot + 1);
    FAIL();
  } catch (const std::length_error& error) {
    EXPECT_NE(std::string(error.what()).find("kMaxRouteQueriesPerRobot"), std::string::npos);
  }
  EXPECT_EQ(crowd.route_asks[0].size(), kMaxRouteQueriesPerRobot);
}

TEST_F(RobotContextTest, RecordSummarisesPerMetricPooledAndPerRobot) {
  WorldRobotContext a(state_, 0);
  WorldRobotContext b(state_, 1);
  a.record("delay", 2.0);
  b.record("delay", -1.0);
  b.record("delay", 5.0);
  a.record("count", 1.0);
  const ControllerMetrics pooled = state_.metrics.pooled();
  ASSERT_EQ(pooled.size(), 2U);
  const MetricSummary& delay = pooled.find("delay")->second;
  EXPECT_EQ(delay.count, 3U);
  EXPECT_EQ(delay.sum, 6.0);
  EXPECT_EQ(delay.min, -1.0);
  EXPECT_EQ(delay.max, 5.0);
  EXPECT_EQ(delay.mean(), 2.0);
  EXPECT_EQ(pooled.begin()->first, "count");  // name order

  EXPECT_EQ(state_.metrics.of(0, "delay").count, 1U);
  EXPECT_EQ(state_.metrics.of(0, "delay").sum, 2.0);
  EXPECT_EQ(state_.metrics.of(1, "delay").count, 2U);
  EXPECT_EQ(state_.metrics.of(1, "delay").min, -1.0);
  EXPECT_EQ(state_.metrics.of(1, "count").count, 0U);
  EXPECT_EQ(state_.metrics.of(2, "delay").count, 0U);
}

TEST_F(RobotContextTest, SampleWritesOneRowPerCallWithTimeAndRobot) {
  std::ostringstream out;
  state_.series = MetricSeries([&]() -> std::ostream& { return out; });
  WorldRobotContext a(state_, 0);
  WorldRobotContext c(state_, 2);
  state_.now = from_seconds(0.5);
  c.sample("hops", 3.0);
  a.sample("hops", 0.25);
  state_.now = from_seconds(0.6);
  a.sample("rssi, smoothed", -71.5);
  EXPECT_EQ(out.str(),
            "time_ns,robot,series,value\n"
            "500000000,2,hops,3\n"
            "500000000,0,hops,0.25\n"
            "600000000,0,\"rssi, smoothed\",-71.5\n");
  EXPECT_EQ(state_.series.rows(), 3U);
}

TEST_F(RobotContextTest, SampleRefusesWhatCannotBePlotted) {
  std::ostringstream out;
  state_.series = MetricSeries([&]() -> std::ostream& { return out; });
  WorldRobotContext a(state_, 1);
  EXPECT_THROW(a.sample("", 1.0), std::invalid_argument);
  try {
    a.sample("link", std::numeric_limits<double>::quiet_NaN());
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("robot 1"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("link"), std::string::npos) << error.what();
  }
  EXPECT_EQ(out.str(), "");  // nothing opened for a refused sample
  RobotWorldState unwritten;
  WorldRobotContext b(unwritten, 0);
  EXPECT_THROW(b.sample("x", 1.0), std::logic_error);
}

}  // namespace
}  // namespace swarmnet
