// ARP inside whole runs (network.arp: ns3, the default): its frames go through the MAC and the
// channel like any other, cost airtime and delay the first packet to a neighbour, and a
// neighbour out of reach is given up after ns-3's retries.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "network_test_support.hpp"

namespace swarmnet {
namespace {

constexpr std::uint32_t kPayloadBytes = 100;
constexpr std::int64_t kMs = 1'000'000;

std::uint64_t arp(const test::RunOutput& out, const char* key) {
  return out.report["arp"][key].get<std::uint64_t>();
}

class ArpNetwork : public ::testing::Test {
 protected:
  ArpNetwork() : settings_(test::make_settings(loader_, 3, "ideal_mac", "direct")) {
    test::set_param(settings_.network.propagation[0], "range_m", 1000.0);
  }
  PluginLoader loader_;
  NetworkSettings settings_;
  std::vector<Vec2> positions_ = {{10, 50}, {310, 50}, {10, 250}};
};

TEST_F(ArpNetwork, TheFirstPacketWaitsForARequestAndAReply) {
  const auto out = test::run(settings_, loader_,
                             test::fixed_batches(settings_, positions_, 3,
                                                 {test::message(0, 0, 1, kPayloadBytes),
                                                  test::message(1, 0, 1, kPayloadBytes)}));
  ASSERT_EQ(out.deliveries.size(), 2U);
  // The broadcast request (node 2 hears it and keeps quiet: not its address), the reply, the
  // two data frames: 4 frames, every one at 6 Mbit/s with ideal_mac's 28 header bytes.
  EXPECT_EQ(out.report["mac"]["tx_frames"], 4);
  EXPECT_EQ(out.report["mac"]["tx_bytes"], 2 * (28 + 28) + 2 * (28 + 28 + kPayloadBytes));
  EXPECT_EQ(arp(out, "requests_sent"), 1U);
  EXPECT_EQ(arp(out, "replies_sent"), 1U);
  EXPECT_EQ(arp(out, "resolved"), 1U);
  // The first message waited a whole number of milliseconds of jitter, then the request's and
  // the reply's airtime (56 B at 6 Mbit/s: 74.667 us each) and propagation (300 m: 1001 ns).
  const Delivery& first = out.deliveries[0];
  const std::int64_t delay = (first.delivered_at - first.sent_at).count();
  const std::int64_t after_jitter = delay % kMs;
  EXPECT_LT(delay, 10 * kMs);
  EXPECT_NEAR(static_cast<double>(after_jitter), 2 * (74'667 + 1'001) + 208'000 + 1'001, 4.0);
}

TEST_F(ArpNetwork, ANeighbourOutOfReachIsGivenUpAfterThreeRetries) {
  std::vector<Vec2> far = positions_;
  far[1] = {5000, 50};  // beyond the 1000 m disk
  settings_.arena.width_m = 6000.0;
  auto batches = test::fixed_batches(settings_, far, 60, {test::message(0, 0, 1, kPayloadBytes)});
  const auto out = test::run(settings_, loader_, batches);
  EXPECT_TRUE(out.deliveries.empty());
  EXPECT_EQ(arp(out, "requests_sent"), 4U);  // the first and three retries
  EXPECT_EQ(arp(out, "failed"), 1U);
  EXPECT_EQ(out.report["packets"]["dropped"]["arp_unresolved"], 1);
}

TEST_F(ArpNetwork, StaticEntriesSendNoArpFrame) {
  settings_.network.arp.reset();
  const auto out = test::run(
      settings_, loader_,
      test::fixed_batches(settings_, positions_, 2, {test::message(0, 0, 1, kPayloadBytes)}));
  ASSERT_EQ(out.deliveries.size(), 1U);
  EXPECT_EQ(out.report["mac"]["tx_frames"], 1);
  EXPECT_EQ(arp(out, "requests_sent"), 0U);
}

TEST_F(ArpNetwork, AodvOverArpOnALineDeliversAndRunsAreByteIdentical) {
  NetworkSettings settings = test::make_settings(loader_, 5, "ideal_mac", "aodv");
  auto batches = test::fixed_batches(settings, test::line_positions(5, 100.0), 40, {});
  for (std::uint64_t step = 0; step < 20; ++step) {
    batches[step].messages.push_back(test::message(step, 0, 4));
  }
  const auto first = test::run(settings, loader_, batches);
  const auto second = test::run(settings, loader_, batches);
  EXPECT_EQ(first.trace, second.trace);
  EXPECT_EQ(first.report.dump(), second.report.dump());
  // Every hop resolved its next hop (and RREPs resolved theirs on the way back).
  EXPECT_GE(arp(first, "resolved"), 4U);
  EXPECT_EQ(arp(first, "failed"), 0U);
  // ns-3's pending queue holds 3 packets per neighbour: what AODV releases at once when its
  // route is found may overflow it, and nothing else is lost on a quiet line.
  const std::uint64_t arp_drops =
      first.report["packets"]["dropped"]["arp_queue_full"].get<std::uint64_t>();
  EXPECT_EQ(first.deliveries.size() + arp_drops, 20U);
  EXPECT_GE(first.deliveries.size(), 17U);
  for (const Delivery& d : first.deliveries) EXPECT_EQ(d.hops, 4U);
}

}  // namespace
}  // namespace swarmnet
