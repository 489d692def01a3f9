// gossip on the SDK test kit: one node's plugin, a fake routing context, simulated time.
#include "gossip.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "swarmnet/testing.hpp"

namespace example::gossip {
namespace {

using namespace swarmnet;
using swarmnet::testing::FakeRoutingContext;
using swarmnet::testing::PacketBuilder;
using swarmnet::testing::plugin_args;
using swarmnet::testing::TestScheduler;

struct Node {
  explicit Node(double p) : gossip(plugin_args<Gossip>({{"p", p}}, 3, 1, 4)) { gossip.attach(ctx); }
  TestScheduler scheduler;
  FakeRoutingContext ctx{scheduler, 1, 4};
  Gossip gossip;
};

TEST(Gossip, WithPOneAFirstCopyIsDeliveredRelayedOnceAndADuplicateCounted) {
  Node node(1.0);
  const Packet heard = PacketBuilder().uid(5).from(0).broadcast().message(1).hops(1).build();
  node.gossip.receive(heard, 0);
  node.gossip.receive(heard, 2);
  node.scheduler.run_all();
  EXPECT_EQ(node.ctx.delivered.size(), 1U);
  ASSERT_EQ(node.ctx.to_mac.size(), 1U);
  EXPECT_EQ(node.ctx.to_mac[0].next_hop, kBroadcast);
  EXPECT_EQ(node.ctx.counter("gossip_relays"), 1U);
  EXPECT_EQ(node.ctx.counter("duplicates"), 1U);
}

TEST(Gossip, WithPZeroNothingIsRelayed) {
  Node node(0.0);
  node.gossip.receive(PacketBuilder().uid(5).from(0).to(3).message(1).hops(1).build(), 0);
  node.scheduler.run_all();
  EXPECT_TRUE(node.ctx.to_mac.empty());
  EXPECT_EQ(node.ctx.counter("gossip_suppressed"), 1U);
}

TEST(Gossip, TheDestinationDeliversAndDoesNotRelay) {
  Node node(1.0);
  node.gossip.receive(PacketBuilder().uid(5).from(0).to(1).message(1).hops(1).build(), 0);
  node.scheduler.run_all();
  EXPECT_EQ(node.ctx.delivered.size(), 1U);
  EXPECT_TRUE(node.ctx.to_mac.empty());
}

}  // namespace
}  // namespace example::gossip
