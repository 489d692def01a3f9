// flooding as a protocol, on the SDK test kit: one node's plugin with a fake routing context.
#include <gtest/gtest.h>

#include <vector>

#include "flooding.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::flooding {
namespace {

using testing::FakeRoutingContext;
using testing::PacketBuilder;
using testing::plugin_args;
using testing::TestScheduler;

class FloodingProtocol : public ::testing::Test {
 protected:
  // Node 2 of 5, flooding with `jitter_max_s` and `ttl`.
  void make(double jitter_max_s, std::int64_t ttl = 32) {
    flooding_ = std::make_unique<Flooding>(
        plugin_args<Flooding>({{"jitter_max_s", jitter_max_s}, {"ttl", ttl}}, 7, 2, 5));
    flooding_->attach(node_);
  }
  // A packet as node `originator` flooded it with sequence `sequence` and `ttl` hops left.
  static Packet flooded(NodeId originator, NodeId destination, std::uint32_t sequence,
                        std::uint8_t ttl) {
    Packet packet = PacketBuilder()
                        .from(originator)
                        .to(destination)
                        .message(sequence)
                        .hops(1)
                        .payload_bytes(10)
                        .build();
    encode(FloodingHeader{originator, sequence, ttl}, packet.header);
    return packet;
  }

  TestScheduler scheduler_;
  FakeRoutingContext node_{scheduler_, 2, 5};
  std::unique_ptr<Flooding> flooding_;
};

TEST_F(FloodingProtocol, AnOriginatedPacketGoesOutAsABroadcastAtOnce) {
  make(0.005);
  flooding_->send(PacketBuilder().from(2).to(4).message(1).payload_bytes(10).build());
  ASSERT_EQ(node_.to_mac.size(), 1U);
  EXPECT_EQ(node_.to_mac[0].next_hop, kBroadcast);
  EXPECT_EQ(node_.to_mac[0].at, SimTime{0});
  EXPECT_EQ(node_.to_mac[0].packet.header.size(), 9U);
}

TEST_F(FloodingProtocol, AFirstCopyIsRelayedOnceWithinTheJitterAndLaterCopiesAreCounted) {
  make(0.005);
  flooding_->receive(flooded(0, 4, 1, 5), 0);
  flooding_->receive(flooded(0, 4, 1, 5), 1);  // the same packet from another neighbour
  EXPECT_TRUE(node_.to_mac.empty());           // waiting for its jitter
  scheduler_.run_for(from_seconds(0.005));
  ASSERT_EQ(node_.to_mac.size(), 1U);
  EXPECT_LE(node_.to_mac[0].at, from_seconds(0.005));
  EXPECT_EQ(node_.forwarded.size(), 1U);
  EXPECT_EQ(node_.counter("duplicates"), 1U);
  EXPECT_TRUE(node_.delivered.empty());  // not for this node
  const auto header = decode(node_.to_mac[0].packet.header);
  ASSERT_TRUE(header.has_value());
  EXPECT_EQ(header->ttl, 4);
}

TEST_F(FloodingProtocol, TheDestinationDeliversAndDoesNotRelay) {
  make(0.0);
  flooding_->receive(flooded(0, 2, 1, 5), 0);
  scheduler_.run_all();
  EXPECT_EQ(node_.delivered.size(), 1U);
  EXPECT_TRUE(node_.to_mac.empty());
}

TEST_F(FloodingProtocol, APacketOnItsLastHopIsDroppedAsTtlExpired) {
  make(0.0);
  flooding_->receive(flooded(0, 4, 1, 1), 0);
  scheduler_.run_all();
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::ttl_expired);
  EXPECT_TRUE(node_.to_mac.empty());
}

TEST_F(FloodingProtocol, ABroadcastIsDeliveredHereAndRelayed) {
  make(0.0);
  flooding_->receive(flooded(0, kBroadcast, 1, 5), 0);
  scheduler_.run_all();
  EXPECT_EQ(node_.delivered.size(), 1U);
  EXPECT_EQ(node_.to_mac.size(), 1U);
}

TEST_F(FloodingProtocol, AMalformedHeaderIsCountedAndIgnored) {
  make(0.0);
  flooding_->receive(PacketBuilder().from(0).to(4).message(1).header({1, 2, 3}).build(), 0);
  scheduler_.run_all();
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_TRUE(node_.to_mac.empty());
  EXPECT_TRUE(node_.delivered.empty());
}

}  // namespace
}  // namespace swarmnet::flooding
