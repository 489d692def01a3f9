// ns-3.37's rule for the route to a RREQ's sender (aodv-routing-protocol.cc RecvRequest, after
// the reverse route: toNeighbor.SetLifeTime(ActiveRouteTimeout), SetValidSeqNo(false),
// SetSeqNo(rreq's originator number), SetFlag(VALID), SetHop(1), SetNextHop(src)), with
// rreq_invalidates_sender_seqno: true, against SwarmNet's default, which keeps the number. On the
// SDK test kit: one node, node 0 of 10, with a fake routing context.
//
// Why it matters (issue 19, delay): a node that relays a RREQ no longer counts as answerable by
// its neighbours until its next HELLO, and a node relaying RREQs sends no HELLO. During the
// floods that start traffic, ns-3's discoveries must reach the destination itself, one ring
// further than SwarmNet's did: SwarmNet buffered packets for routes 1.6-1.7 times shorter.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "aodv_one_node.hpp"

namespace swarmnet::aodv {
namespace {

using testing::ParamOverrides;

class AodvRreqSender : public AodvOneNode {
 protected:
  void make(bool ns3_rule) {
    AodvOneNode::make(ParamOverrides{{"rreq_invalidates_sender_seqno", ns3_rule}});
  }
  // A RREQ of `originator` (sequence number `originator_seq`) for `destination`, relayed to this
  // node by `from`.
  void rreq(NodeId from, NodeId originator, std::uint32_t originator_seq, NodeId destination) {
    Rreq rreq;
    rreq.originator = originator;
    rreq.originator_seq = originator_seq;
    rreq.id = 1;
    rreq.hop_count = from == originator ? 0 : 1;
    rreq.destination = destination;
    rreq.unknown_seq = true;
    rreq.ttl = 2;
    hear(rreq, from);
  }
  [[nodiscard]] const RouteEntry& route(NodeId destination) const {
    const RouteEntry* entry = aodv_->routing_table().entry(destination);
    if (entry == nullptr) throw std::out_of_range("no route to " + std::to_string(destination));
    return *entry;
  }
  // RREPs this node unicast to `next_hop` so far.
  [[nodiscard]] std::size_t replies_to(NodeId next_hop) const {
    std::size_t n = 0;
    for (const auto& sent : node_.to_mac) {
      if (sent.next_hop != next_hop || !sent.packet.is_control()) continue;
      const std::optional<Message> message = decode(sent.packet.header);
      if (message && std::holds_alternative<Rrep>(*message)) ++n;
    }
    return n;
  }
};

TEST_F(AodvRreqSender, Ns3LeavesTheRouteToARreqSenderValidWithoutASequenceNumber) {
  make(true);
  hello_from(5, 1);
  ASSERT_TRUE(route(5).valid_seq);
  scheduler_.run_for(from_seconds(0.5));
  rreq(5, 7, 3, 8);  // 5 relays 7's RREQ for 8
  const RouteEntry& to_5 = route(5);
  EXPECT_TRUE(to_5.is_valid());
  EXPECT_EQ(to_5.hop_count, 1U);
  EXPECT_EQ(to_5.next_hop, 5U);
  EXPECT_FALSE(to_5.valid_seq);
  EXPECT_EQ(to_5.seq, 3U);  // ns-3 copies the RREQ's originator number into it
  EXPECT_EQ(to_5.expires, scheduler_.now() + from_seconds(3.0));  // ActiveRouteTimeout, set
}

TEST_F(AodvRreqSender, Ns3AnswersNoRreqForANeighbourThatRelayedARreqUntilItsNextHello) {
  make(true);
  hello_from(5, 1);
  rreq(5, 7, 3, 8);
  rreq(6, 9, 4, 5);  // 9's RREQ for 5, through 6: relayed, not answered
  EXPECT_EQ(replies_to(6), 0U);
  scheduler_.run_for(from_seconds(0.02));        // past the broadcast jitter
  EXPECT_EQ(node_.counter("control_rreq"), 2U);  // 7's RREQ for 8 and 9's for 5, both relayed

  hello_from(5, 2);  // the number is known again
  EXPECT_TRUE(route(5).valid_seq);
  EXPECT_EQ(route(5).seq, 2U);
  rreq(6, 4, 4, 5);  // 4's RREQ for 5: answered for the neighbour
  EXPECT_EQ(replies_to(6), 1U);
}

TEST_F(AodvRreqSender, ByDefaultTheRouteToARreqSenderKeepsItsNumberAndAnswers) {
  make(false);
  hello_from(5, 1);
  rreq(5, 7, 3, 8);
  EXPECT_TRUE(route(5).valid_seq);
  EXPECT_EQ(route(5).seq, 1U);
  rreq(6, 9, 4, 5);
  EXPECT_EQ(replies_to(6), 1U);
}

TEST_F(AodvRreqSender, Ns3RuleAppliesToTheOriginatorsOwnReverseRoute) {
  make(true);
  rreq(7, 7, 3, 8);  // heard from its originator: the reverse route is the route to the sender
  const RouteEntry& to_7 = route(7);
  EXPECT_TRUE(to_7.is_valid());
  EXPECT_FALSE(to_7.valid_seq);
  EXPECT_EQ(to_7.seq, 3U);
}

}  // namespace
}  // namespace swarmnet::aodv
