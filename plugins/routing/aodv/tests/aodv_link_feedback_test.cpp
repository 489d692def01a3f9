// AODV's layer-2 feedback as ns-3.37's AODV receives it, on the SDK test kit (one node, node 0
// of 10, with a fake routing context). ns-3 (aodv-routing-protocol.cc NotifyTxError,
// aodv-neighbor.cc ProcessTxError, Update, LookupMacAddress) closes only a neighbour whose
// link-layer address its ARP cache had resolved when the neighbour was recorded; any other
// report breaks no link. The neighbour list is filled by HELLOs (with enable_hello), RREQs and
// data traffic, and expired neighbours break their links at the neighbour timer's purges.
#include <gtest/gtest.h>

#include <memory>

#include "aodv_one_node.hpp"

namespace swarmnet::aodv {
namespace {

using testing::PacketBuilder;

class AodvLinkFeedback : public AodvOneNode {
 protected:
  // A RREP answering this node's (imagined) RREQ: a route to `destination` through `next_hop`.
  void route_via(NodeId destination, NodeId next_hop) {
    Rrep rrep;
    rrep.destination = destination;
    rrep.destination_seq = 7;
    rrep.originator = 0;
    rrep.hop_count = 1;
    rrep.lifetime_ms = 10000;
    hear(rrep, next_hop);
  }
  void rreq_from(NodeId neighbor) {
    Rreq rreq;
    rreq.originator = neighbor;
    rreq.originator_seq = 3;
    rreq.id = 1;
    rreq.destination = 8;
    rreq.unknown_seq = true;
    rreq.ttl = 1;  // not relayed
    hear(rreq, neighbor);
  }
  [[nodiscard]] bool valid(NodeId destination) const {
    const RouteEntry* route = aodv_->routing_table().entry(destination);
    return route != nullptr && route->state == RouteState::valid &&
           route->expires >= scheduler_.now();
  }
  static Packet data_to(NodeId destination) {
    return PacketBuilder().uid(500).from(0).to(destination).message(1).payload_bytes(50).build();
  }
  static Packet arp_reply_to(NodeId requester) {
    Packet packet = PacketBuilder().uid(600).from(0).to(requester).build();
    packet.protocol = LinkProtocol::arp_reply;
    return packet;
  }
};

TEST_F(AodvLinkFeedback, AReportForANextHopThatIsNoNeighbourBreaksNothing) {
  make();
  route_via(9, 5);  // a route through 5, which is not in the neighbour list
  ASSERT_FALSE(aodv_->neighbors().is_neighbor(5, scheduler_.now()));
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_failures"), 1U);
  EXPECT_EQ(node_.counter("link_breaks"), 0U);
  EXPECT_TRUE(valid(9));
  EXPECT_TRUE(valid(5));
}

TEST_F(AodvLinkFeedback, NextHopMatchingBreaksTheLinkToAnyReportedNextHop) {
  make({{"link_failure_match", std::string("next_hop")}});
  route_via(9, 5);
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
  EXPECT_FALSE(valid(5));
}

TEST_F(AodvLinkFeedback, AReportForANeighbourWithoutAResolvedAddressBreaksNothing) {
  make();
  node_.unresolved = {5};
  hello_from(5);
  route_via(9, 5);
  ASSERT_TRUE(aodv_->neighbors().is_neighbor(5, scheduler_.now()));
  EXPECT_FALSE(aodv_->neighbors().address_known(5));
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_breaks"), 0U);
  EXPECT_TRUE(valid(9));
  EXPECT_TRUE(aodv_->neighbors().is_neighbor(5, scheduler_.now()));

  node_.unresolved.clear();  // ARP resolves 5; the next HELLO records its address
  hello_from(5);
  EXPECT_TRUE(aodv_->neighbors().address_known(5));
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
  EXPECT_FALSE(aodv_->neighbors().is_neighbor(5, scheduler_.now()));
}

TEST_F(AodvLinkFeedback, AnAddressOnceResolvedIsKeptWhenTheArpEntryLapses) {
  make();
  hello_from(5);
  route_via(9, 5);
  node_.unresolved = {5};  // ns-3 looks the address up only while it is unknown
  hello_from(5);
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
}

TEST_F(AodvLinkFeedback, ADroppedArpReplyClosesAResolvedNeighbourAndIsNeverBuffered) {
  make({{"enable_local_repair", true}});
  hello_from(5);
  route_via(9, 5);
  Packet arp = arp_reply_to(5);
  arp.source = 3;  // even looking like a relayed data packet, it is never repaired
  arp.message_id = 42;
  aodv_->link_failed(arp, 5);
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
  EXPECT_FALSE(valid(5));
  EXPECT_EQ(node_.counter("local_repairs"), 0U);
  EXPECT_EQ(aodv_->request_queue().size(), 0U);
  EXPECT_TRUE(node_.dropped.empty());
  scheduler_.run_for(from_seconds(0.05));
  for (const auto& out : node_.to_mac) EXPECT_FALSE(out.packet.is_arp());
}

TEST_F(AodvLinkFeedback, ABroadcastDropMatchesNoNeighbour) {
  make();
  hello_from(5);
  route_via(9, 5);
  aodv_->link_failed(PacketBuilder().uid(7).from(0).broadcast().build(), kBroadcast);
  EXPECT_EQ(node_.counter("link_breaks"), 0U);
  EXPECT_TRUE(valid(9));
}

TEST_F(AodvLinkFeedback, WithoutLinkLayerFeedbackReportsAreOnlyCounted) {
  make({{"link_layer_feedback", false}});
  hello_from(5);
  route_via(9, 5);
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_failures"), 1U);
  EXPECT_EQ(node_.counter("link_breaks"), 0U);
  EXPECT_TRUE(valid(9));
}

// enable_hello: false. ns-3.37 still records neighbours from RREQs (RecvRequest) and traffic,
// not from HELLOs others send (ProcessHello), and the first neighbour recorded starts the
// neighbour timer, whose purges break the links of expired neighbours.
TEST_F(AodvLinkFeedback, WithoutHellosRreqsMakeNeighboursThatTheMacCanClose) {
  make({{"enable_hello", false}});
  hello_from(6);
  EXPECT_FALSE(aodv_->neighbors().is_neighbor(6, scheduler_.now()));
  rreq_from(5);
  route_via(9, 5);
  EXPECT_TRUE(aodv_->neighbors().is_neighbor(5, scheduler_.now()));
  aodv_->link_failed(data_to(9), 5);
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
}

TEST_F(AodvLinkFeedback, WithoutHellosAnExpiredNeighbourBreaksItsLinksAtTheNextPurge) {
  make({{"enable_hello", false}});
  rreq_from(5);  // a neighbour for allowed_hello_loss * hello_interval = 2 s
  route_via(9, 5);
  scheduler_.run_until(from_seconds(2.5));
  EXPECT_TRUE(valid(9));  // expired after 2 s, not yet purged
  EXPECT_EQ(node_.counter("link_breaks"), 0U);
  scheduler_.run_until(from_seconds(3.0));  // purges every hello_interval from the first record
  EXPECT_EQ(node_.counter("link_breaks"), 1U);
  EXPECT_FALSE(valid(9));
}

}  // namespace
}  // namespace swarmnet::aodv
