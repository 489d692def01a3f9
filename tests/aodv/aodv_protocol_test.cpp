// The AODV protocol class in a stand-alone test network (aodv_test_network.hpp), where every
// route table can be read at any instant: discovery, expanding ring, intermediate replies,
// sequence-number freshness, RERR propagation, HELLO loss, repair, local repair, RREP-ACK and
// blacklist, buffering limits, rate limits, broadcasts, and loop freedom under random mobility.
#include <gtest/gtest.h>

#include <algorithm>

#include "aodv_test_network.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::aodv {
namespace {

using test::aodv_params;
using test::TestNetwork;

SimTime s(double seconds) { return from_seconds(seconds); }

std::vector<Vec2> line(std::uint32_t n, double spacing_m = 100.0) {
  std::vector<Vec2> out;
  for (std::uint32_t i = 0; i < n; ++i) out.emplace_back(spacing_m * i, 0.0);
  return out;
}

const test::TestDelivery* delivery_of(const TestNetwork& net, std::uint64_t message_id) {
  for (const auto& d : net.deliveries()) {
    if (d.message_id == message_id) return &d;
  }
  return nullptr;
}

std::size_t drops_with(const TestNetwork& net, DropReason reason) {
  return static_cast<std::size_t>(std::count_if(
      net.drops().begin(), net.drops().end(),
      [reason](const test::TestDrop& d) { return !d.control && d.reason == reason; }));
}

// Node 0's first RREQ (its sequence number 1, id 1) for `destination`, whose number it does not
// know, with IP TTL `ttl`: the start of a flood to inject at a node by hand.
Rreq first_request_of_node_0(NodeId destination, std::uint8_t ttl) {
  Rreq rreq;
  rreq.originator = 0;
  rreq.originator_seq = 1;
  rreq.id = 1;
  rreq.destination = destination;
  rreq.unknown_seq = true;
  rreq.ttl = ttl;
  return rreq;
}

// A RREP towards node 0 about node 3 (sequence number 5), one hop from its sender, valid 10 s:
// injected at node 1 from node 2, it gives node 1 a two-hop route to node 3 through node 2.
Rrep reply_about_node_3() {
  Rrep rrep;
  rrep.destination = 3;
  rrep.destination_seq = 5;
  rrep.originator = 0;
  rrep.hop_count = 1;
  rrep.lifetime_ms = 10000;
  return rrep;
}

TEST(AodvProtocol, ExpandingRingFindsADestinationFourHopsAwayAtTtlFive) {
  TestNetwork net(line(5), aodv_params({{"enable_hello", false}}), true);
  net.send(0, 4, 1);
  net.run_until(s(2));
  const auto* d = delivery_of(net, 1);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->receiver, 4U);
  EXPECT_EQ(d->hops, 4U);
  // TTL 1 and TTL 3 time out after 2 * 40 ms * (ttl + 2) = 240 and 400 ms; TTL 5 reaches it,
  // each of the 4 RREQ transmissions after a jitter of at most 10 ms.
  const SimTime latency = d->delivered_at - d->sent_at;
  EXPECT_GE(latency, s(0.640));
  EXPECT_LE(latency, s(0.640 + 4 * 0.010 + 0.002));
  EXPECT_EQ(net.count(0, "route_discoveries"), 3U);

  // Forward and reverse routes along the line, with precursors.
  for (NodeId n = 0; n < 4; ++n) {
    const RouteEntry* to_destination = net.valid_route(n, 4);
    ASSERT_NE(to_destination, nullptr) << n;
    EXPECT_EQ(to_destination->next_hop, n + 1);
    EXPECT_EQ(to_destination->hop_count, 4 - n);
    if (n > 0) {
      EXPECT_EQ(to_destination->precursors, std::vector<NodeId>{n - 1}) << n;
    }
  }
  for (NodeId n = 1; n <= 4; ++n) {
    const RouteEntry* to_origin = net.valid_route(n, 0);
    ASSERT_NE(to_origin, nullptr) << n;
    EXPECT_EQ(to_origin->next_hop, n - 1);
    EXPECT_EQ(to_origin->hop_count, n);
  }
  EXPECT_EQ(net.find_loop(), "");
}

TEST(AodvProtocol, IntermediateNodeWithAHelloRouteRepliesAndSendsAGratuitousReply) {
  TestNetwork net(line(5), aodv_params(), true);
  net.send(0, 4, 1);
  net.run_until(s(2));
  const auto* d = delivery_of(net, 1);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->hops, 4U);
  // By the TTL 3 ring (240 ms) node 3 knows node 4 from its HELLOs and answers for it.
  const SimTime latency = d->delivered_at - d->sent_at;
  EXPECT_GE(latency, s(0.240));
  EXPECT_LE(latency, s(0.240 + 3 * 0.010 + 0.002));
  EXPECT_EQ(net.count(0, "route_discoveries"), 2U);
  EXPECT_EQ(net.count(4, "control_rrep"), 0U);  // the destination never replied
  EXPECT_GE(net.count(3, "control_rrep"), 2U);  // the reply and the gratuitous reply
  // The gratuitous RREP gave the destination its route back to the originator.
  const RouteEntry* back = net.valid_route(4, 0);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(back->next_hop, 3U);
  EXPECT_EQ(back->hop_count, 4U);
  // Node 3 replied for a neighbour: it asked node 2 for a RREP-ACK and got it.
  EXPECT_EQ(net.count(2, "control_rrep_ack"), 1U);
  EXPECT_EQ(net.count("blacklisted"), 0U);
}

// Node 0 reaches node 2 through node 1 or node 3 (both two hops).
std::vector<Vec2> diamond() { return {{0, 0}, {100, 0}, {200, 0}, {100, 60}}; }

TEST(AodvProtocol, StaleSequenceNumberDoesNotReplaceAFresherRoute) {
  TestNetwork net(diamond(), aodv_params({{"enable_hello", false}}), true);
  net.send(0, 2, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  const RouteEntry* route = net.valid_route(0, 2);
  ASSERT_NE(route, nullptr);
  const RouteEntry before = *route;
  ASSERT_EQ(before.hop_count, 2U);
  const NodeId other = before.next_hop == 1 ? 3 : 1;

  // An older sequence number loses even with fewer hops.
  Rrep stale;
  stale.destination = 2;
  stale.destination_seq = before.seq - 1;
  stale.originator = 0;
  stale.hop_count = 0;
  stale.lifetime_ms = 10000;
  net.inject(0, stale, other);
  route = net.valid_route(0, 2);
  ASSERT_NE(route, nullptr);
  EXPECT_EQ(route->next_hop, before.next_hop);
  EXPECT_EQ(route->seq, before.seq);
  EXPECT_EQ(route->hop_count, 2U);

  // The same sequence number with more hops loses too.
  Rrep longer = stale;
  longer.destination_seq = before.seq;
  longer.hop_count = 5;
  net.inject(0, longer, other);
  EXPECT_EQ(net.valid_route(0, 2)->next_hop, before.next_hop);

  // The same sequence number with fewer hops wins, and a newer one wins with more hops.
  Rrep shorter = longer;
  shorter.hop_count = 0;
  net.inject(0, shorter, other);
  EXPECT_EQ(net.valid_route(0, 2)->next_hop, other);
  EXPECT_EQ(net.valid_route(0, 2)->hop_count, 1U);
  Rrep newer = longer;
  newer.destination_seq = before.seq + 1;
  newer.hop_count = 3;
  net.inject(0, newer, before.next_hop);
  EXPECT_EQ(net.valid_route(0, 2)->next_hop, before.next_hop);
  EXPECT_EQ(net.valid_route(0, 2)->seq, before.seq + 1);
  EXPECT_EQ(net.valid_route(0, 2)->hop_count, 4U);

  // A RREQ carrying an older originator sequence number does not re-point the reverse route.
  const RouteEntry* reverse = net.valid_route(2, 0);
  ASSERT_NE(reverse, nullptr);
  const NodeId reverse_hop = reverse->next_hop;
  Rreq old;
  old.originator = 0;
  old.originator_seq = reverse->seq - 1;
  old.id = 999;
  old.destination = 7;
  old.ttl = 1;
  net.inject(2, old, reverse_hop == 1 ? 3 : 1);
  EXPECT_EQ(net.valid_route(2, 0)->next_hop, reverse_hop);
}

TEST(AodvProtocol, RerrFromABrokenLinkReachesEveryPrecursorUpstream) {
  TestNetwork net(line(5), aodv_params({{"enable_hello", false}}), true);
  net.send(0, 4, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  const std::uint32_t seq = net.valid_route(0, 4)->seq;

  net.move(4, {400, 500});  // the destination leaves
  net.send(0, 4, 2);
  net.run_for(s(0.1));
  EXPECT_EQ(delivery_of(net, 2), nullptr);
  EXPECT_EQ(net.count(3, "link_failures"), 1U);
  // Node 3 reports the break to its precursor 2, which tells 1, which tells 0.
  for (NodeId n = 1; n <= 3; ++n) EXPECT_EQ(net.count(n, "control_rerr"), 1U) << n;
  EXPECT_EQ(net.count(0, "control_rerr"), 0U);  // the source has no precursors
  for (NodeId n = 0; n <= 2; ++n) {
    const bool heard = std::any_of(
        net.receptions().begin(), net.receptions().end(), [n](const test::Reception& r) {
          return r.receiver == n && r.from == n + 1 && !r.header.empty() && r.header[0] == 3;
        });
    EXPECT_TRUE(heard) << "node " << n << " got no RERR from " << n + 1;
  }
  for (NodeId n = 0; n <= 3; ++n) {
    EXPECT_EQ(net.valid_route(n, 4), nullptr) << n;
    const RouteEntry* to_4 = net.aodv(n).routing_table().entry(4);
    ASSERT_NE(to_4, nullptr);
    EXPECT_EQ(to_4->state, RouteState::invalid);
    EXPECT_EQ(to_4->seq, seq + 1) << n;  // incremented where the link broke
  }
  // Routes that did not use the broken link survive.
  EXPECT_NE(net.valid_route(3, 0), nullptr);

  // A new message finds no route; the discovery gives up and drops it as no_route.
  net.send(0, 4, 3);
  net.run_for(s(15));
  EXPECT_EQ(delivery_of(net, 3), nullptr);
  EXPECT_EQ(drops_with(net, DropReason::no_route), 1U);
  EXPECT_FALSE(net.aodv(0).discovering(4));
  EXPECT_EQ(net.aodv(0).request_queue().size(), 0U);
}

// After a break RFC 3561 (6.11) increments the destination's sequence number, so the next RREQ
// asks for a fresher route than any that existed before the break; ns-3.37 keeps the number, so a
// node still holding an old route of that number answers, and the route it offers may lead into
// the break. Node 3 (a neighbour of 0 and 1 only) holds such a route to 2 through 1, and is not
// a precursor of 1, so no RERR reaches it.
struct StaleReplyOutcome {
  std::uint32_t seq_before = 0;
  std::uint32_t seq_after_break = 0;  // node 0's number for destination 2 after the RERR
  std::uint64_t stale_replies = 0;    // RREPs node 3 sent
  const RouteEntry* route = nullptr;  // node 0's route to 2 after the new discovery
  std::size_t no_route_drops = 0;
};

StaleReplyOutcome reply_after_a_break(TestNetwork& net) {
  StaleReplyOutcome out;
  net.send(0, 2, 1);
  net.run_until(s(1));
  EXPECT_NE(delivery_of(net, 1), nullptr);
  out.seq_before = net.valid_route(0, 2)->seq;
  Rrep old;  // node 3 learns a route to 2 through 1, with the same number
  old.destination = 2;
  old.destination_seq = out.seq_before;
  old.originator = 3;
  old.hop_count = 1;
  old.lifetime_ms = 10000;
  net.inject(3, old, 1);

  net.move(2, {200, 500});  // the destination leaves; node 1's MAC reports the next frame lost
  net.send(0, 2, 2);
  net.run_for(s(0.1));
  EXPECT_EQ(net.valid_route(0, 2), nullptr);
  const RouteEntry* to_2 = net.aodv(0).routing_table().entry(2);
  EXPECT_NE(to_2, nullptr);
  out.seq_after_break = to_2 == nullptr ? 0 : to_2->seq;
  net.send(0, 2, 3);
  net.run_for(s(0.5));
  out.stale_replies = net.count(3, "control_rrep");
  out.route = net.valid_route(0, 2);
  out.no_route_drops = drops_with(net, DropReason::no_route);
  return out;
}

TEST(AodvProtocol, AStaleRouteAnswersAfterABreakOnlyWithNs3sSequenceNumberRule) {
  const std::vector<Vec2> positions{{0, 0}, {100, 0}, {200, 0}, {50, 90}};
  TestNetwork rfc(positions, aodv_params({{"enable_hello", false}}), true);
  const StaleReplyOutcome a = reply_after_a_break(rfc);
  EXPECT_EQ(a.seq_after_break, a.seq_before + 1);
  EXPECT_EQ(a.stale_replies, 0U);
  EXPECT_EQ(a.route, nullptr);  // still searching for a route fresher than the broken one
  EXPECT_EQ(a.no_route_drops, 0U);

  TestNetwork ns3(
      positions, aodv_params({{"enable_hello", false}, {"increment_seqno_on_break", false}}), true);
  const StaleReplyOutcome b = reply_after_a_break(ns3);
  EXPECT_EQ(b.seq_after_break, b.seq_before);
  EXPECT_GE(b.stale_replies, 1U);
  ASSERT_NE(b.route, nullptr);  // a route through node 3 to the robot that left ...
  EXPECT_EQ(b.route->next_hop, 3U);
  EXPECT_EQ(b.no_route_drops, 1U);  // ... where node 1 drops message 3
  EXPECT_EQ(delivery_of(ns3, 3), nullptr);
}

TEST(AodvProtocol, HelloLossBreaksTheLinkWithoutMacFeedback) {
  TestNetwork net(line(3), aodv_params(), false);
  net.send(0, 2, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  net.move(1, {100, 500});  // the relay leaves
  const SimTime left = net.now();
  net.run_until(left + s(0.9));
  EXPECT_NE(net.valid_route(0, 2), nullptr);  // too early to notice
  net.run_until(left + s(4));
  EXPECT_EQ(net.valid_route(0, 2), nullptr);
  EXPECT_EQ(net.count(0, "link_breaks"), 1U);
  EXPECT_EQ(net.count(0, "link_failures"), 0U);
}

// ns-3.37 (Forwarding) refreshes the neighbour entry of the next hop on every forwarded packet:
// without layer-2 feedback a relay does not notice that its next hop has gone while traffic
// flows, and the packets are lost.
TEST(AodvProtocol, ForwardingKeepsTheNextHopAliveAsInNs3) {
  TestNetwork net(line(3), aodv_params(), false);
  std::uint64_t id = 1;
  net.send(0, 2, id++);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  net.move(2, {200, 500});  // the destination leaves
  for (int k = 0; k < 25; ++k) {
    net.send(0, 2, id++);
    net.run_for(s(0.2));
  }
  EXPECT_EQ(net.count(1, "link_breaks"), 0U);
  EXPECT_NE(net.valid_route(1, 2), nullptr);
  EXPECT_EQ(net.deliveries().size(), 1U);
}

TEST(AodvProtocol, RouteIsRepairedThroughAnotherRelayWhenTheMiddleRobotLeaves) {
  std::vector<Vec2> positions = diamond();
  positions[3] = {1000, 1000};  // the spare relay starts far away
  TestNetwork net(positions, aodv_params(), true);
  net.send(0, 2, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  EXPECT_EQ(net.valid_route(0, 2)->next_hop, 1U);

  net.move(1, {100, -900});
  net.move(3, {100, 60});
  std::uint64_t id = 2;
  for (int k = 0; k < 20; ++k) {
    net.send(0, 2, id++);
    net.run_for(s(0.1));
    EXPECT_EQ(net.find_loop(), "");
  }
  net.run_for(s(1));
  const RouteEntry* route = net.valid_route(0, 2);
  ASSERT_NE(route, nullptr);
  EXPECT_EQ(route->next_hop, 3U);
  EXPECT_EQ(route->hop_count, 2U);
  // Only the message in flight when the link broke is lost.
  std::size_t delivered = 0;
  for (std::uint64_t m = 2; m < id; ++m) delivered += delivery_of(net, m) != nullptr ? 1 : 0;
  EXPECT_GE(delivered, 19U);
  EXPECT_EQ(delivery_of(net, 21)->hops, 2U);
}

TEST(AodvProtocol, LocalRepairSavesThePacketAndReportsNoBreakForItsDestination) {
  // 0 - 1 - 2 - 3 on a line; the spare 4 replaces relay 2.
  std::vector<Vec2> positions = line(4);
  positions.emplace_back(1000, 1000);
  TestNetwork net(positions, aodv_params({{"enable_local_repair", true}, {"enable_hello", false}}),
                  true);
  net.send(0, 3, 1);
  net.run_until(s(1.5));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  net.move(2, {200, 900});
  net.move(4, {200, 40});
  net.send(0, 3, 2);
  net.run_for(s(1));
  const auto* d = delivery_of(net, 2);
  ASSERT_NE(d, nullptr) << "the packet that met the break was not repaired";
  EXPECT_EQ(d->hops, 3U);
  EXPECT_EQ(net.count(1, "local_repairs"), 1U);
  // Node 1 reports that node 2 itself is gone, but not destination 3.
  for (const auto& r : net.receptions()) {
    const auto message = decode(r.header);
    if (!message || !std::holds_alternative<Rerr>(*message)) continue;
    for (const auto& d : std::get<Rerr>(*message).destinations) EXPECT_NE(d.destination, 3U);
  }
  EXPECT_EQ(net.valid_route(1, 3)->next_hop, 4U);
  EXPECT_EQ(net.valid_route(0, 3)->next_hop, 1U);  // the source never noticed
}

TEST(AodvProtocol, UnacknowledgedRrepBlacklistsAUnidirectionalLink) {
  TestNetwork net(line(3), aodv_params({{"enable_hello", false}, {"rrep_ack_required", true}}),
                  false);
  net.block(1, 0);  // node 0 hears nobody; node 1 hears node 0
  net.send(0, 2, 1);
  net.run_until(s(0.5));
  EXPECT_EQ(net.count(1, "blacklisted"), 1U);
  const std::uint64_t relayed = net.count(1, "control_rreq");
  net.run_until(s(12));
  EXPECT_EQ(delivery_of(net, 1), nullptr);
  // Later RREQs from node 0 (at least the TTL 3 and 5 rings) are ignored while blacklisted.
  EXPECT_GE(net.count(0, "route_discoveries"), 3U);
  EXPECT_EQ(net.count(1, "control_rreq"), relayed);
  EXPECT_EQ(drops_with(net, DropReason::no_route), 1U);
}

TEST(AodvProtocol, AcknowledgedRrepsBlacklistNobody) {
  TestNetwork net(line(4), aodv_params({{"enable_hello", false}, {"rrep_ack_required", true}}),
                  false);
  net.send(0, 3, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  EXPECT_EQ(net.count("control_rrep_ack"), 3U);  // one per RREP hop
  EXPECT_EQ(net.count("blacklisted"), 0U);
}

// ns-3.37 sets the A flag when an intermediate node answers for its neighbour but never starts
// the RREP-ACK timer, and does not blacklist a neighbour a RREP could not be delivered to.
TEST(AodvProtocol, NeitherAMissingRrepAckNorAnUndeliveredRrepBlacklists) {
  TestNetwork undelivered(line(3), aodv_params({{"enable_hello", false}}), true);
  undelivered.block(2, 1);  // the destination's RREP never reaches the relay
  undelivered.send(0, 2, 1);
  undelivered.run_until(s(1));
  EXPECT_GE(undelivered.count(2, "link_failures"), 1U);
  EXPECT_EQ(undelivered.count("blacklisted"), 0U);

  TestNetwork unacknowledged(line(3), aodv_params(), false);
  unacknowledged.block(0, 1);        // node 0's RREP-ACK never reaches node 1
  unacknowledged.run_until(s(1.5));  // node 1 knows node 2 from its HELLOs
  unacknowledged.inject(1, first_request_of_node_0(2, 3), 0);
  unacknowledged.run_for(s(0.5));
  EXPECT_EQ(unacknowledged.count(1, "control_rrep"), 1U);  // answered for its neighbour, A set
  EXPECT_EQ(unacknowledged.count(0, "control_rrep_ack"), 1U);
  EXPECT_EQ(unacknowledged.count("blacklisted"), 0U);
}

// ns-3.37 routes AODV's unicast control messages through IP, whose route lookup is AODV's own:
// a gratuitous RREP towards a next hop whose own route has expired waits for a RREQ that finds
// that neighbour again.
TEST(AodvProtocol, ControlMessageToANeighbourWithoutARouteWaitsForADiscovery) {
  TestNetwork net(line(4), aodv_params({{"enable_hello", false}}), false);
  net.inject(1, reply_about_node_3(), 2);  // node 1 learns node 3 through node 2, for 10 s
  net.run_until(s(3.5));  // its route to node 2 itself (active_route_timeout) has expired
  ASSERT_NE(net.valid_route(1, 3), nullptr);
  ASSERT_EQ(net.valid_route(1, 2), nullptr);

  Rreq rreq = first_request_of_node_0(3, 5);
  rreq.unknown_seq = false;
  rreq.destination_seq = 5;
  rreq.gratuitous = true;
  net.inject(1, rreq, 0);
  EXPECT_TRUE(net.aodv(1).discovering(2));
  EXPECT_EQ(net.count(1, "route_discoveries"), 1U);
  EXPECT_EQ(net.count(1, "control_rrep"), 1U);  // the reply to node 0 went at once
  net.run_for(s(1));
  EXPECT_NE(net.valid_route(1, 2), nullptr);
  EXPECT_EQ(net.count(1, "control_rrep"), 2U);  // then the gratuitous one to node 2
  const bool gratuitous_heard =
      std::any_of(net.receptions().begin(), net.receptions().end(), [](const test::Reception& r) {
        return r.receiver == 2 && r.from == 1 && !r.header.empty() && r.header[0] == 2 &&
               decode(r.header).has_value() && !std::get<Rrep>(*decode(r.header)).is_hello();
      });
  EXPECT_TRUE(gratuitous_heard);
}

// ns-3.37 (RecvAodv) makes the sender of every AODV message a one-hop route before it looks at
// the message, so a duplicate RREQ, dropped unread, still turns a longer route to its sender
// into a direct one; the neighbour table learns nothing from it.
TEST(AodvProtocol, ADuplicateRreqMakesItsSenderADirectRouteAsInNs3) {
  TestNetwork net(line(4), aodv_params({{"enable_hello", false}}), false);
  net.inject(1, reply_about_node_3(), 2);  // node 1 learns node 3 through node 2
  ASSERT_NE(net.valid_route(1, 3), nullptr);
  ASSERT_EQ(net.valid_route(1, 3)->hop_count, 2U);

  // A flood from node 0, heard first from node 0, then relayed by node 3.
  Rreq rreq = first_request_of_node_0(9, 5);
  net.inject(1, rreq, 0);
  rreq.hop_count = 2;
  net.inject(1, rreq, 3);
  const RouteEntry* to_three_now = net.valid_route(1, 3);
  ASSERT_NE(to_three_now, nullptr);
  EXPECT_EQ(to_three_now->next_hop, 3U);
  EXPECT_EQ(to_three_now->hop_count, 1U);
  EXPECT_EQ(to_three_now->seq, 5U);  // kept (loop freedom: see update_route_to_neighbor)
  EXPECT_FALSE(net.aodv(1).neighbors().is_neighbor(3, net.now()));
  EXPECT_EQ(net.valid_route(1, 0)->next_hop, 0U);  // the duplicate changed no reverse route
}

// ns-3.37 draws its first HELLO in whole milliseconds up to 100 ms and every broadcast jitter in
// whole milliseconds up to 10 ms (UniformRandomVariable::GetInteger), so HELLOs leave on whole
// milliseconds.
TEST(AodvProtocol, HellosLeaveOnWholeMilliseconds) {
  TestNetwork net(line(3), aodv_params(), false);
  net.run_until(s(3.5));
  // Every HELLO has the same airtime, so all are heard at the same offset within a millisecond.
  constexpr std::int64_t kMs = 1'000'000;
  std::optional<std::int64_t> offset;
  std::size_t hellos = 0;
  for (const test::Reception& r : net.receptions()) {
    const std::optional<Message> message = decode(r.header);
    if (!message || !std::holds_alternative<Rrep>(*message)) continue;
    ++hellos;
    if (!offset) offset = r.at.count() % kMs;
    EXPECT_EQ(r.at.count() % kMs, *offset)
        << "HELLO from " << r.from << " heard at " << to_seconds(r.at);
  }
  EXPECT_GE(hellos, 8U);
}

// ns-3.37 notes a broadcast for the HELLO rule only when it sends or relays a RREQ: a node that
// broadcasts a RERR still sends its next HELLO.
TEST(AodvProtocol, ABroadcastRerrDoesNotStandInForAHello) {
  std::vector<Vec2> positions = line(3);
  positions.emplace_back(100, 60);  // node 3, a second precursor of node 1 for node 2
  TestNetwork net(positions, aodv_params(), true);
  net.send(0, 2, 1);
  net.send(3, 2, 2);
  net.run_until(s(1.2));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  ASSERT_NE(delivery_of(net, 2), nullptr);
  ASSERT_EQ(net.valid_route(1, 2)->precursors.size(), 2U);
  net.move(2, {200, 500});
  net.send(0, 2, 3);  // node 1's MAC reports the failure; node 1 broadcasts the RERR
  net.run_for(s(0.1));
  ASSERT_EQ(net.count(1, "control_rerr"), 1U);
  const std::uint64_t hellos = net.count(1, "control_hello");
  net.run_for(s(1.05));  // one HELLO tick later
  EXPECT_EQ(net.count(1, "control_hello"), hellos + 1);
}

// With link_layer_feedback off the MAC's failure reports are counted and otherwise ignored.
TEST(AodvProtocol, MacFailureReportsAreIgnoredWithoutLinkLayerFeedback) {
  TestNetwork net(line(3), aodv_params({{"enable_hello", false}, {"link_layer_feedback", false}}),
                  true);
  net.send(0, 2, 1);
  net.run_until(s(1));
  ASSERT_NE(delivery_of(net, 1), nullptr);
  net.move(2, {200, 500});
  net.send(0, 2, 2);
  net.run_for(s(0.1));
  EXPECT_EQ(net.count(1, "link_failures"), 1U);
  EXPECT_EQ(net.count(1, "link_breaks"), 0U);
  EXPECT_EQ(net.count("control_rerr"), 0U);
  EXPECT_NE(net.valid_route(1, 2), nullptr);
}

TEST(AodvProtocol, BufferIsBoundedAndTimedOut) {
  // Node 1 is out of everyone's reach.
  TestNetwork net({{0, 0}, {500, 500}}, aodv_params({{"max_queue_len", std::int64_t{4}}}), true);
  for (std::uint64_t m = 0; m < 6; ++m) net.send(0, 1, m);
  EXPECT_EQ(drops_with(net, DropReason::queue_full), 2U);
  EXPECT_EQ(net.aodv(0).request_queue().size(), 4U);
  net.run_until(s(20));
  EXPECT_EQ(drops_with(net, DropReason::no_route), 4U);  // given up after the last retry

  TestNetwork timed({{0, 0}, {500, 500}}, aodv_params({{"max_queue_time_s", 0.5}}), true);
  timed.send(0, 1, 0);
  timed.run_until(s(0.6));
  EXPECT_EQ(drops_with(timed, DropReason::buffer_timeout), 1U);
  EXPECT_EQ(timed.aodv(0).request_queue().size(), 0U);
}

TEST(AodvProtocol, DiscoveryGivesUpAfterRreqRetriesAtTheNetworkDiameter) {
  TestNetwork net({{0, 0}, {500, 500}}, aodv_params({{"enable_hello", false}}), true);
  net.send(0, 1, 0);
  // Rings at TTL 1, 3, 5, 7 (240 + 400 + 560 + 720 ms), then TTL 35 twice (2.8 s, 5.6 s).
  net.run_until(s(1.92 + 2.8 + 5.6 - 0.01));
  EXPECT_TRUE(net.aodv(0).discovering(1));
  EXPECT_EQ(net.count(0, "route_discoveries"), 6U);
  net.run_until(s(1.92 + 2.8 + 5.6 + 0.01));
  EXPECT_FALSE(net.aodv(0).discovering(1));
  EXPECT_EQ(drops_with(net, DropReason::no_route), 1U);
  EXPECT_EQ(net.count(0, "control_rreq"), 6U);
}

TEST(AodvProtocol, RreqOriginationIsRateLimited) {
  std::vector<Vec2> positions{{0, 0}};
  for (int i = 0; i < 15; ++i) positions.emplace_back(1000 + 200.0 * i, 1000);
  TestNetwork net(positions, aodv_params({{"enable_hello", false}}), true);
  for (NodeId d = 1; d <= 15; ++d) net.send(0, d, d);
  net.run_until(s(0.999));
  EXPECT_EQ(net.count(0, "route_discoveries"), 10U);
  net.run_until(s(1.01));
  EXPECT_GT(net.count(0, "route_discoveries"), 10U);
  EXPECT_LE(net.count(0, "route_discoveries"), 20U);
}

TEST(AodvProtocol, BroadcastsAreRebroadcastOnceByEveryNode) {
  TestNetwork net(line(5), aodv_params({{"enable_hello", false}}), true);
  net.send(0, kBroadcast, 7);
  net.run_until(s(0.1));
  ASSERT_EQ(net.deliveries().size(), 4U);
  for (const auto& d : net.deliveries()) EXPECT_EQ(d.hops, d.receiver);
  for (NodeId n = 1; n < 5; ++n) EXPECT_EQ(net.count(n, "test_forwards"), 1U) << n;
  EXPECT_GT(net.count("duplicates"), 0U);

  TestNetwork local(line(5), aodv_params({{"enable_hello", false}, {"enable_broadcast", false}}),
                    true);
  local.send(0, kBroadcast, 7);
  local.run_until(s(0.1));
  ASSERT_EQ(local.deliveries().size(), 1U);
  EXPECT_EQ(local.deliveries()[0].receiver, 1U);
}

TEST(AodvProtocol, DataTtlLimitsForwarding) {
  TestNetwork net(line(5), aodv_params({{"data_ttl", std::int64_t{2}}}), true);
  net.send(0, 4, 1);
  net.run_until(s(2));
  EXPECT_EQ(delivery_of(net, 1), nullptr);
  EXPECT_EQ(drops_with(net, DropReason::ttl_expired), 1U);
  EXPECT_EQ(net.drops().front().node, 2U);
}

// Random waypoint over 30 robots: after every 0.1 s step, the union of the route tables must
// hold no loop, with and without link-layer feedback.
void random_mobility_run(bool mac_feedback, std::uint64_t seed) {
  constexpr std::uint32_t kRobots = 30;
  constexpr double kSide = 400.0;
  RandomStream random(seed);
  std::vector<Vec2> positions;
  std::vector<Vec2> targets;
  std::vector<double> speeds;
  for (std::uint32_t i = 0; i < kRobots; ++i) {
    positions.emplace_back(random.uniform(0, kSide), random.uniform(0, kSide));
    targets.emplace_back(random.uniform(0, kSide), random.uniform(0, kSide));
    speeds.push_back(random.uniform(1.0, 20.0));
  }
  TestNetwork net(positions, aodv_params(), mac_feedback, seed);
  std::uint64_t id = 0;
  for (int step = 0; step < 500; ++step) {
    for (std::uint32_t i = 0; i < kRobots; ++i) {
      Vec2 p = net.positions()[i];
      const Vec2 to = targets[i] - p;
      const double stride = speeds[i] * 0.1;
      if (to.norm() <= stride) {
        p = targets[i];
        targets[i] = {random.uniform(0, kSide), random.uniform(0, kSide)};
        speeds[i] = random.uniform(1.0, 20.0);
      } else {
        p += to / to.norm() * stride;
      }
      net.move(i, p);
    }
    for (int k = 0; k < 4; ++k) {
      const auto source = static_cast<NodeId>(random.below(kRobots));
      const auto destination =
          static_cast<NodeId>((source + 1 + random.below(kRobots - 1)) % kRobots);
      net.send(source, destination, id++);
    }
    net.run_for(s(0.1));
    const std::string loop = net.find_loop();
    ASSERT_EQ(loop, "") << "step " << step;
  }
  net.run_for(s(2));
  EXPECT_EQ(net.find_loop(), "");
  const double pdr = static_cast<double>(net.deliveries().size()) / static_cast<double>(id);
  EXPECT_GT(pdr, 0.5) << "delivered " << net.deliveries().size() << " of " << id;
  EXPECT_GT(net.count("control_rerr"), 0U);  // links did break
  for (const auto& d : net.deliveries()) EXPECT_LE(d.hops, kRobots - 1);
}

TEST(AodvProtocol, NoRoutingLoopUnderRandomMobilityWithMacFeedback) {
  random_mobility_run(true, 1);
}
TEST(AodvProtocol, NoRoutingLoopUnderRandomMobilityWithHellosOnly) {
  random_mobility_run(false, 2);
}
TEST(AodvProtocol, NoRoutingLoopUnderRandomMobilityAnotherSeed) { random_mobility_run(true, 3); }

}  // namespace
}  // namespace swarmnet::aodv
