// ideal_mac timing: airtime = (header_bytes + packet bytes) * 8 / bitrate, frames back to back.
#include <gtest/gtest.h>

#include <algorithm>

#include "network_test_support.hpp"
#include "protocol/step_data.hpp"

namespace swarmnet {
namespace {

// Packet above the MAC with `direct` routing (no routing header): 28 B IP/UDP + payload.
constexpr std::uint32_t kPayloadBytes = 100;
constexpr std::uint32_t kPacketBytes = kNetworkHeaderBytes + kPayloadBytes;  // 128
constexpr std::uint32_t kFrameBytes = 28 + kPacketBytes;                     // 156

class NetworkIdealMac : public ::testing::Test {
 protected:
  NetworkIdealMac() : scenario_(test::make_settings(loader_, 3, "ideal_mac", "direct")) {
    test::set_param(scenario_.network.propagation[0], "range_m", 1000.0);
    // Static ARP: these tests pin the MAC's airtimes and queue; ARP's exchange, which would add
    // frames before the first data frame, has tests of its own (arp_network_test.cpp).
    scenario_.network.arp.reset();
  }

  SimTime injected_at(std::uint64_t message_id) const {
    return injection_offset(scenario_.seed, message_id, from_seconds(scenario_.step_s));
  }

  PluginLoader loader_;
  NetworkSettings scenario_;
  // Node 1 is 300 m from node 0; node 2 is 200 m away, also in range.
  std::vector<Vec2> positions_ = {{10, 50}, {310, 50}, {10, 250}};
};

TEST_F(NetworkIdealMac, SingleFrameArrivesAfterAirtimePlusPropagation) {
  const auto out = test::run(
      scenario_, loader_,
      test::fixed_batches(scenario_, positions_, 2, {test::message(0, 0, 1, kPayloadBytes)}));
  ASSERT_EQ(out.deliveries.size(), 1U);  // node 2 hears the unicast frame and ignores it
  const Delivery& d = out.deliveries[0];
  EXPECT_EQ(d.receiver, 1U);
  EXPECT_EQ(d.hops, 1U);
  EXPECT_EQ(d.sent_at, injected_at(0));
  // 156 B * 8 / 6 Mbit/s = 208 us exactly; 300 m / c = 1000.69 ns, rounded to 1001 ns.
  EXPECT_EQ(d.delivered_at - d.sent_at, SimTime{208'000 + 1'001});
  EXPECT_EQ(out.report["mac"]["tx_frames"], 1);
  EXPECT_EQ(out.report["mac"]["tx_bytes"], kFrameBytes);
  EXPECT_DOUBLE_EQ(out.report["delay_s"]["mean"].get<double>(), 209'001e-9);
}

TEST_F(NetworkIdealMac, BackToBackFramesAreSerialised) {
  // At 10 kbit/s a frame takes 124.8 ms, longer than a step: every message of step 0 is queued
  // before the first frame ends, and they leave one after another in injection order.
  test::set_param(scenario_.network.mac, "bitrate_bps", 1.0e4);
  const SimTime airtime{124'800'000};
  const SimTime propagation{1'001};
  std::vector<AppMessage> messages;
  for (std::uint64_t id = 0; id < 5; ++id)
    messages.push_back(test::message(id, 0, 1, kPayloadBytes));
  const auto out = test::run(scenario_, loader_,
                             test::fixed_batches(scenario_, positions_, 10, std::move(messages)));
  ASSERT_EQ(out.deliveries.size(), 5U);

  std::vector<std::uint64_t> by_injection = {0, 1, 2, 3, 4};
  std::sort(by_injection.begin(), by_injection.end(),
            [&](std::uint64_t a, std::uint64_t b) { return injected_at(a) < injected_at(b); });
  const SimTime first = injected_at(by_injection[0]);
  for (std::size_t k = 0; k < 5; ++k) {
    const Delivery& d = out.deliveries[k];
    EXPECT_EQ(d.message_id, by_injection[k]);
    EXPECT_EQ(d.delivered_at, first + airtime * static_cast<std::int64_t>(k + 1) + propagation);
  }
  EXPECT_EQ(out.report["packets"]["dropped"]["queue_full"], 0);
}

TEST_F(NetworkIdealMac, QueueOverflowDropsAreCounted) {
  test::set_param(scenario_.network.mac, "bitrate_bps", 1.0e4);
  test::set_param(scenario_.network.mac, "queue_limit", std::int64_t{2});
  std::vector<AppMessage> messages;
  for (std::uint64_t id = 0; id < 5; ++id)
    messages.push_back(test::message(id, 0, 1, kPayloadBytes));
  const auto out = test::run(scenario_, loader_,
                             test::fixed_batches(scenario_, positions_, 10, std::move(messages)));

  // One frame on the air, two waiting: the last two injected are dropped.
  std::vector<std::uint64_t> by_injection = {0, 1, 2, 3, 4};
  std::sort(by_injection.begin(), by_injection.end(),
            [&](std::uint64_t a, std::uint64_t b) { return injected_at(a) < injected_at(b); });
  ASSERT_EQ(out.deliveries.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(out.deliveries[k].message_id, by_injection[k]);
  EXPECT_EQ(out.report["packets"]["dropped"]["queue_full"], 2);
  EXPECT_EQ(out.report["packets"]["delivered"], 3);

  const auto trace = test::parse_trace(out.trace);
  std::vector<std::string> dropped;
  for (const auto& line : trace) {
    if (line.event != "drop") continue;
    EXPECT_EQ(line.detail, "queue_full");
    EXPECT_EQ(line.node, 0);
    EXPECT_EQ(line.time_ns, injected_at(std::stoull(line.message_id)).count());
    dropped.push_back(line.message_id);
  }
  EXPECT_EQ(dropped, (std::vector<std::string>{std::to_string(by_injection[3]),
                                               std::to_string(by_injection[4])}));
}

}  // namespace
}  // namespace swarmnet
