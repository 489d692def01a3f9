// ns-3.37's protocol rules (aodv-routing-protocol.cc) where SwarmNet's default reads RFC 3561
// otherwise, each a parameter of the plugin and each tested both ways, on the SDK test kit (one
// node, node 0 of 10, with a fake routing context). Four control-message rules:
//   rrep_over_invalid_reverse_route  RecvReply forwards a RREP over any route to its originator
//                                    that is not in search, an invalid one included;
//   rrep_ip_ttl                      a RREP's IP TTL is its sender's hop count to the originator,
//                                    and a forwarder drops one that arrives below 2;
//   rerr_to_valid_precursors         SendRerrMessage sends only to precursors with a valid route,
//                                    after 0-10 ms of jitter, and counts only unicast RERRs;
//   queue_released_by_rrep_only      buffered packets leave only on a RREP for this node or when
//                                    the discovery timer fires.
// Three route-update rules:
//   rreq_overwrites_reverse_route    RecvRequest makes the RREQ's sender the next hop to its
//                                    originator whatever the route's freshness, state unchanged;
//   neighbor_route_forgets_seqno     UpdateRouteToNeighbor replaces a neighbour's route that is
//                                    not one hop with a valid number by one with number 0, unknown;
//   reply_seqno_plus_one_only        SendReply increments the number only if the RREQ asks for
//                                    exactly one more.
// And ns-3's IP under AODV's unicast messages:
//   control_via_route_to_neighbor    a RREP, RERR or RREP-ACK to a neighbour takes the route to
//                                    it; a node on the way relays it as IP (TTL, no route), and
//                                    the neighbour takes the IP source for the sender;
//   ip_input_refreshes_routes        IP refreshes the route to a message's sender (and for one
//                                    addressed to this node the way back) before AODV reads it.
// And which routes a broken link or a RERR reports:
//   rerr_covers_routes_in_any_state  SendRerrWhenBreaksLinkToNextHop and RecvError list routes
//                                    through the neighbour in any state, and the neighbour itself.
// And what a RREP does to the route it updates:
//   rrep_replaces_route              RecvReply puts a new entry in the route's place (no
//                                    precursors), and over a route in search for this node.
// And its RREQ rate limit:
//   rate_limited_requests_stack      SendRequest schedules every refused request on its own for
//                                    100 us after the window turns; each packet asks again.
// And what a RREP for this node does to its discovery:
//   rrep_ends_search_only            RecvReply cancels the discovery timer only for a route the
//                                    RREP found in search, and sends the buffer over the route
//                                    whatever its state.
// And when its routes age:
//   lookups_age_all_routes           every route lookup ages the whole table (Purge); no timer
//                                    ages it.
// Why they matter: docs/history/validation-journal.md, "The saturated rows, and ns-3's
// control-message rules", and the sections of the later rules (docs/validation.md lists them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "aodv_one_node.hpp"

namespace swarmnet::aodv {
namespace {

using testing::PacketBuilder;
using testing::ParamOverrides;

class AodvNs3ControlRules : public AodvOneNode {
 protected:
  // `originator`'s RREQ for `destination`, `hops_before` hops old, relayed to this node by
  // `from`: the reverse route to `originator` goes through `from`.
  void rreq(NodeId from, NodeId originator, NodeId destination, std::uint8_t hops_before,
            std::uint32_t id = 1) {
    Rreq rreq;
    rreq.originator = originator;
    rreq.originator_seq = 3;
    rreq.id = id;
    rreq.hop_count = hops_before;
    rreq.destination = destination;
    rreq.unknown_seq = true;
    rreq.gratuitous = true;
    rreq.ttl = 1;  // not relayed further
    hear(rreq, from);
  }
  // A RREP about `destination` (`hops_before` hops behind `from`) on its way to `originator`.
  void rrep(NodeId from, NodeId destination, NodeId originator, std::uint8_t hops_before,
            std::uint8_t ttl = 0) {
    Rrep rrep;
    rrep.destination = destination;
    rrep.destination_seq = 7;
    rrep.originator = originator;
    rrep.hop_count = hops_before;
    rrep.lifetime_ms = 10000;
    rrep.ttl = ttl;
    hear(rrep, from);
  }
  // A RREP for this node about `destination` with number `seq`, `hops_before` hops behind `from`.
  void rrep_for_us(NodeId from, NodeId destination, std::uint32_t seq, std::uint8_t hops_before) {
    Rrep rrep;
    rrep.destination = destination;
    rrep.destination_seq = seq;
    rrep.originator = 0;
    rrep.hop_count = hops_before;
    rrep.lifetime_ms = 10000;
    hear(rrep, from);
  }
  void data_from(NodeId neighbor, NodeId source, NodeId destination, std::uint64_t uid) {
    aodv_->receive(PacketBuilder()
                       .uid(uid)
                       .from(source)
                       .to(destination)
                       .message(uid)
                       .payload_bytes(50)
                       .hops(1)
                       .build(),
                   neighbor);
  }
  static Packet data_to(NodeId destination, std::uint64_t uid) {
    return PacketBuilder().uid(uid).from(0).to(destination).message(uid).payload_bytes(50).build();
  }
  void run(double seconds) { scheduler_.run_for(from_seconds(seconds)); }
  // This node relays 7's discovery for 8: route to 8 via neighbour 6 with precursor 5. Then for
  // `seconds` seconds HELLOs from 6, and from 5 too if `hear_precursor`, keep their links.
  void relay_seven_to_eight(int seconds, bool hear_precursor) {
    rreq(5, 7, 8, 1);
    rrep(6, 8, 7, 1);
    ASSERT_TRUE(route(8)->has_precursor(5));
    for (int second = 1; second <= seconds; ++second) {
      run(1.0);
      hello_from(6, second);
      if (hear_precursor) hello_from(5, second);
    }
  }

  struct Sent {
    Message message;
    NodeId next_hop;
    SimTime at;
  };
  // The control messages of type T handed to the MAC, in order.
  template <typename T>
  [[nodiscard]] std::vector<Sent> sent() const {
    std::vector<Sent> out;
    for (const auto& item : node_.to_mac) {
      if (!item.packet.is_control()) continue;
      const std::optional<Message> message = decode(item.packet.header);
      if (message && std::holds_alternative<T>(*message)) {
        out.push_back({*message, item.next_hop, item.at});
      }
    }
    return out;
  }
  // RREPs (HELLOs left out) handed to the MAC.
  [[nodiscard]] std::vector<std::pair<Rrep, NodeId>> replies() const {
    std::vector<std::pair<Rrep, NodeId>> out;
    for (const Sent& s : sent<Rrep>()) {
      const Rrep& rrep = std::get<Rrep>(s.message);
      if (!rrep.is_hello()) out.emplace_back(rrep, s.next_hop);
    }
    return out;
  }
  // RERRs that report `destination`.
  [[nodiscard]] std::vector<Sent> errors_about(NodeId destination) const {
    std::vector<Sent> out;
    for (const Sent& s : sent<Rerr>()) {
      const auto& list = std::get<Rerr>(s.message).destinations;
      if (std::any_of(list.begin(), list.end(),
                      [&](const auto& d) { return d.destination == destination; })) {
        out.push_back(s);
      }
    }
    return out;
  }
  // RREQs this node originated for `destination`.
  [[nodiscard]] std::size_t requests_for(NodeId destination) const {
    std::size_t n = 0;
    for (const Sent& s : sent<Rreq>()) {
      const Rreq& r = std::get<Rreq>(s.message);
      if (r.originator == 0 && r.destination == destination) ++n;
    }
    return n;
  }
  // Data packets handed to the MAC, by uid, in order.
  [[nodiscard]] std::vector<std::uint64_t> data_sent() const {
    std::vector<std::uint64_t> uids;
    for (const auto& item : node_.to_mac) {
      if (!item.packet.is_control()) uids.push_back(item.packet.uid);
    }
    return uids;
  }
  [[nodiscard]] const RouteEntry* route(NodeId destination) const {
    return aodv_->routing_table().entry(destination);
  }
};

// A rule's suite, run with ns-3.37's reading (the parameter true) and RFC 3561's (false).
class BothReadings : public AodvNs3ControlRules, public ::testing::WithParamInterface<bool> {
 protected:
  // The node with `rule` at the reading under test, and `also` as given.
  void make_with(const std::string& rule, ParamOverrides also = {}) {
    also[rule] = GetParam();
    make(also);
  }
};

std::string reading_name(const ::testing::TestParamInfo<bool>& info) {
  return info.param ? "ns3" : "rfc";
}

// ---- rrep_over_invalid_reverse_route -------------------------------------------------------

// The reverse route to 7 (through neighbour 5) has expired; HELLOs keep the route to 5 itself
// valid. A RREP for 7 then arrives from 6.
class RrepOverInvalidReverseRoute : public BothReadings {
 protected:
  void expire_reverse_route() {
    make_with("rrep_over_invalid_reverse_route");
    rreq(5, 7, 8, 1);  // reverse route to 7 via 5, 2 hops, for 5.44 s
    for (int second = 1; second <= 6; ++second) {
      run(1.0);
      hello_from(5, second);
      hello_from(6, second);
    }
    run(0.5);  // past the housekeeping purge at 6 s, which ages the route (5.44 s)
    ASSERT_NE(route(7), nullptr);
    ASSERT_EQ(route(7)->state, RouteState::invalid);
    ASSERT_TRUE(route(5)->is_valid());
  }
};

TEST_P(RrepOverInvalidReverseRoute, DecidesWhetherARrepTravelsOverAnInvalidReverseRoute) {
  expire_reverse_route();
  const SimTime expires_before = route(7)->expires;
  rrep(6, 8, 7, 1);
  const bool ns3 = GetParam();
  ASSERT_EQ(replies().size(), ns3 ? 1U : 0U);
  if (ns3) {
    EXPECT_EQ(replies().front().second, 5U);          // the invalid route's next hop
    EXPECT_EQ(route(7)->state, RouteState::invalid);  // it stays invalid, living longer
    EXPECT_EQ(route(7)->expires, std::max(expires_before, scheduler_.now() + from_seconds(3.0)));
  }
  EXPECT_TRUE(route(8)->is_valid());  // the forward route is learned either way
}

TEST_P(RrepOverInvalidReverseRoute, NeverTravelsOverARouteInSearch) {
  expire_reverse_route();
  aodv_->send(data_to(7, 900));  // a discovery for 7: the route is in search
  ASSERT_EQ(route(7)->state, RouteState::in_search);
  rrep(6, 8, 7, 1);
  EXPECT_TRUE(replies().empty());
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RrepOverInvalidReverseRoute, ::testing::Bool(), reading_name);

// ---- rrep_ip_ttl --------------------------------------------------------------------------

TEST_F(AodvNs3ControlRules, ADestinationsRrepCarriesItsHopCountToTheOriginatorAsTtl) {
  make(ParamOverrides{{"rrep_ip_ttl", true}});
  rreq(5, 7, 0, 2);  // 7's RREQ for this node, 3 hops from 7
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().front().first.ttl, 3U);
  EXPECT_EQ(replies().front().second, 5U);
}

TEST_F(AodvNs3ControlRules, AnIntermediateRrepAndItsGratuitousRrepCarryTheirHopCounts) {
  make(ParamOverrides{{"rrep_ip_ttl", true}});
  rrep(6, 8, 0, 1);  // a route to 8 through 6: 2 hops
  rreq(5, 7, 8, 2);  // 7's RREQ for 8 (gratuitous flag set), 3 hops from 7
  const auto out = replies();
  ASSERT_EQ(out.size(), 2U);
  EXPECT_EQ(out[0].second, 5U);  // to the originator: its hop count to 7
  EXPECT_EQ(out[0].first.ttl, 3U);
  EXPECT_EQ(out[1].second, 6U);  // the gratuitous RREP to 8: the hop count to 8
  EXPECT_EQ(out[1].first.ttl, 2U);
}

TEST_F(AodvNs3ControlRules, AForwarderTakesOneOffTheTtlAndDropsARrepBelowTwo) {
  make(ParamOverrides{{"rrep_ip_ttl", true}});
  rreq(5, 7, 8, 1);  // reverse route to 7 via 5
  rrep(6, 8, 7, 1, 2);
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().front().first.ttl, 1U);
  rrep(6, 9, 7, 1, 1);  // arrives with TTL 1: the routes are learned, the RREP goes no further
  EXPECT_EQ(replies().size(), 1U);
  EXPECT_EQ(node_.counter("rrep_ttl_drops"), 1U);
  EXPECT_TRUE(route(9)->is_valid());
  EXPECT_TRUE(route(9)->has_precursor(5));
}

TEST_F(AodvNs3ControlRules, ByDefaultARrepHasNoTtlAndTravelsToItsOriginator) {
  make();
  rreq(5, 7, 0, 2);
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().front().first.ttl, 0U);
  rreq(5, 7, 8, 1, 2);
  rrep(6, 8, 7, 1, 1);  // a TTL means nothing here
  EXPECT_EQ(replies().size(), 2U);
  EXPECT_EQ(node_.counter("rrep_ttl_drops"), 0U);
}

// ---- rerr_to_valid_precursors -------------------------------------------------------------

// This node relays 7's flow to 8: route to 8 via 6 with precursor 5. The link to 6 breaks.
class RerrToValidPrecursors : public BothReadings {
 protected:
  void relay_then_break(bool precursor_route_valid) {
    make_with("rerr_to_valid_precursors");
    // 5 is heard from only while `precursor_route_valid`.
    relay_seven_to_eight(4, precursor_route_valid);
    ASSERT_TRUE(route(8)->is_valid());
    ASSERT_EQ(route(5) != nullptr && route(5)->is_valid(), precursor_route_valid);
    broke_at_ = scheduler_.now();
    aodv_->link_failed(data_to(8, 901), 6);
    ASSERT_FALSE(route(8)->is_valid());
  }
  SimTime broke_at_{};
};

TEST_P(RerrToValidPrecursors, AValidPrecursorGetsTheRerrAtOnceOrAfterJitter) {
  relay_then_break(true);
  const bool ns3 = GetParam();
  EXPECT_EQ(errors_about(8).size(), ns3 ? 0U : 1U);  // ns-3 waits 0-10 ms
  run(0.011);
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_EQ(errors.front().next_hop, 5U);  // unicast to the single precursor
  EXPECT_LE(errors.front().at - broke_at_, from_seconds(0.010));
  if (!ns3) {
    EXPECT_EQ(errors.front().at, broke_at_);
  }
}

TEST_P(RerrToValidPrecursors, APrecursorWithoutAValidRouteGetsNoneOrIsSearchedFor) {
  relay_then_break(false);
  run(0.011);
  const bool ns3 = GetParam();
  EXPECT_TRUE(errors_about(8).empty());  // no route to 5 either way
  // SwarmNet buffers the RERR and searches for 5; ns-3 sends nothing at all.
  EXPECT_EQ(requests_for(5), ns3 ? 0U : 1U);
  EXPECT_EQ(aodv_->request_queue().has(5), !ns3);
}

TEST_P(RerrToValidPrecursors, OnlyUnicastRerrsCountTowardTheRateLimit) {
  make_with("rerr_to_valid_precursors");
  // Data of 7 for 9 reaches this node, which has no route to 9 and none back to 7: each packet
  // is dropped and answered by a broadcast RERR, 12 of them within one second.
  for (std::uint64_t uid = 1; uid <= 12; ++uid) data_from(5, 7, 9, 100 + uid);
  run(0.011);
  EXPECT_EQ(node_.dropped.size(), 12U);
  EXPECT_EQ(errors_about(9).size(), GetParam() ? 12U : 10U);  // rerr_rate_limit 10
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RerrToValidPrecursors, ::testing::Bool(), reading_name);

// ---- queue_released_by_rrep_only ----------------------------------------------------------

class QueueReleasedByRrepOnly : public BothReadings {
 protected:
  void make_rule() { make_with("queue_released_by_rrep_only"); }
};

TEST_P(QueueReleasedByRrepOnly, AHelloEndsTheDiscoveryOrNewPacketsOvertakeTheBuffer) {
  make_rule();
  aodv_->send(data_to(5, 1));  // no route to 5: buffered, a RREQ (ring timeout 240 ms)
  ASSERT_TRUE(aodv_->discovering(5));
  run(0.05);
  hello_from(5);  // the route to 5 is valid now
  aodv_->send(data_to(5, 2));
  if (!GetParam()) {
    EXPECT_FALSE(aodv_->discovering(5));
    EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{1, 2}));  // the buffer went at once
    return;
  }
  EXPECT_TRUE(aodv_->discovering(5));                       // the timer still runs
  EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{2}));  // the new packet overtook
  EXPECT_TRUE(aodv_->request_queue().has(5));
  run(0.25);  // the discovery timer fires with a valid route: the buffer leaves
  EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{2, 1}));
  EXPECT_FALSE(aodv_->discovering(5));
  EXPECT_EQ(requests_for(5), 1U);  // no second ring
}

TEST_P(QueueReleasedByRrepOnly, ARrepForThisNodeSendsTheBufferEitherWay) {
  make_rule();
  aodv_->send(data_to(8, 1));
  aodv_->send(data_to(8, 2));
  run(0.05);
  rrep(6, 8, 0, 1);
  EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{1, 2}));
  EXPECT_FALSE(aodv_->discovering(8));
}

TEST_P(QueueReleasedByRrepOnly, ARreqFromTheDestinationReleasesTheBufferOnlyByDefault) {
  make_rule();
  aodv_->send(data_to(7, 1));
  run(0.05);
  rreq(5, 7, 8, 1);  // 7's own RREQ (for 8) gives a valid route to 7 through 5
  ASSERT_TRUE(route(7)->is_valid());
  EXPECT_EQ(data_sent().size(), GetParam() ? 0U : 1U);
  run(0.25);
  EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{1}));
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, QueueReleasedByRrepOnly, ::testing::Bool(), reading_name);

// ---- rreq_overwrites_reverse_route ----------------------------------------------------------

class RreqOverwritesReverseRoute : public BothReadings {
 protected:
  void make_rule() { make_with("rreq_overwrites_reverse_route"); }
};

TEST_P(RreqOverwritesReverseRoute, ALongerPathWithTheSameNumberReplacesTheReverseRouteOrNot) {
  make_rule();
  rreq(5, 7, 8, 1);  // 7's RREQ (number 3) through 5: 2 hops
  ASSERT_EQ(route(7)->next_hop, 5U);
  rreq(6, 7, 9, 3, 2);  // 7's next RREQ, same number, through 6: 4 hops
  const bool ns3 = GetParam();
  EXPECT_EQ(route(7)->next_hop, ns3 ? 6U : 5U);
  EXPECT_EQ(route(7)->hop_count, ns3 ? 4U : 2U);
  EXPECT_TRUE(route(7)->is_valid());
}

TEST_P(RreqOverwritesReverseRoute, AnInvalidReverseRouteStaysInvalidAndIsAnsweredOverAnyway) {
  // The expired route keeps its number (ns-3's rule, as the grid runs it), so that the RREQ's
  // equal number is fresh enough for RFC 3561 too.
  make_with("rreq_overwrites_reverse_route", {{"increment_seqno_on_break", false}});
  rreq(5, 7, 8, 1);  // reverse route to 7 via 5, for 5.44 s
  for (int second = 1; second <= 6; ++second) {
    run(1.0);
    hello_from(5, second);
    hello_from(6, second);
  }
  run(0.5);  // past the housekeeping purge at 6 s
  ASSERT_EQ(route(7)->state, RouteState::invalid);
  rreq(6, 7, 0, 2, 2);  // 7's RREQ for this node, same number, through 6: 3 hops
  const bool ns3 = GetParam();
  // RFC 3561 6.2: an equal number makes an invalid route valid again; ns-3 changes only the
  // next hop and the hop count, and answers over the route all the same.
  EXPECT_EQ(route(7)->state, ns3 ? RouteState::invalid : RouteState::valid);
  EXPECT_EQ(route(7)->next_hop, 6U);
  EXPECT_EQ(route(7)->hop_count, 3U);
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().front().second, 6U);
  EXPECT_EQ(replies().front().first.destination, 0U);
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RreqOverwritesReverseRoute, ::testing::Bool(), reading_name);

// ---- neighbor_route_forgets_seqno -----------------------------------------------------------

class NeighborRouteForgetsSeqno : public BothReadings {
 protected:
  void make_rule() { make_with("neighbor_route_forgets_seqno"); }
  // Any AODV message from `neighbor`: a RERR about a node this one has no route to.
  void message_from(NodeId neighbor) {
    Rerr rerr;
    rerr.destinations.push_back({9, 1});
    hear(rerr, neighbor);
  }
};

TEST_P(NeighborRouteForgetsSeqno, AMultiHopRouteToTheSenderBecomesOneHopWithOrWithoutItsNumber) {
  make_rule();
  rreq(4, 7, 5, 1);  // 7 looks for 5 through 4
  rrep(6, 5, 7, 1);  // 5 answers (number 7) through 6: route to 5 via 6, 2 hops, precursor 4
  ASSERT_EQ(route(5)->hop_count, 2U);
  ASSERT_TRUE(route(5)->has_precursor(4));
  message_from(5);  // 5 is heard directly
  const bool ns3 = GetParam();
  EXPECT_TRUE(route(5)->is_valid());
  EXPECT_EQ(route(5)->next_hop, 5U);
  EXPECT_EQ(route(5)->hop_count, 1U);
  EXPECT_EQ(route(5)->valid_seq, !ns3);
  EXPECT_EQ(route(5)->seq, ns3 ? 0U : 7U);
  EXPECT_EQ(route(5)->has_precursor(4), !ns3);
  // With the number forgotten any RREP for 5 replaces the direct route, a longer one included
  // (how ns-3's routes can loop); with it kept, an equal number needs fewer hops.
  rrep(6, 5, 0, 1);
  EXPECT_EQ(route(5)->next_hop, ns3 ? 6U : 5U);
  EXPECT_EQ(route(5)->hop_count, ns3 ? 2U : 1U);
}

TEST_P(NeighborRouteForgetsSeqno, AnInvalidOneHopRouteWithANumberStaysInvalid) {
  make_rule();
  hello_from(5, 4);  // a one-hop route to 5, number 4, for 2 s
  run(3.5);          // expired by the housekeeping purge
  ASSERT_EQ(route(5)->state, RouteState::invalid);
  ASSERT_TRUE(route(5)->valid_seq);
  const std::uint32_t seq = route(5)->seq;
  const SimTime expires = route(5)->expires;
  message_from(5);
  const bool ns3 = GetParam();
  // ns-3.37 updates a copy of such a route and drops it: the route stays as it was.
  EXPECT_EQ(route(5)->state, ns3 ? RouteState::invalid : RouteState::valid);
  EXPECT_EQ(route(5)->seq, seq);
  EXPECT_TRUE(route(5)->valid_seq);
  if (ns3) {
    EXPECT_EQ(route(5)->expires, expires);
  }
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, NeighborRouteForgetsSeqno, ::testing::Bool(), reading_name);

// ---- reply_seqno_plus_one_only --------------------------------------------------------------

class ReplySeqnoPlusOneOnly : public BothReadings {
 protected:
  // 7's RREQ for this node through neighbour 5, asking for number `wanted`.
  void asked_for(std::uint32_t wanted, std::uint32_t id) {
    Rreq rreq;
    rreq.originator = 7;
    rreq.originator_seq = 3 + id;
    rreq.id = id;
    rreq.hop_count = 1;
    rreq.destination = 0;
    rreq.destination_seq = wanted;
    rreq.ttl = 1;
    hear(rreq, 5);
  }
};

TEST_P(ReplySeqnoPlusOneOnly, ADestinationAnswersWithTheNumberAskedForOrOnlyOneMore) {
  make_with("reply_seqno_plus_one_only");
  const std::uint32_t own = aodv_->sequence_number();
  asked_for(own + 1, 1);  // exactly one more: both readings increment
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().back().first.destination_seq, own + 1);
  asked_for(own + 5, 2);  // four more than that
  ASSERT_EQ(replies().size(), 2U);
  const bool ns3 = GetParam();
  EXPECT_EQ(replies().back().first.destination_seq, ns3 ? own + 1 : own + 5);
  EXPECT_EQ(aodv_->sequence_number(), ns3 ? own + 1 : own + 5);
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, ReplySeqnoPlusOneOnly, ::testing::Bool(), reading_name);

// ---- control_via_route_to_neighbor ----------------------------------------------------------

class ControlViaRouteToNeighbor : public BothReadings {
 protected:
  void make_rule() { make_with("control_via_route_to_neighbor", {{"rrep_ip_ttl", true}}); }
  // A unicast AODV message that `source` sent to `destination`, handed over by link sender
  // `from` after one link.
  void unicast(const Message& message, NodeId source, NodeId destination, NodeId from,
               std::uint32_t hops = 1) {
    Packet packet =
        PacketBuilder().uid(next_uid_++).from(source).to(destination).hops(hops).build();
    encode(message, packet.header);
    aodv_->receive(std::move(packet), from);
  }
  static Rrep rrep_about(NodeId destination, NodeId originator, std::uint8_t ttl) {
    Rrep rrep;
    rrep.destination = destination;
    rrep.destination_seq = 7;
    rrep.originator = originator;
    rrep.hop_count = 1;
    rrep.lifetime_ms = 10000;
    rrep.ttl = ttl;
    return rrep;
  }
};

TEST_P(ControlViaRouteToNeighbor, ARerrToAPrecursorTakesTheRouteToItOrGoesStraightToIt) {
  make_rule();
  rreq(5, 7, 8, 1);  // 7 looks for 8 through neighbour 5
  rrep(6, 8, 7, 1);  // 8 answers through 6: route to 8 via 6 with precursor 5
  rrep(4, 5, 0, 2);  // a RREP about 5 through 4 replaces the direct route to 5: 3 hops
  ASSERT_EQ(route(5)->next_hop, 4U);
  hello_from(6);  // 6 is a neighbour, so its link can break
  aodv_->link_failed(data_to(8, 901), 6);
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_EQ(errors.front().next_hop, GetParam() ? 4U : 5U);
  const auto it = std::find_if(node_.to_mac.begin(), node_.to_mac.end(), [](const auto& item) {
    return item.packet.is_control() && decode(item.packet.header) &&
           std::holds_alternative<Rerr>(*decode(item.packet.header));
  });
  ASSERT_NE(it, node_.to_mac.end());
  EXPECT_EQ(it->packet.destination, 5U);  // for the precursor either way
}

TEST_P(ControlViaRouteToNeighbor, TheReceiverTakesTheIpSourceOrTheLinkSenderForTheSender) {
  make_rule();
  unicast(rrep_about(8, 0, 3), 7, 0, 4);  // 7's RREP about 8 for this node, relayed by 4
  const NodeId sender = GetParam() ? 7U : 4U;
  ASSERT_NE(route(8), nullptr);
  EXPECT_EQ(route(8)->next_hop, sender);
  ASSERT_NE(route(sender), nullptr);
  EXPECT_EQ(route(sender)->hop_count, 1U);  // believed a neighbour
  EXPECT_EQ(route(GetParam() ? 4U : 7U), nullptr);
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, ControlViaRouteToNeighbor, ::testing::Bool(), reading_name);

class ControlRelayedByIp : public ControlViaRouteToNeighbor {};

TEST_P(ControlRelayedByIp, ARrepForAnotherNodeIsRelayedAlongItsRouteWithOneTtlLess) {
  make_rule();
  rrep(6, 5, 0, 1);                       // route to 5 via 6
  unicast(rrep_about(8, 5, 3), 7, 5, 4);  // 7's RREP for neighbour 5, relayed here by 4
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(replies().front().second, 6U);
  EXPECT_EQ(replies().front().first.ttl, 2U);
  EXPECT_EQ(replies().front().first.destination, 8U);
  EXPECT_EQ(node_.to_mac.back().packet.source, 7U);
  EXPECT_EQ(node_.to_mac.back().packet.destination, 5U);
  EXPECT_EQ(node_.forwarded.size(), 1U);
  EXPECT_EQ(node_.counter("control_rrep"), 1U);
  EXPECT_EQ(route(8), nullptr);  // the relay does not read it
  EXPECT_EQ(route(7), nullptr);
}

TEST_P(ControlRelayedByIp, TheRelayKeepsTheRouteItUsesAlive) {
  make_rule();
  rrep(6, 5, 0, 1);  // route to 5 via 6, for 10 s (the RREP's lifetime)
  run(8.0);
  hello_from(6, 8);
  unicast(rrep_about(8, 5, 3), 7, 5, 4);
  ASSERT_EQ(replies().size(), 1U);
  EXPECT_EQ(route(5)->expires, scheduler_.now() + from_seconds(3.0));  // past its 10 s
  EXPECT_GE(route(6)->expires, scheduler_.now() + from_seconds(3.0));
}

TEST_P(ControlRelayedByIp, OurOwnDatagramComingBackIsDiscardedSilently) {
  make_rule();
  rrep(6, 5, 0, 1);
  unicast(rrep_about(8, 5, 3), 0, 5, 4);  // this node's own RREP for 5, handed back by 4
  EXPECT_TRUE(node_.to_mac.empty());
  EXPECT_TRUE(node_.dropped.empty());
}

TEST_P(ControlRelayedByIp, WithoutRrepIpTtlARrepLivesForDataTtlLinks) {
  make(ParamOverrides{{"control_via_route_to_neighbor", true}, {"data_ttl", 3}});
  rrep(6, 5, 0, 1);
  unicast(rrep_about(8, 5, 0), 7, 5, 4, 2);  // two links so far: one relay left
  EXPECT_EQ(replies().size(), 1U);
  unicast(rrep_about(8, 5, 0), 7, 5, 4, 3);  // three: its TTL of 3 is used up here
  EXPECT_EQ(replies().size(), 1U);
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped.back().reason, DropReason::ttl_expired);
}

TEST_P(ControlRelayedByIp, ARerrDiesAtTheRelayAndAPacketWithoutARouteIsReported) {
  make_rule();
  rrep(6, 5, 0, 1);
  Rerr rerr;
  rerr.destinations.push_back({9, 1});
  unicast(rerr, 7, 5, 4);  // a RERR's IP TTL is 1
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped.back().reason, DropReason::ttl_expired);
  EXPECT_TRUE(node_.to_mac.empty());
  unicast(rrep_about(8, 3, 4), 7, 3, 4);  // for 3: no route
  ASSERT_EQ(node_.dropped.size(), 2U);
  EXPECT_EQ(node_.dropped.back().reason, DropReason::no_route);
  run(0.011);
  const auto errors = errors_about(3);  // broadcast: no route back to 7 either
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_EQ(errors.front().next_hop, kBroadcast);
}

INSTANTIATE_TEST_SUITE_P(Ns3, ControlRelayedByIp, ::testing::Values(true),
                         [](const auto&) { return "ns3"; });

// ---- ip_input_refreshes_routes ---------------------------------------------------------------

// A neighbour's route that AODV itself leaves alone (neighbor_route_forgets_seqno, as ns-3.37's
// UpdateRouteToNeighbor does) lives on only if IP refreshes it.
class IpInputRefreshesRoutes : public BothReadings {
 protected:
  void make_rule() {
    make_with("ip_input_refreshes_routes",
              {{"neighbor_route_forgets_seqno", true}, {"control_via_route_to_neighbor", true}});
  }
  void rerr_from(NodeId source, NodeId destination, NodeId from) {
    Rerr rerr;
    rerr.destinations.push_back({9, 1});
    Packet packet = PacketBuilder().uid(next_uid_++).from(source).to(destination).hops(1).build();
    encode(Message{rerr}, packet.header);
    aodv_->receive(std::move(packet), from);
  }
};

TEST_P(IpInputRefreshesRoutes, ABroadcastRefreshesTheRouteToItsSenderOrNot) {
  make_rule();
  hello_from(5, 4);  // a one-hop route to 5 with a number, for 2 s
  const SimTime expires = route(5)->expires;
  run(1.5);
  rerr_from(5, kBroadcast, 5);
  EXPECT_EQ(route(5)->expires, GetParam() ? scheduler_.now() + from_seconds(3.0) : expires);
}

TEST_P(IpInputRefreshesRoutes, AMessageForThisNodeRefreshesTheWayBackOrNot) {
  make_rule();
  rreq(5, 7, 8, 1);  // reverse route to 7 via 5; the route to 5: one hop, 3 s
  hello_from(5, 4);
  run(1.5);
  const SimTime to_neighbor = route(5)->expires;
  rerr_from(7, 0, 5);  // 7's RERR for this node, relayed by 5
  EXPECT_EQ(route(5)->expires,
            GetParam() ? std::max(to_neighbor, scheduler_.now() + from_seconds(3.0)) : to_neighbor);
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, IpInputRefreshesRoutes, ::testing::Bool(), reading_name);

// ---- rerr_covers_routes_in_any_state ----------------------------------------------------------

// This node relayed 7's route discovery for 8: route to 8 via neighbour 6 with precursor 5, and
// 5 a neighbour too. HELLOs from 5 and 6 keep their links while the route to 8 may expire.
class RerrCoversRoutesInAnyState : public BothReadings {
 protected:
  void relay_for_seconds(int seconds) {
    make_with("rerr_covers_routes_in_any_state");
    relay_seven_to_eight(seconds, true);
  }
  void break_link_to(NodeId neighbor) { aodv_->link_failed(data_to(neighbor, 901), neighbor); }
  // `from`'s RERR for this node listing `destination` with sequence number `seq`.
  void rerr_from(NodeId from, NodeId destination, std::uint32_t seq) {
    Rerr rerr;
    rerr.destinations.push_back({destination, seq});
    hear(rerr, from);
  }
};

TEST_P(RerrCoversRoutesInAnyState, ABrokenLinkReportsAnInvalidRouteThroughItOrNot) {
  relay_for_seconds(11);  // the route to 8 (10 s) has expired; its entry is kept
  ASSERT_EQ(route(8)->state, RouteState::invalid);
  ASSERT_EQ(route(8)->next_hop, 6U);
  break_link_to(6);
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), GetParam() ? 1U : 0U);
  if (GetParam()) {
    EXPECT_EQ(errors.front().next_hop, 5U);  // to the invalid route's precursor
    const auto& listed = std::get<Rerr>(errors.front().message).destinations;
    ASSERT_EQ(listed.size(), 2U);  // 6 itself and 8, by address
    EXPECT_EQ(listed[0].destination, 6U);
    EXPECT_EQ(listed[1].destination, 8U);
  }
  EXPECT_FALSE(route(6)->is_valid());           // the link's own route is invalidated either way
  EXPECT_EQ(node_.counter("link_breaks"), 1U);  // it ended a valid route: 6's
}

TEST_P(RerrCoversRoutesInAnyState, ARouteInSearchIsReportedAndStaysInSearch) {
  relay_for_seconds(11);
  aodv_->send(data_to(8, 902));  // this node's own packet for 8 starts a search for it
  ASSERT_EQ(route(8)->state, RouteState::in_search);
  ASSERT_EQ(route(8)->next_hop, 6U);  // the search keeps the old next hop
  break_link_to(6);
  EXPECT_EQ(errors_about(8).size(), GetParam() ? 1U : 0U);
  EXPECT_EQ(route(8)->state, RouteState::in_search);
}

TEST_P(RerrCoversRoutesInAnyState, TheNeighbourIsReportedWhereverItsRouteLeads) {
  relay_for_seconds(2);
  rrep(4, 6, 0, 2);  // a RREP about 6 through 4 replaces the direct route: 3 hops
  ASSERT_EQ(route(6)->next_hop, 4U);
  ASSERT_TRUE(route(8)->is_valid());
  break_link_to(6);                    // 6 is still a neighbour: its link breaks
  EXPECT_FALSE(route(8)->is_valid());  // the valid route through 6, either way
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), 1U);
  const auto& listed = std::get<Rerr>(errors.front().message).destinations;
  // ns-3 reports 6 and invalidates its route through 4; RFC 3561 leaves that route alone.
  EXPECT_EQ(listed.size(), GetParam() ? 2U : 1U);
  EXPECT_EQ(route(6)->is_valid(), !GetParam());
}

TEST_P(RerrCoversRoutesInAnyState, ARerrAboutAnInvalidRouteIsRelayedWithItsNumberOrNot) {
  relay_for_seconds(11);
  ASSERT_EQ(route(8)->state, RouteState::invalid);
  rerr_from(6, 8, 3);  // an older number than the route's 7
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), GetParam() ? 1U : 0U);
  if (GetParam()) {
    EXPECT_EQ(errors.front().next_hop, 5U);
    EXPECT_EQ(std::get<Rerr>(errors.front().message).destinations.front().seq, 3U);
  }
}

TEST_P(RerrCoversRoutesInAnyState, ARerrAboutAValidRouteIsRelayedEitherWay) {
  relay_for_seconds(2);
  ASSERT_TRUE(route(8)->is_valid());
  rerr_from(6, 8, 3);
  const auto errors = errors_about(8);
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_EQ(errors.front().next_hop, 5U);
  EXPECT_FALSE(route(8)->is_valid());
  // ns-3 relays the number it was given; RFC 3561 the route's own.
  EXPECT_EQ(std::get<Rerr>(errors.front().message).destinations.front().seq,
            GetParam() ? 3U : route(8)->seq);
}

TEST_P(RerrCoversRoutesInAnyState, ARerrFromAnotherNeighbourChangesNothing) {
  relay_for_seconds(2);
  rerr_from(5, 8, 9);  // 5 is not the next hop to 8
  EXPECT_TRUE(errors_about(8).empty());
  EXPECT_TRUE(route(8)->is_valid());
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RerrCoversRoutesInAnyState, ::testing::Bool(), reading_name);

// ---- rrep_replaces_route ------------------------------------------------------------------------

using RrepReplacesRoute = BothReadings;

TEST_P(RrepReplacesRoute, AFresherRrepForgetsTheRoutesPrecursorsOrKeepsThem) {
  make_with("rrep_replaces_route");
  rreq(5, 7, 8, 1);  // this node relays 7's discovery for 8: route to 8 via 6, precursor 5
  rrep(6, 8, 7, 1);
  hello_from(5);
  ASSERT_TRUE(route(8)->has_precursor(5));
  rrep_for_us(4, 8, 9, 1);  // a fresher route to 8, through 4
  ASSERT_EQ(route(8)->next_hop, 4U);
  EXPECT_EQ(route(8)->has_precursor(5), !GetParam());
  hello_from(4);
  aodv_->link_failed(data_to(8, 901), 4);  // the new route breaks
  EXPECT_FALSE(route(8)->is_valid());
  // RFC 3561 still tells 5, which had relied on the old route; ns-3 tells nobody.
  EXPECT_EQ(errors_about(8).size(), GetParam() ? 0U : 1U);
}

TEST_P(RrepReplacesRoute, ARrepForThisNodeTakesARouteInSearchFresherOrNot) {
  make_with("rrep_replaces_route");
  rrep_for_us(6, 8, 7, 1);  // route to 8 via 6, number 7, for 10 s
  run(11.0);
  ASSERT_EQ(route(8)->state, RouteState::invalid);
  aodv_->send(data_to(8, 902));  // a search for 8 starts; the packet waits
  ASSERT_EQ(route(8)->state, RouteState::in_search);
  ASSERT_EQ(route(8)->seq, 8U);  // the expired route's number went up
  rrep_for_us(4, 8, 7, 1);       // an older number than the route's
  EXPECT_EQ(route(8)->is_valid(), GetParam());
  EXPECT_EQ(data_sent().size(), GetParam() ? 1U : 0U);
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RrepReplacesRoute, ::testing::Bool(), reading_name);

// ---- rate_limited_requests_stack ----------------------------------------------------------------

// With a limit of two RREQs a second, searches for 1 and 2 use up the first window; three packets
// for 3 then find the limit reached. Every ring is the whole network (ttl_start 35), so no
// retry falls before 2.8 s. (queue_released_by_rrep_only as in ns-3, where a packet asks for a
// route unless one is in search.)
class RateLimitedRequestsStack : public BothReadings {
 protected:
  void three_packets_past_the_limit() {
    make_with("rate_limited_requests_stack",
              {{"rreq_rate_limit", 2}, {"ttl_start", 35}, {"queue_released_by_rrep_only", true}});
    aodv_->send(data_to(1, 1));
    aodv_->send(data_to(2, 2));
    for (std::uint64_t uid = 3; uid <= 5; ++uid) aodv_->send(data_to(3, uid));
    run(0.011);  // past the broadcast jitter
    ASSERT_EQ(sent<Rreq>().size(), 2U);
  }
  // In which rate-limit window (0: the first second) each of this node's RREQs for 3 was
  // originated: a request let through at a turn leaves within the 10 ms jitter after it.
  [[nodiscard]] std::vector<std::int64_t> windows_of_requests_for_three() const {
    std::vector<std::int64_t> out;
    for (const Sent& s : sent<Rreq>()) {
      if (std::get<Rreq>(s.message).destination != 3) continue;
      const SimTime into_window = s.at % std::chrono::seconds(1);
      EXPECT_GE(into_window, std::chrono::microseconds(100));  // 100 us after the turn
      EXPECT_LE(into_window, std::chrono::microseconds(10100));
      out.push_back(s.at / std::chrono::seconds(1));
    }
    return out;
  }
};

TEST_P(RateLimitedRequestsStack, EachRefusedRequestGoesOutAtTheTurnOrOneStandsForAll) {
  three_packets_past_the_limit();
  EXPECT_TRUE(windows_of_requests_for_three().empty());
  EXPECT_EQ(node_.counter("rreq_rate_limited"), GetParam() ? 3U : 1U);
  run(1.02);
  if (GetParam()) {
    // ns-3: two of the three refused requests go out as the window turns, each counting as a
    // try at the network's diameter; the third is refused again.
    EXPECT_EQ(windows_of_requests_for_three(), (std::vector<std::int64_t>{1, 1}));
    EXPECT_EQ(route(3)->rreq_count, 2U);
    EXPECT_EQ(node_.counter("rreq_rate_limited"), 4U);
  } else {
    EXPECT_EQ(windows_of_requests_for_three(), std::vector<std::int64_t>{1});
    EXPECT_EQ(route(3)->rreq_count, 1U);
    EXPECT_EQ(node_.counter("rreq_rate_limited"), 1U);
  }
  EXPECT_EQ(route(3)->state, RouteState::in_search);
  EXPECT_EQ(aodv_->request_queue().size(), 5U);  // every packet still waits for a route
}

TEST_P(RateLimitedRequestsStack, ARequestRefusedAgainGoesOutAtTheNextTurn) {
  three_packets_past_the_limit();
  run(2.5);
  if (GetParam()) {
    EXPECT_EQ(windows_of_requests_for_three(), (std::vector<std::int64_t>{1, 1, 2}));
    EXPECT_EQ(route(3)->rreq_count, 3U);
  } else {
    // One request stood for the three; its retry is due 2.8 s after it.
    EXPECT_EQ(windows_of_requests_for_three(), std::vector<std::int64_t>{1});
  }
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RateLimitedRequestsStack, ::testing::Bool(), reading_name);

// ---- rrep_ends_search_only ----------------------------------------------------------------------

// This node searches for its neighbour 8 (a one-hop ring: the timer is 2 * 40 ms * (1 + 2) =
// 240 ms), and 8's HELLO makes the route valid before 8's RREP arrives; the packet waits for the
// RREP (queue_released_by_rrep_only), and a break keeps the route's number, as in ns-3.
class RrepEndsSearchOnly : public BothReadings {
 protected:
  void search_answered_after_a_hello() {
    make_with("rrep_ends_search_only", {{"queue_released_by_rrep_only", true},
                                        {"rrep_replaces_route", true},
                                        {"increment_seqno_on_break", false}});
    aodv_->send(data_to(8, 901));
    ASSERT_EQ(route(8)->state, RouteState::in_search);
    hello_from(8, 5);
    ASSERT_TRUE(route(8)->is_valid());
    ASSERT_TRUE(data_sent().empty());
    rrep_for_us(8, 8, 5, 0);
    ASSERT_EQ(data_sent(), std::vector<std::uint64_t>{901});  // the RREP sends it either way
  }
  // A relayed packet for 8 that the MAC could not deliver: the link to 8 breaks.
  void link_to_eight_fails() {
    aodv_->link_failed(PacketBuilder().uid(902).from(3).to(8).message(902).build(), 8);
    ASSERT_NE(route(8), nullptr);
    ASSERT_EQ(route(8)->state, RouteState::invalid);
  }
};

TEST_P(RrepEndsSearchOnly, ARouteBrokenBeforeTheTimerFiresIsDeletedOrKeptInvalid) {
  search_answered_after_a_hello();
  link_to_eight_fails();
  run(0.3);  // past the discovery timer
  if (GetParam()) {
    // ns-3: the timer ran on; finding the route neither valid nor in search it deletes it.
    EXPECT_EQ(route(8), nullptr);
  } else {
    ASSERT_NE(route(8), nullptr);
    EXPECT_EQ(route(8)->state, RouteState::invalid);
    EXPECT_EQ(route(8)->seq, 5U);  // kept for the next search's RREQ
  }
  EXPECT_EQ(requests_for(8), 1U);  // no second RREQ either way
}

TEST_P(RrepEndsSearchOnly, ARouteStillValidWhenTheTimerFiresStays) {
  search_answered_after_a_hello();
  run(0.3);
  ASSERT_NE(route(8), nullptr);
  EXPECT_TRUE(route(8)->is_valid());
  EXPECT_EQ(data_sent(), std::vector<std::uint64_t>{901});
  EXPECT_EQ(requests_for(8), 1U);
}

TEST_P(RrepEndsSearchOnly, AStaleRrepSendsTheBufferOverAnInvalidRouteOrKeepsItWaiting) {
  search_answered_after_a_hello();
  aodv_->send(data_to(8, 903));  // over the valid route
  ASSERT_EQ(data_sent().size(), 2U);
  link_to_eight_fails();
  aodv_->send(data_to(8, 904));  // a new search; the packet waits
  ASSERT_EQ(route(8)->state, RouteState::in_search);
  hello_from(8, 6);  // valid again; 904 still waits for a RREP
  link_to_eight_fails();
  rrep_for_us(4, 8, 5, 1);  // older than the route's number 6: the route stays invalid, via 8
  ASSERT_EQ(route(8)->state, RouteState::invalid);
  if (GetParam()) {
    // ns-3 sends the buffer over the route as it stands: to 8, its next hop.
    EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{901, 903, 904}));
    EXPECT_EQ(node_.to_mac.back().next_hop, 8U);
    EXPECT_EQ(aodv_->request_queue().size(), 0U);
  } else {
    EXPECT_EQ(data_sent(), (std::vector<std::uint64_t>{901, 903}));
    EXPECT_EQ(aodv_->request_queue().size(), 1U);
  }
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, RrepEndsSearchOnly, ::testing::Bool(), reading_name);

// ---- lookups_age_all_routes ---------------------------------------------------------------------

// The reverse route to 7 (through neighbour 5) expires at 5.44 s, and nothing looks it up again;
// HELLOs from 5 keep that link, and each is a lookup of the route to 5.
class LookupsAgeAllRoutes : public BothReadings {
 protected:
  void expire_unused_route() {
    make_with("lookups_age_all_routes", {{"increment_seqno_on_break", false}});
    rreq(5, 7, 8, 1);
    for (int second = 1; second <= 5; ++second) {
      run(1.0);
      hello_from(5, second);
    }
    run(0.5);
    hello_from(5, 6);  // at 5.5 s, after the route to 7 expired
  }
};

TEST_P(LookupsAgeAllRoutes, AnExpiredRoutesDeletePeriodStartsAtTheNextLookupOrAtTheNextPurge) {
  expire_unused_route();
  ASSERT_NE(route(7), nullptr);
  if (GetParam()) {
    // ns-3: the lookup of the route to 5 aged the route to 7 too.
    EXPECT_EQ(route(7)->state, RouteState::invalid);
    EXPECT_EQ(route(7)->expires, from_seconds(20.5));
  } else {
    EXPECT_EQ(route(7)->state, RouteState::valid);  // expired, not yet aged
  }
  run(1.0);  // past the housekeeping purge at 6 s
  ASSERT_NE(route(7), nullptr);
  EXPECT_EQ(route(7)->state, RouteState::invalid);
  EXPECT_EQ(route(7)->expires, from_seconds(GetParam() ? 20.5 : 21.0));
}

TEST_P(LookupsAgeAllRoutes, NoTimerAgesTheTableUnderNs3sRule) {
  make_with("lookups_age_all_routes", {{"increment_seqno_on_break", false}});
  rreq(5, 7, 8, 1);  // the reverse route to 7 expires at 5.44 s
  for (int second = 1; second <= 5; ++second) {
    run(1.0);
    hello_from(5, second);
  }
  run(1.5);  // to 6.5 s, past the housekeeping at 6 s, with no lookup since 5 s
  ASSERT_NE(route(7), nullptr);
  if (GetParam()) {
    EXPECT_EQ(route(7)->state, RouteState::valid);  // expired, not yet aged
  } else {
    EXPECT_EQ(route(7)->state, RouteState::invalid);
    EXPECT_EQ(route(7)->expires, from_seconds(21.0));
  }
  hello_from(5, 6);  // the first lookup after the expiry
  EXPECT_EQ(route(7)->state, RouteState::invalid);
  EXPECT_EQ(route(7)->expires, from_seconds(GetParam() ? 21.5 : 21.0));
}

TEST_P(LookupsAgeAllRoutes, AnInvalidRouteIsDeletedAtTheFirstLookupAfterItsDeletePeriod) {
  expire_unused_route();
  for (int second = 7; second <= 20; ++second) {  // 6.5 s to 19.5 s
    run(1.0);
    hello_from(5, second);
  }
  run(1.25);
  hello_from(5, 21);  // at 20.75 s: past ns-3's 20.5 s, before the purge's 21 s
  if (GetParam()) {
    EXPECT_EQ(route(7), nullptr);
  } else {
    ASSERT_NE(route(7), nullptr);
    EXPECT_EQ(route(7)->state, RouteState::invalid);
  }
  EXPECT_TRUE(route(5)->is_valid());
}

INSTANTIATE_TEST_SUITE_P(Ns3AndRfc, LookupsAgeAllRoutes, ::testing::Bool(), reading_name);

}  // namespace
}  // namespace swarmnet::aodv
