// Flooding over a line of robots 100 m apart with a 120 m disk: each robot hears only its
// immediate neighbours, so a flood must relay hop by hop.
#include <gtest/gtest.h>

#include "network_test_support.hpp"

namespace swarmnet {
namespace {

constexpr std::uint32_t kLine = 10;
constexpr double kSpacingM = 100.0;

class NetworkFlooding : public ::testing::Test {
 protected:
  NetworkFlooding() : settings_(test::make_settings(loader_, kLine)) {}

  test::RunOutput run_line(AppMessage message) {
    return test::run(settings_, loader_,
                     test::fixed_batches(settings_, test::line_positions(kLine, kSpacingM), 10,
                                         {std::move(message)}));
  }

  PluginLoader loader_;
  NetworkSettings settings_;
};

TEST_F(NetworkFlooding, UnicastCrossesTheLineWithEveryRelayForwardingOnce) {
  const auto out = run_line(test::message(0, 0, kLine - 1));
  ASSERT_EQ(out.deliveries.size(), 1U);
  const Delivery& delivery = out.deliveries[0];
  EXPECT_EQ(delivery.receiver, kLine - 1);
  EXPECT_EQ(delivery.hops, kLine - 1);
  EXPECT_GT(delivery.delivered_at, delivery.sent_at);
  EXPECT_EQ(delivery.payload, test::message(0, 0, kLine - 1).payload);

  const auto trace = test::parse_trace(out.trace);
  EXPECT_EQ(test::count_events(trace, "send", 0), 1U);
  EXPECT_EQ(test::count_events(trace, "forward", 0), 0U);  // the originator sends, not forwards
  for (std::uint32_t node = 1; node + 1 < kLine; ++node) {
    EXPECT_EQ(test::count_events(trace, "forward", node), 1U) << "node " << node;
    EXPECT_EQ(test::count_events(trace, "deliver", node), 0U) << "node " << node;
  }
  EXPECT_EQ(test::count_events(trace, "forward", kLine - 1), 0U);  // destination stops it
  EXPECT_EQ(test::count_events(trace, "deliver", kLine - 1), 1U);
  // A relay at node k has traversed k links.
  for (const auto& line : trace) {
    if (line.event == "forward") {
      EXPECT_EQ(line.hops, static_cast<std::uint32_t>(line.node));
    }
  }

  EXPECT_EQ(out.report["pdr"].get<double>(), 1.0);
  EXPECT_EQ(out.report["hops_mean"].get<double>(), kLine - 1.0);
  EXPECT_EQ(out.report["routing"]["data_forwards"], kLine - 2);
  // Each relay's copy is heard by both neighbours; all but the first are duplicates.
  EXPECT_EQ(out.report["mac"]["tx_frames"], kLine - 1);
  EXPECT_GT(out.report["routing"]["duplicates"].get<int>(), 0);
}

TEST_F(NetworkFlooding, BroadcastIsDeliveredAndForwardedOnceByEveryNode) {
  const auto out = run_line(test::message(0, 0, kBroadcast));
  ASSERT_EQ(out.deliveries.size(), kLine - 1);
  std::vector<int> delivered(kLine, 0);
  for (const Delivery& d : out.deliveries) {
    ++delivered[d.receiver];
    EXPECT_EQ(d.hops, d.receiver);
    EXPECT_EQ(d.destination, kBroadcast);
  }
  EXPECT_EQ(delivered[0], 0);  // the source does not receive its own broadcast
  for (std::uint32_t node = 1; node < kLine; ++node) EXPECT_EQ(delivered[node], 1) << node;

  const auto trace = test::parse_trace(out.trace);
  EXPECT_EQ(test::count_events(trace, "forward", 0), 0U);
  for (std::uint32_t node = 1; node < kLine; ++node) {
    EXPECT_EQ(test::count_events(trace, "forward", node), 1U) << "node " << node;
  }
  EXPECT_EQ(out.report["packets"]["broadcast_sent"], 1);
  EXPECT_EQ(out.report["packets"]["broadcast_deliveries"], kLine - 1);
  EXPECT_EQ(out.report["pdr"].get<double>(), 0.0);  // no unicast sent
  EXPECT_TRUE(out.report["delay_s"]["mean"].is_null());
  EXPECT_TRUE(out.report["hops_mean"].is_null());
}

TEST_F(NetworkFlooding, TtlShorterThanTheLineStopsTheFlood) {
  test::set_param(settings_.network.routing, "ttl", std::int64_t{3});
  const auto out = run_line(test::message(0, 0, kLine - 1));
  EXPECT_TRUE(out.deliveries.empty());

  const auto trace = test::parse_trace(out.trace);
  // ttl 3: nodes 1 and 2 relay, node 3 would relay with ttl 0 and drops instead.
  EXPECT_EQ(test::count_events(trace, "forward", 1), 1U);
  EXPECT_EQ(test::count_events(trace, "forward", 2), 1U);
  EXPECT_EQ(test::count_events(trace, "forward", 3), 0U);
  EXPECT_EQ(test::count_events(trace, "drop", 3), 1U);
  for (const auto& line : trace) {
    if (line.event == "drop") {
      EXPECT_EQ(line.detail, "ttl_expired");
    }
    EXPECT_LE(line.node, 3);
  }
  EXPECT_EQ(out.report["packets"]["dropped"]["ttl_expired"], 1);
  EXPECT_EQ(out.report["packets"]["undelivered"], 1);
  EXPECT_EQ(out.report["pdr"].get<double>(), 0.0);
}

TEST_F(NetworkFlooding, RelayJitterStaysWithinItsBound) {
  test::set_param(settings_.network.routing, "jitter_max_s", 0.002);
  test::set_param(settings_.network.mac, "bitrate_bps", 1.0e9);  // airtime ~1 us per hop
  const auto out = run_line(test::message(0, 0, kLine - 1));
  ASSERT_EQ(out.deliveries.size(), 1U);
  // 9 transmissions of ~1.3 us plus 8 relay jitters of at most 2 ms.
  const SimTime delay = out.deliveries[0].delivered_at - out.deliveries[0].sent_at;
  EXPECT_LT(delay, from_seconds(8 * 0.002 + 9 * 2e-6));
  EXPECT_GT(delay, from_seconds(9 * 1e-6));
}

}  // namespace
}  // namespace swarmnet
