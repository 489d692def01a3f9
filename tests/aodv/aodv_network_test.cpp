// AODV end to end in the network half: the plugin loaded from the build tree, robots on a line
// with a 120 m disk, over ideal_mac (and dcf80211 when it is built). Checks latencies and hop
// counts of discoveries, repair by HELLO loss, and the counters summary.json reports.
#include <gtest/gtest.h>

#include <string>

#include "network_test_support.hpp"
#include "plugin/plugin_error.hpp"

namespace swarmnet {
namespace {

constexpr double kSpacingM = 100.0;

class AodvNetwork : public ::testing::Test {
 protected:
  // Static ARP: these tests pin AODV's discovery latencies and counts; AODV over ARP, which
  // adds an exchange per new neighbour, is tested in arp_network_test.cpp.
  NetworkSettings settings(std::uint32_t robots, const std::string& mac = "ideal_mac") {
    NetworkSettings s = test::make_settings(loader_, robots, mac, "aodv");
    s.network.arp.reset();
    return s;
  }
  PluginLoader loader_;
};

std::uint64_t counter(const nlohmann::ordered_json& report, const char* key) {
  const auto& routing = report["routing"];
  return routing.contains(key) ? routing[key].get<std::uint64_t>() : 0;
}

void expect_control_counters_add_up(const nlohmann::ordered_json& report) {
  const std::uint64_t typed = counter(report, "control_rreq") + counter(report, "control_rrep") +
                              counter(report, "control_rerr") +
                              counter(report, "control_rrep_ack") +
                              counter(report, "control_hello");
  EXPECT_EQ(typed, counter(report, "control_packets"));
}

TEST_F(AodvNetwork, DiscoveryOnALineHasTheExpectedLatencyAndHopCount) {
  const NetworkSettings sc = settings(10);
  // Three hops: found by the TTL 3 ring after the TTL 1 ring's 240 ms timeout.
  auto out = test::run(
      sc, loader_,
      test::fixed_batches(sc, test::line_positions(10, kSpacingM), 10, {test::message(0, 0, 3)}));
  ASSERT_EQ(out.deliveries.size(), 1U);
  EXPECT_EQ(out.deliveries[0].hops, 3U);
  SimTime latency = out.deliveries[0].delivered_at - out.deliveries[0].sent_at;
  EXPECT_GE(latency, from_seconds(0.240));
  EXPECT_LE(latency, from_seconds(0.240 + 3 * 0.010 + 0.003));
  EXPECT_GT(counter(out.report, "control_rreq"), 0U);
  EXPECT_GT(counter(out.report, "control_rrep"), 0U);
  EXPECT_GT(counter(out.report, "control_hello"), 0U);
  EXPECT_EQ(counter(out.report, "route_discoveries"), 2U);
  EXPECT_EQ(out.report["routing"]["data_forwards"], 2);
  expect_control_counters_add_up(out.report);

  // Nine hops: rings 1, 3, 5, 7 time out (240 + 400 + 560 + 720 ms); TTL 35 finds it, node 8
  // answering from its HELLO route.
  out = test::run(
      sc, loader_,
      test::fixed_batches(sc, test::line_positions(10, kSpacingM), 30, {test::message(0, 0, 9)}));
  ASSERT_EQ(out.deliveries.size(), 1U);
  EXPECT_EQ(out.deliveries[0].hops, 9U);
  latency = out.deliveries[0].delivered_at - out.deliveries[0].sent_at;
  EXPECT_GE(latency, from_seconds(1.920));
  EXPECT_LE(latency, from_seconds(1.920 + 9 * 0.010 + 0.005));
  EXPECT_EQ(out.report["pdr"].get<double>(), 1.0);
  EXPECT_EQ(out.report["hops_mean"].get<double>(), 9.0);
}

TEST_F(AodvNetwork, LaterMessagesUseTheRouteWithoutNewDiscovery) {
  const NetworkSettings sc = settings(5);
  auto batches = test::fixed_batches(sc, test::line_positions(5, kSpacingM), 20, {});
  for (std::uint64_t step = 0; step < 10; ++step) {
    batches[step].messages.push_back(test::message(step, 0, 4));
  }
  const auto out = test::run(sc, loader_, batches);
  EXPECT_EQ(out.deliveries.size(), 10U);
  EXPECT_EQ(out.report["pdr"].get<double>(), 1.0);
  EXPECT_LE(counter(out.report, "route_discoveries"), 3U);
  // Messages after the first wait for nothing but airtime.
  for (const Delivery& d : out.deliveries) {
    if (d.message_id >= 9) {
      EXPECT_LT(d.delivered_at - d.sent_at, from_seconds(0.005));
    }
  }
}

TEST_F(AodvNetwork, RepairAfterTheMiddleRobotLeavesOverIdealMac) {
  // 0 and 2 are 200 m apart; relay 1 sits between them, spare 3 far away. At 2 s the relay
  // leaves and the spare takes its place. ideal_mac reports nothing: HELLO loss breaks the link.
  const NetworkSettings sc = settings(4);
  std::vector<Vec2> before{{10, 500}, {110, 500}, {210, 500}, {900, 900}};
  std::vector<Vec2> after{{10, 500}, {110, 100}, {210, 500}, {110, 560}};
  auto batches = test::fixed_batches(sc, before, 100, {});
  for (std::uint64_t step = 0; step < 100; ++step) {
    if (step >= 20) batches[step].positions = after;
    batches[step].messages.push_back(test::message(step, 0, 2));
  }
  const auto out = test::run(sc, loader_, batches);
  const auto trace = test::parse_trace(out.trace);
  EXPECT_GT(test::count_events(trace, "forward", 1), 10U);
  EXPECT_GT(test::count_events(trace, "forward", 3), 40U);
  // Messages from 6 s on all arrive, through the spare.
  std::size_t late = 0;
  for (const Delivery& d : out.deliveries) {
    EXPECT_EQ(d.hops, 2U);
    if (d.message_id >= 60) ++late;
  }
  EXPECT_EQ(late, 40U);
  EXPECT_GE(counter(out.report, "link_breaks"), 1U);
  EXPECT_GT(out.report["pdr"].get<double>(), 0.7);
  expect_control_counters_add_up(out.report);
}

TEST_F(AodvNetwork, UnreachableDestinationDropsAreReportedByReason) {
  NetworkSettings sc = settings(3);
  test::set_param(sc.network.routing, "max_queue_len", std::int64_t{2});
  std::vector<Vec2> positions{{10, 10}, {110, 10}, {900, 900}};
  auto batches = test::fixed_batches(
      sc, positions, 120, {test::message(0, 0, 2), test::message(1, 0, 2), test::message(2, 0, 2)});
  const auto out = test::run(sc, loader_, batches);
  EXPECT_TRUE(out.deliveries.empty());
  EXPECT_EQ(out.report["packets"]["dropped"]["queue_full"], 1);
  EXPECT_EQ(out.report["packets"]["dropped"]["no_route"], 2);
  EXPECT_EQ(counter(out.report, "route_discoveries"), 6U);
}

TEST_F(AodvNetwork, RunsOverDcf80211WhenItIsBuilt) {
  try {
    loader_.find("dcf80211", PluginKind::mac);
  } catch (const PluginError&) {
    GTEST_SKIP() << "dcf80211 is not built";
  }
  const NetworkSettings sc = settings(6, "dcf80211");
  auto batches = test::fixed_batches(sc, test::line_positions(6, kSpacingM), 30, {});
  for (std::uint64_t step = 0; step < 10; ++step) {
    batches[step].messages.push_back(test::message(step, 0, 5));
  }
  const auto out = test::run(sc, loader_, batches);
  EXPECT_EQ(out.deliveries.size(), 10U);
  for (const Delivery& d : out.deliveries) EXPECT_EQ(d.hops, 5U);
  expect_control_counters_add_up(out.report);
}

}  // namespace
}  // namespace swarmnet
