// The SDK test kit itself: the scheduler's order, the fakes' records, plugin_args' checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarmnet/testing.hpp"

namespace swarmnet::testing {
namespace {

TEST(TestScheduler, RunsEventsByTimeThenBySchedulingOrder) {
  TestScheduler scheduler;
  std::vector<int> order;
  scheduler.schedule(SimTime{20}, [&] { order.push_back(3); });
  scheduler.schedule(SimTime{10}, [&] { order.push_back(1); });
  scheduler.schedule(SimTime{10}, [&] { order.push_back(2); });
  scheduler.run_until(SimTime{15});
  EXPECT_EQ(order, (std::vector<int>{1, 2}));
  EXPECT_EQ(scheduler.now(), SimTime{15});
  scheduler.run_all();
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(scheduler.now(), SimTime{20});
}

TEST(TestScheduler, EventsScheduledByEventsRunInTheSameCall) {
  TestScheduler scheduler;
  std::vector<SimTime> at;
  scheduler.schedule(SimTime{5}, [&] {
    at.push_back(scheduler.now());
    scheduler.schedule(SimTime{0}, [&] { at.push_back(scheduler.now()); });
  });
  scheduler.run_until(SimTime{5});
  EXPECT_EQ(at, (std::vector<SimTime>{SimTime{5}, SimTime{5}}));
}

TEST(TestScheduler, ACancelledEventDoesNotRunAndUnknownIdsAreIgnored) {
  TestScheduler scheduler;
  bool ran = false;
  const TimerId id = scheduler.schedule(SimTime{1}, [&] { ran = true; });
  scheduler.cancel(id);
  scheduler.cancel(id);
  scheduler.cancel(kNoTimer);
  EXPECT_EQ(scheduler.run_all(), 0U);
  EXPECT_FALSE(ran);
  EXPECT_THROW(scheduler.schedule(SimTime{-1}, [] {}), std::invalid_argument);
}

TEST(TestScheduler, AnEndlessProtocolStopsAtTheLimit) {
  TestScheduler scheduler;
  std::function<void()> again = [&] { scheduler.schedule(SimTime{1}, again); };
  scheduler.schedule(SimTime{1}, again);
  EXPECT_THROW(scheduler.run_all(100), std::runtime_error);
}

TEST(FakeRoutingContext, RecordsWhatThePluginAskedAndRunsItsTimers) {
  TestScheduler scheduler;
  FakeRoutingContext node(scheduler, 3, 10);
  EXPECT_EQ(node.node(), 3U);
  EXPECT_EQ(node.node_count(), 10U);
  const Packet control = node.make_control_packet(kBroadcast);
  EXPECT_TRUE(control.is_control());
  EXPECT_EQ(control.source, 3U);
  EXPECT_NE(node.make_control_packet(1).uid, control.uid);
  node.schedule(SimTime{7}, [&] { node.send_to_mac(control, 4); });
  node.count("hello");
  node.count("hello", 2);
  scheduler.run_all();
  ASSERT_EQ(node.to_mac.size(), 1U);
  EXPECT_EQ(node.to_mac[0].next_hop, 4U);
  EXPECT_EQ(node.to_mac[0].at, SimTime{7});
  EXPECT_EQ(node.counter("hello"), 3U);
  EXPECT_EQ(node.counter("never"), 0U);
}

TEST(FakeMacContext, StampsTransmittedFramesAsTheKernelWould) {
  TestScheduler scheduler;
  FakeMacContext node(scheduler, 1, 2);
  const Packet packet = PacketBuilder().from(1).to(0).message(9).payload_bytes(100).build();
  EXPECT_EQ(packet.payload_bytes(), 100U);
  EXPECT_FALSE(packet.is_control());
  node.transmit(data_frame(packet, 1, 0), SimTime{500});
  node.transmit(control_frame(FrameType::ack, 1, 0), SimTime{40});
  ASSERT_EQ(node.transmitted.size(), 2U);
  EXPECT_EQ(node.transmitted[0].frame.transmitter, 1U);
  EXPECT_NE(node.transmitted[0].frame.uid, node.transmitted[1].frame.uid);
  EXPECT_EQ(node.transmitted[0].frame.size_bytes(), 28U + packet.size_bytes());
  node.busy = true;
  EXPECT_TRUE(node.medium_busy());
}

TEST(FakeRobotContext, ActuatorsBehaveAsTheKernelPromises) {
  FakeRobotContext robot;
  robot.max_speed = 0.5;
  robot.set_wheel_speeds(2.0, -2.0);
  EXPECT_EQ(robot.left_mps, 0.5);
  EXPECT_EQ(robot.right_mps, -0.5);
  const std::vector<std::byte> big(kMaxPayloadBytes + 1);
  EXPECT_THROW(robot.send(0, big), std::invalid_argument);
  robot.record("x", 1.0);
  robot.record("x", 3.0);
  EXPECT_EQ(robot.recorded.at("x"), (std::vector<double>{1.0, 3.0}));
  robot.sample("link", 0.5);
  robot.set_wheel_speeds(0.5, 0.5);
  robot.advance();
  EXPECT_NEAR(robot.pose_position.x(), 0.05, 1e-12);
  EXPECT_EQ(robot.now(), from_seconds(0.1));
  robot.sample("link", 0.75);
  ASSERT_EQ(robot.sampled.at("link").size(), 2U);
  EXPECT_EQ(robot.sampled.at("link")[0].at, SimTime{});
  EXPECT_EQ(robot.sampled.at("link")[1].at, from_seconds(0.1));
  EXPECT_EQ(robot.sampled.at("link")[1].value, 0.75);
  // Refused as a run refuses them.
  EXPECT_THROW(robot.sample("", 1.0), std::invalid_argument);
  EXPECT_THROW(robot.sample("two\nlines", 1.0), std::invalid_argument);
  EXPECT_THROW(robot.sample("link", std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

// A controller's decision on its send reports, tested on the kit: a beacon whose report says it
// was dropped is sent again, one hop only.
TEST(FakeRobotContext, SendOptionsAreRecordedAndReportsFaked) {
  FakeRobotContext robot;
  const std::vector<std::byte> beacon(4);
  const std::uint64_t id = robot.send(kBroadcast, beacon, SendOptions{1, true});
  ASSERT_EQ(robot.sent.size(), 1U);
  EXPECT_EQ(robot.sent[0].options.hop_limit, 1U);
  EXPECT_TRUE(robot.sent[0].options.report);
  robot.send(3, beacon);  // without options
  EXPECT_EQ(robot.sent[1].options.hop_limit, 0U);
  EXPECT_FALSE(robot.sent[1].options.report);

  robot.reports = {{id, SendOutcome::dropped, DropReason::queue_full, from_seconds(0.05)}};
  for (const SendReport& report : robot.send_reports()) {
    if (report.outcome == SendOutcome::dropped) {
      robot.send(kBroadcast, robot.sent[report.message_id].payload, SendOptions{1, true});
    }
  }
  ASSERT_EQ(robot.sent.size(), 3U);
  EXPECT_EQ(robot.sent[2].destination, kBroadcast);
  EXPECT_EQ(robot.sent[2].options.hop_limit, 1U);
}

// The example of docs/plugins.md, "Range and bearing": head for the mean bearing of the robots
// in sight, and tell them how many of them this robot sees.
void flock_step(RobotContext& robot) {
  const auto seen = robot.range_and_bearing();
  double x = 0.0;
  double y = 0.0;
  for (const RangeAndBearingReading& r : seen) {
    x += std::cos(r.bearing_rad);
    y += std::sin(r.bearing_rad);
    robot.record("neighbour_count_heard", std::to_integer<int>(r.data[0]));
  }
  const double turn = seen.empty() ? 0.0 : std::atan2(y, x);  // relative to the heading
  const double w = std::clamp(0.5 * turn, -2.0, 2.0) / robot.step_s();
  const double v = 0.1;
  robot.set_wheel_speeds(v - w * robot.axle_m() / 2.0, v + w * robot.axle_m() / 2.0);
  const std::array<std::byte, 1> count{std::byte(std::min<std::size_t>(seen.size(), 255))};
  robot.set_range_and_bearing_data(count);  // the others read it next step, zero-padded
}

TEST(FakeRobotContext, RangeAndBearingReadingsAreFakedAndTheDataRecorded) {
  FakeRobotContext robot;
  robot.max_speed = 10.0;
  const std::array<std::byte, 1> three{std::byte{3}};
  robot.see_by_range_and_bearing(7, 1.0, 0.2, three);
  robot.see_by_range_and_bearing(2, 2.0, 0.4);
  ASSERT_EQ(robot.range_and_bearing().size(), 2U);
  EXPECT_EQ(robot.range_and_bearing()[0].robot, 2U);  // in id order, as the kernel gives them
  EXPECT_EQ(robot.range_and_bearing()[1].data.size(), 10U);
  EXPECT_EQ(robot.range_and_bearing()[1].data[0], std::byte{3});
  EXPECT_EQ(robot.range_and_bearing()[1].data[9], std::byte{0});

  flock_step(robot);
  EXPECT_GT(robot.right_mps, robot.left_mps) << "turns left, towards bearings 0.2 and 0.4";
  EXPECT_EQ(robot.recorded.at("neighbour_count_heard"), (std::vector<double>{0.0, 3.0}));
  ASSERT_EQ(robot.range_and_bearing_data.size(), 1U);
  EXPECT_EQ(robot.range_and_bearing_data[0].data.size(), 10U);
  EXPECT_EQ(robot.range_and_bearing_data[0].data[0], std::byte{2});

  const std::vector<std::byte> too_long(11);
  EXPECT_THROW(robot.set_range_and_bearing_data(too_long), std::invalid_argument);
  robot.range_and_bearing_enabled = false;
  EXPECT_THROW((void)robot.range_and_bearing(), std::logic_error);
  EXPECT_THROW(robot.set_range_and_bearing_data(three), std::logic_error);
}

// A stand-in plugin class with a parameter table, for plugin_args.
struct Tabled {
  static PluginInfo info() {
    return {"tabled",
            "1.0.0",
            "",
            "",
            {real_param("gain", 1.0, "", "", 0.0, 2.0), integer_param("n", 3, "", "", 1, 9),
             text_param("mode", "a", "", {"a", "b"})}};
  }
};

TEST(PluginArgs, DefaultsThenCheckedOverrides) {
  const PluginArgs args = plugin_args<Tabled>({{"gain", 1.5}}, 42, 3, 8);
  EXPECT_EQ(args.params.real("gain"), 1.5);
  EXPECT_EQ(args.params.integer("n"), 3);
  EXPECT_EQ(args.params.text("mode"), "a");
  EXPECT_EQ(args.seed, 42U);
  EXPECT_EQ(args.instance, 3U);
  EXPECT_EQ(args.instance_count, 8U);
  EXPECT_THROW(plugin_args<Tabled>({{"gian", 1.0}}), std::invalid_argument);
  EXPECT_THROW(plugin_args<Tabled>({{"n", 2.0}}), std::invalid_argument);  // real for integer
  EXPECT_THROW(plugin_args<Tabled>({{"gain", 3.0}}), std::invalid_argument);
  EXPECT_THROW(plugin_args<Tabled>({{"mode", std::string("c")}}), std::invalid_argument);
}

}  // namespace
}  // namespace swarmnet::testing
