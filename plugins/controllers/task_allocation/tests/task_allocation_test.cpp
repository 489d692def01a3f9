// task_allocation on a fake robot whose world readings the test writes (SDK test kit).
#include "task_allocation.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "swarmnet/testing.hpp"

namespace swarmnet::task_allocation {
namespace {

using testing::FakeRobotContext;
using testing::ParamOverrides;
using testing::plugin_args;
using Mode = TaskAllocation::Mode;

constexpr RobotId kSelf = 5;

class TaskAllocationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    robot.robot_id = kSelf;
    robot.robots = 20;
    robot.max_speed = 5.0;
    robot.world = Arena{500.0, 500.0, {}};
    robot.pose_position = Vec2(100.0, 100.0);
    robot.readings["battery"] = {1.0, 0.0};
    robot.readings["skills"] = {0.0};
    robot.readings["events_in_view"] = {};
    robot.readings["charger"] = {250.0, 250.0, 10.0};
    robot.readings["joined"] = {};
    robot.offered_requests = {"join", "leave"};  // task_events's
  }

  TaskAllocation& make(const ParamOverrides& overrides = {}, std::uint64_t seed = 1) {
    controller = std::make_unique<TaskAllocation>(plugin_args<TaskAllocation>(overrides, seed));
    controller->init(robot);
    return *controller;
  }

  // Runs one step and advances the robot, with the inbox emptied afterwards.
  void step() {
    controller->control_step(robot);
    robot.received.clear();
    robot.advance();
  }

  void see(std::vector<double> events) { robot.readings["events_in_view"] = std::move(events); }

  void hear(MessageType type, RobotId from, std::uint32_t id, const Vec2& at,
            std::uint16_t required, std::uint16_t skill, std::uint16_t waiting) {
    const TaskMessage m{type, id, at, required, skill, waiting, Vec2(0.0, 0.0)};
    ReceivedMessage received;
    received.source = from;
    received.destination = kBroadcast;
    received.payload = encode(m);
    robot.received.push_back(received);
  }

  // Messages sent since `from`, decoded.
  std::vector<TaskMessage> sent(std::size_t from = 0) const {
    std::vector<TaskMessage> out;
    for (std::size_t i = from; i < robot.sent.size(); ++i) {
      EXPECT_EQ(robot.sent[i].destination, kBroadcast);
      const auto m = decode(robot.sent[i].payload);
      EXPECT_TRUE(m.has_value());
      if (m) out.push_back(*m);
    }
    return out;
  }

  std::string types(std::size_t from = 0) const {
    std::string out;
    for (const TaskMessage& m : sent(from)) out += std::string(letter(m.type));
    return out;
  }

  std::size_t count(const std::string& metric) const {
    const auto it = robot.recorded.find(metric);
    return it == robot.recorded.end() ? 0 : it->second.size();
  }

  // Puts the robot at event `id` (at `at`), going there, and arrives: it joins.
  void arrive_at(std::uint32_t id, const Vec2& at, double required, double waiting_before) {
    see({static_cast<double>(id), at.x(), at.y(), 0.0, required, waiting_before});
    step();  // discovered: S, G
    ASSERT_EQ(controller->mode(), Mode::going);
    robot.pose_position = at + Vec2(1.0, 0.0);
    step();  // arrives: join, S
    ASSERT_EQ(controller->mode(), Mode::waiting);
    robot.readings["joined"] = {static_cast<double>(id), waiting_before + 1.0, 0.0};
  }

  FakeRobotContext robot;
  std::unique_ptr<TaskAllocation> controller;
};

TEST_F(TaskAllocationTest, DiscoveryWithTheSkillSendsStatusThenGoing) {
  make();
  see({3.0, 140.0, 100.0, 0.0, 4.0, 0.0});
  step();
  EXPECT_EQ(types(), "SG");
  const auto messages = sent();
  EXPECT_EQ(messages[0].event_id, 3U);
  EXPECT_EQ(messages[0].event_position, Vec2(140.0, 100.0));
  EXPECT_EQ(messages[0].required, 4U);
  EXPECT_EQ(messages[0].skill, 0U);
  EXPECT_EQ(messages[0].waiting, 0U);
  EXPECT_EQ(messages[0].sender_position, Vec2(100.0, 100.0));
  EXPECT_EQ(controller->mode(), Mode::going);
  EXPECT_EQ(controller->event(), 3U);
  EXPECT_EQ(count("sent.S"), 1U);
  EXPECT_EQ(count("sent.G"), 1U);
  // Seen again: nothing new to say.
  step();
  EXPECT_EQ(types(), "SG");
  // It drives towards the event (east, its heading): both wheels forward.
  EXPECT_GT(robot.left_mps, 0.0);
  EXPECT_GT(robot.right_mps, 0.0);
}

TEST_F(TaskAllocationTest, DiscoveryWithoutTheSkillOnlyAnnounces) {
  make();
  see({3.0, 140.0, 100.0, 1.0, 4.0, 0.0});
  step();
  EXPECT_EQ(types(), "S");
  EXPECT_EQ(controller->mode(), Mode::exploring);
  EXPECT_TRUE(controller->memory().contains(3));
}

TEST_F(TaskAllocationTest, StatusFromAnotherRobotStartsTheDecisionAndOthersGoingChangeIt) {
  make();
  hear(MessageType::status, 7, 1, Vec2(300.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(), "G");
  EXPECT_EQ(controller->event(), 1U);
  // A closer event that needs robots: cancel the first, go to the second.
  hear(MessageType::status, 8, 2, Vec2(150.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(1), "CG");
  EXPECT_EQ(sent()[1].event_id, 1U);
  EXPECT_EQ(sent()[2].event_id, 2U);
  // Two robots decided to go to event 2 before this one heard of them: 1 waiting + 2 going
  // covers 3, and they decided first: back to event 1.
  hear(MessageType::going, 9, 2, Vec2(150.0, 100.0), 3, 0, 1);
  hear(MessageType::going, 11, 2, Vec2(150.0, 100.0), 3, 0, 1);
  step();
  // Both G arrived after this robot's own decision: they count for nothing on its own event.
  EXPECT_EQ(controller->event(), 2U);
  EXPECT_EQ(types(3), "");
  EXPECT_EQ(count("received.S"), 2U);
  EXPECT_EQ(count("received.G"), 2U);
}

TEST_F(TaskAllocationTest, AnEventOthersCoverIsNotChosen) {
  make({{"other_event_probability", 0.0}});
  hear(MessageType::going, 7, 1, Vec2(150.0, 100.0), 3, 0, 1);
  hear(MessageType::going, 8, 1, Vec2(150.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(), "");  // 1 waiting + 2 going: covered
  EXPECT_EQ(controller->mode(), Mode::exploring);
  hear(MessageType::cancelled, 8, 1, Vec2(150.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(), "G");
  EXPECT_EQ(controller->event(), 1U);
  EXPECT_EQ(count("received.C"), 1U);
  // A robot that goes there too after it: it keeps going (it decided first).
  hear(MessageType::going, 9, 1, Vec2(150.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(controller->event(), 1U);
  // H: being serviced, no longer a candidate: cancel and explore.
  hear(MessageType::handling, 7, 1, Vec2(150.0, 100.0), 3, 0, 3);
  step();
  EXPECT_EQ(types(1), "C");
  EXPECT_EQ(controller->mode(), Mode::exploring);
}

TEST_F(TaskAllocationTest, MalformedPayloadsAreCountedAndIgnored) {
  make();
  ReceivedMessage junk;
  junk.source = 3;
  junk.payload = std::vector<std::byte>(10, std::byte{'S'});
  robot.received.push_back(junk);
  hear(MessageType::status, 3, 1, Vec2(150.0, 100.0), 3, 0, 1);
  robot.received.back().payload[0] = std::byte{'Z'};
  step();
  EXPECT_EQ(count("malformed_messages"), 2U);
  EXPECT_EQ(controller->memory().size(), 0U);
  EXPECT_TRUE(robot.sent.empty());
  EXPECT_EQ(count("received.S"), 0U);
}

TEST_F(TaskAllocationTest, ArrivingJoinsAndAnnouncesItselfAsWaiting) {
  make();
  see({3.0, 140.0, 100.0, 0.0, 4.0, 1.0});
  step();
  robot.pose_position = Vec2(138.0, 100.0);  // 2 m away: within arrive_radius_m
  step();
  ASSERT_EQ(robot.requests.size(), 1U);
  EXPECT_EQ(robot.requests[0].name, "join");
  EXPECT_EQ(robot.requests[0].args, std::vector<double>{3.0});
  EXPECT_EQ(types(), "SGS");
  EXPECT_EQ(sent()[2].waiting, 2U);  // the one already there and itself
  EXPECT_EQ(controller->mode(), Mode::waiting);
  EXPECT_EQ(robot.left_mps, 0.0);
  EXPECT_EQ(robot.right_mps, 0.0);
}

TEST_F(TaskAllocationTest, ArrivingAtAnEventNoLongerInViewGivesItUp) {
  make({{"other_event_probability", 0.0}});
  hear(MessageType::status, 7, 1, Vec2(140.0, 100.0), 3, 0, 1);
  step();
  ASSERT_EQ(controller->event(), 1U);
  robot.pose_position = Vec2(139.0, 100.0);  // there, but the world shows no event 1
  step();
  EXPECT_TRUE(robot.requests.empty());
  EXPECT_EQ(types(), "GC");
  EXPECT_TRUE(controller->memory().find(1)->handled);
  EXPECT_EQ(controller->mode(), Mode::exploring);
}

TEST_F(TaskAllocationTest, HandlingIsSentOnceWhenTheServiceStarts) {
  make();
  arrive_at(3, Vec2(140.0, 100.0), 2.0, 0.0);
  step();
  const std::size_t before = robot.sent.size();
  robot.readings["joined"] = {3.0, 2.0, 0.0};  // a second robot arrived: service starts
  step();
  EXPECT_EQ(types(before), "H");
  EXPECT_EQ(sent(before)[0].waiting, 2U);
  EXPECT_TRUE(controller->memory().find(3)->handled);
  robot.readings["joined"] = {3.0, 2.0, 1.5};
  step();
  step();
  EXPECT_EQ(types(before), "H");
  EXPECT_EQ(count("sent.H"), 1U);
  // Serviced: the world clears the join.
  robot.readings["joined"] = {};
  see({});
  step();
  EXPECT_EQ(controller->mode(), Mode::exploring);
  EXPECT_EQ(robot.requests.size(), 1U);  // no leave after a service
}

TEST_F(TaskAllocationTest, NoHandlingWhenAnotherRobotSentItFirst) {
  make();
  arrive_at(3, Vec2(140.0, 100.0), 2.0, 0.0);
  step();
  const std::size_t before = robot.sent.size();
  hear(MessageType::handling, 8, 3, Vec2(140.0, 100.0), 2, 0, 2);
  robot.readings["joined"] = {3.0, 2.0, 0.0};
  step();
  EXPECT_EQ(types(before), "");
  EXPECT_EQ(controller->mode(), Mode::waiting);
}

TEST_F(TaskAllocationTest, AbandonsAfterTheTimeoutAndDoesNotComeBackAtOnce) {
  make({{"abandon_after_s", 5.0}, {"other_event_probability", 0.0}});
  arrive_at(3, Vec2(140.0, 100.0), 4.0, 1.0);
  const std::size_t before = robot.sent.size();
  for (int i = 0; i < 50; ++i) step();  // 5 s: not yet
  EXPECT_EQ(controller->mode(), Mode::waiting);
  EXPECT_EQ(types(before), "");
  step();
  step();
  EXPECT_EQ(types(before), "A");
  EXPECT_EQ(sent(before)[0].waiting, 1U);  // the one left behind
  ASSERT_EQ(robot.requests.size(), 2U);
  EXPECT_EQ(robot.requests[1].name, "leave");
  EXPECT_TRUE(robot.requests[1].args.empty());
  EXPECT_EQ(count("abandoned"), 1U);
  EXPECT_EQ(controller->mode(), Mode::exploring);
  // Still needed, but shunned for abandon_after_s.
  robot.readings["joined"] = {};
  see({});
  hear(MessageType::status, 8, 3, Vec2(140.0, 100.0), 4, 0, 1);
  step();
  EXPECT_EQ(controller->mode(), Mode::exploring);
  for (int i = 0; i < 40; ++i) step();
  EXPECT_EQ(controller->mode(), Mode::exploring);
  // The shun ends: with no message at all, the rule runs again and the event is chosen.
  for (int i = 0; i < 12; ++i) step();
  EXPECT_EQ(controller->mode(), Mode::going);
  EXPECT_EQ(controller->event(), 3U);
}

TEST_F(TaskAllocationTest, LowBatteryWhileGoingCancelsAndHeadsForTheCharger) {
  make();
  robot.pose_position = Vec2(250.0, 100.0);
  robot.pose_heading_rad = 0.0;
  hear(MessageType::status, 7, 1, Vec2(400.0, 100.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(), "G");
  robot.readings["battery"] = {0.2, 1.0};
  step();
  EXPECT_EQ(types(), "GC");
  EXPECT_EQ(controller->mode(), Mode::to_charger);
  EXPECT_EQ(robot.shown_state, "to_charger");  // what the viewer draws
  // The charger is due north, 90 degrees left: it turns counter-clockwise in place.
  EXPECT_GT(robot.right_mps, 0.0);
  EXPECT_LT(robot.left_mps, 0.0);
  // New messages change the memory but not its course.
  hear(MessageType::status, 8, 2, Vec2(250.0, 120.0), 3, 0, 1);
  step();
  EXPECT_EQ(types(), "GC");
  EXPECT_EQ(controller->mode(), Mode::to_charger);
  // At the charger: stops and charges until full.
  robot.pose_position = Vec2(252.0, 250.0);
  step();
  EXPECT_EQ(controller->mode(), Mode::charging);
  EXPECT_EQ(robot.shown_state, "charging");
  EXPECT_EQ(count("charges"), 1U);
  robot.readings["battery"] = {0.8, 0.0};
  step();
  EXPECT_EQ(controller->mode(), Mode::charging);
  EXPECT_EQ(robot.left_mps, 0.0);
  robot.readings["battery"] = {1.0, 0.0};
  step();
  // Charged: the rule runs again and event 2 (needing robots) is chosen.
  EXPECT_EQ(controller->mode(), Mode::going);
  EXPECT_EQ(robot.shown_state, "going");
  EXPECT_EQ(controller->event(), 2U);
}

TEST_F(TaskAllocationTest, LowBatteryWhileWaitingAbandonsButNotDuringAService) {
  make();
  arrive_at(3, Vec2(140.0, 100.0), 4.0, 1.0);
  step();
  const std::size_t before = robot.sent.size();
  robot.readings["battery"] = {0.2, 1.0};
  step();
  EXPECT_EQ(types(before), "A");
  EXPECT_EQ(robot.requests.back().name, "leave");
  EXPECT_EQ(controller->mode(), Mode::to_charger);

  // A robot in a started service stays.
  robot = FakeRobotContext{};
  SetUp();
  make();
  arrive_at(3, Vec2(140.0, 100.0), 2.0, 1.0);
  step();  // joined shows 2 of 2: the service runs (this robot announced it on arrival)
  EXPECT_EQ(types(), "SGH");
  robot.readings["battery"] = {0.2, 1.0};
  step();
  EXPECT_EQ(controller->mode(), Mode::waiting);
  EXPECT_EQ(types(), "SGH");
}

TEST_F(TaskAllocationTest, TheRobotThatCompletesTheGroupSendsTheOnlyH) {
  make();
  arrive_at(3, Vec2(140.0, 100.0), 4.0, 3.0);  // three waiting: this robot is the fourth
  EXPECT_EQ(types(), "SGH");
  EXPECT_EQ(sent()[2].waiting, 4U);
  EXPECT_TRUE(controller->memory().find(3)->handled);
  robot.readings["joined"] = {3.0, 4.0, 0.1};
  step();
  step();
  EXPECT_EQ(count("sent.H"), 1U);
}

TEST_F(TaskAllocationTest, AStalledServiceReopensTheEventForTheOthers) {
  make({{"abandon_after_s", 5.0}});
  arrive_at(3, Vec2(140.0, 100.0), 2.0, 1.0);  // completes the group: H
  robot.readings["joined"] = {3.0, 2.0, 0.1};
  step();
  const std::size_t before = robot.sent.size();
  robot.readings["joined"] = {3.0, 1.0, 0.0};  // the other one left: the clock restarted
  step();
  ASSERT_EQ(types(before), "S");
  EXPECT_EQ(sent(before)[0].waiting, 1U);
  EXPECT_FALSE(controller->memory().find(3)->handled);
  EXPECT_EQ(controller->mode(), Mode::waiting);
  // Waiting again, so it may abandon again after abandon_after_s.
  for (int i = 0; i < 52; ++i) step();
  EXPECT_EQ(types(before), "SA");
}

TEST_F(TaskAllocationTest, ExplorationMarksCellsAndAimsInsideTheArena) {
  make();
  robot.pose_position = Vec2(5.0, 250.0);  // by a wall
  for (int i = 0; i < 3000; ++i) {         // 300 s at 5 m/s
    step();
    const auto cell = controller->explorer().target_cell();
    ASSERT_TRUE(cell.has_value());
    const Vec2 t = controller->explorer().centre(*cell);
    ASSERT_GT(t.x(), 0.0);
    ASSERT_LT(t.x(), 500.0);
    ASSERT_GT(t.y(), 0.0);
    ASSERT_LT(t.y(), 500.0);
    ASSERT_GE(robot.pose_position.x(), -1.0);
    ASSERT_LE(robot.pose_position.x(), 501.0);
  }
  // 1500 m of driving reaches many cells of 50 m.
  EXPECT_GE(controller->explorer().explored_count(), 20U);
}

TEST_F(TaskAllocationTest, ResetReproducesARunByteForByte) {
  make({{"other_event_probability", 0.5}, {"abandon_after_s", 3.0}});
  auto run = [&]() {
    robot = FakeRobotContext{};
    SetUp();
    for (int i = 0; i < 600; ++i) {
      if (i == 20)
        see({1.0, robot.pose_position.x() + 20.0, robot.pose_position.y(), 0.0, 4.0, 0.0});
      if (i == 30) hear(MessageType::going, 7, 1, Vec2(0.0, 0.0), 4, 0, 0);
      if (i == 40) hear(MessageType::status, 8, 2, Vec2(300.0, 300.0), 2, 0, 0);
      if (i == 60) hear(MessageType::going, 9, 2, Vec2(300.0, 300.0), 2, 0, 0);
      if (i == 61) hear(MessageType::going, 10, 2, Vec2(300.0, 300.0), 2, 0, 0);
      if (i % 50 == 7) robot.rays[0] = 0.2;
      if (i % 50 == 9) robot.clear_rays();
      if (!robot.requests.empty() && robot.requests.back().name == "join") {
        robot.readings["joined"] = {robot.requests.back().args[0], 1.0, 0.0};
      } else {
        robot.readings["joined"] = {};
      }
      step();
    }
    std::vector<double> trace;
    for (const auto& s : robot.sent) {
      for (const std::byte b : s.payload) trace.push_back(static_cast<double>(b));
    }
    for (const auto& r : robot.requests) trace.push_back(static_cast<double>(r.name.size()));
    trace.push_back(robot.pose_position.x());
    trace.push_back(robot.pose_position.y());
    trace.push_back(robot.pose_heading_rad);
    return std::make_pair(trace, robot.sent.size());
  };
  const auto first = run();
  EXPECT_GT(first.second, 3U);  // the run did send messages
  controller->reset();
  const auto second = run();
  EXPECT_EQ(first, second);
}

TEST_F(TaskAllocationTest, WithoutCommunicationAwarenessItNeitherBeaconsNorReadsNeighbours) {
  make();
  robot.neighbors_enabled = false;  // neighbors() would throw if asked
  for (int i = 0; i < 30; ++i) step();
  EXPECT_TRUE(robot.sent.empty());
  EXPECT_EQ(count("beacons"), 0U);
}

TEST_F(TaskAllocationTest, BeaconsGoOneHopOncePerIntervalAndAreNotMessagesToTheReceiver) {
  make({{"beacon_interval_s", 1.0}});
  for (int i = 0; i < 35; ++i) step();  // 3.5 s: three or four beacons, by the random offset
  ASSERT_GE(robot.sent.size(), 3U);
  ASSERT_LE(robot.sent.size(), 4U);
  for (const auto& sent : robot.sent) {
    EXPECT_EQ(sent.destination, kBroadcast);
    EXPECT_TRUE(is_beacon(sent.payload));
    EXPECT_EQ(sent.options.hop_limit, 1U);
  }
  for (std::size_t i = 1; i < robot.sent.size(); ++i) {
    EXPECT_EQ(robot.sent[i].at - robot.sent[i - 1].at, from_seconds(1.0));
  }
  EXPECT_EQ(count("beacons"), robot.sent.size());
  ReceivedMessage beacon;
  beacon.source = 9;
  beacon.destination = kBroadcast;
  beacon.payload = encode_beacon();
  robot.received.push_back(beacon);
  step();
  EXPECT_EQ(count("malformed_messages"), 0U);
}

TEST_F(TaskAllocationTest, BeaconOffsetsDifferBetweenRobotsAndRepeatPerSeed) {
  const auto first_beacon = [this](std::uint64_t seed) {
    robot = FakeRobotContext{};
    SetUp();
    make({{"beacon_interval_s", 1.0}}, seed);
    while (robot.sent.empty()) step();
    return robot.sent.front().at;
  };
  const SimTime a = first_beacon(1);
  EXPECT_EQ(first_beacon(1), a);
  bool differs = false;
  for (std::uint64_t seed = 2; seed < 6; ++seed) differs = differs || first_beacon(seed) != a;
  EXPECT_TRUE(differs);
}

TEST_F(TaskAllocationTest, AWaitingRobotRefloodsStatusWhenItMeetsSomeone) {
  make({{"reannounce_on_encounter", true},
        {"reannounce_min_interval_s", 5.0},
        {"other_event_probability", 0.0}});
  arrive_at(3, Vec2(140.0, 100.0), 4.0, 0.0);
  const std::size_t before = robot.sent.size();
  step();  // nobody heard yet
  EXPECT_EQ(robot.sent.size(), before);
  RadioNeighbor met;
  met.id = 8;
  robot.radio_neighbors = {met};
  step();  // robot 8 heard: S again, flooded (no hop limit)
  ASSERT_EQ(types(before), "S");
  EXPECT_EQ(sent(before)[0].event_id, 3U);
  EXPECT_EQ(sent(before)[0].waiting, 1U);
  EXPECT_EQ(robot.sent.back().options.hop_limit, 0U);
  EXPECT_EQ(count("reannounced"), 1U);
  step();  // still robot 8: no encounter
  RadioNeighbor other;
  other.id = 11;
  robot.radio_neighbors = {met, other};
  step();  // robot 11 is new, but within reannounce_min_interval_s of the last
  EXPECT_EQ(types(before), "S");
  for (int i = 0; i < 50; ++i) step();
  robot.radio_neighbors = {met};
  step();
  robot.radio_neighbors = {met, other};
  step();  // 5 s on, 11 heard again: S again
  EXPECT_EQ(types(before), "SS");
}

TEST_F(TaskAllocationTest, EncountersDoNotReannounceAServiceThatStartedOrARobotThatExplores) {
  make({{"reannounce_on_encounter", true}, {"other_event_probability", 0.0}});
  RadioNeighbor met;
  met.id = 8;
  robot.radio_neighbors = {met};
  step();  // exploring, meets 8: nothing to say
  EXPECT_TRUE(robot.sent.empty());
  robot.radio_neighbors.clear();
  arrive_at(3, Vec2(140.0, 100.0), 4.0, 3.0);  // completes the group: H, service starts
  robot.readings["joined"] = {3.0, 4.0, 1.0};
  step();
  const std::size_t before = robot.sent.size();
  robot.radio_neighbors = {met};
  step();
  EXPECT_EQ(robot.sent.size(), before);
  EXPECT_EQ(count("reannounced"), 0U);
}

}  // namespace
}  // namespace swarmnet::task_allocation
