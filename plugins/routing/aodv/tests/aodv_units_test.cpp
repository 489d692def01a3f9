// The AODV units alone: route table, request queue, neighbours, id cache, duplicate detection,
// sequence numbers and parameters.
#include <gtest/gtest.h>

#include <iterator>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "aodv_parameters.hpp"
#include "duplicate_detection.hpp"
#include "id_cache.hpp"
#include "neighbors.hpp"
#include "request_queue.hpp"
#include "routing_table.hpp"
#include "sequence_number.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::aodv {
namespace {

SimTime s(double seconds) { return from_seconds(seconds); }

RouteEntry route(NodeId destination, NodeId next_hop, std::uint32_t hops, std::uint32_t seq,
                 SimTime expires) {
  RouteEntry e;
  e.destination = destination;
  e.next_hop = next_hop;
  e.hop_count = hops;
  e.seq = seq;
  e.valid_seq = true;
  e.expires = expires;
  return e;
}

TEST(AodvSequenceNumber, ComparesWithRollover) {
  EXPECT_TRUE(seq_newer(2, 1));
  EXPECT_FALSE(seq_newer(1, 1));
  EXPECT_FALSE(seq_newer(1, 2));
  EXPECT_TRUE(seq_newer(0, 0xffffffff));  // wrapped
  EXPECT_TRUE(seq_newer(5, 0xfffffff0));
  EXPECT_TRUE(seq_not_older(1, 1));
  EXPECT_FALSE(seq_not_older(0xffffffff, 0));
}

TEST(AodvRoutingTable, ValidRouteExpiresToInvalidThenIsDeleted) {
  RoutingTable table(s(15));
  table.insert(route(7, 3, 2, 10, s(3)));
  ASSERT_NE(table.find_valid(7, s(3)), nullptr);  // expiry is inclusive
  EXPECT_EQ(table.find_valid(7, s(3.5)), nullptr);
  RouteEntry* entry = table.find(7, s(3.5));
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->state, RouteState::invalid);
  EXPECT_EQ(entry->seq, 11U);  // the sequence number is remembered, and incremented
  EXPECT_EQ(entry->expires, s(18.5));
  EXPECT_NE(table.find(7, s(18.5)), nullptr);
  EXPECT_EQ(table.find(7, s(18.6)), nullptr);
  EXPECT_EQ(table.size(), 0U);

  RoutingTable ns3_rule(s(15), false);  // increment_seqno_on_break: false
  ns3_rule.insert(route(7, 3, 2, 10, s(3)));
  EXPECT_EQ(ns3_rule.find(7, s(3.5))->seq, 10U);
}

TEST(AodvRoutingTable, WholeTableAgingAgesEveryRouteAtAnyLookup) {
  // ns-3.37: a lookup for 8 at 3.5 s ages the route to 7 too; its delete period starts then.
  RoutingTable ns3_rule(s(15), false, RouteAging::whole_table);
  ns3_rule.insert(route(7, 3, 2, 10, s(3)));
  ns3_rule.insert(route(8, 3, 2, 10, s(100)));
  ASSERT_NE(ns3_rule.find(8, s(3.5)), nullptr);
  ASSERT_NE(ns3_rule.entry(7), nullptr);
  EXPECT_EQ(ns3_rule.entry(7)->state, RouteState::invalid);
  EXPECT_EQ(ns3_rule.entry(7)->expires, s(18.5));
  EXPECT_EQ(ns3_rule.entry(7)->seq, 10U);
  ASSERT_NE(ns3_rule.find(8, s(18.6)), nullptr);
  EXPECT_EQ(ns3_rule.entry(7), nullptr);  // deleted at the first lookup after 18.5 s
  EXPECT_EQ(ns3_rule.size(), 1U);

  // By entry: the route to 7 ages only when it is itself looked up (or at a purge).
  RoutingTable per_entry(s(15), false);
  per_entry.insert(route(7, 3, 2, 10, s(3)));
  per_entry.insert(route(8, 3, 2, 10, s(100)));
  ASSERT_NE(per_entry.find(8, s(3.5)), nullptr);
  EXPECT_EQ(per_entry.entry(7)->state, RouteState::valid);
  EXPECT_EQ(per_entry.find(7, s(4))->expires, s(19));
  ASSERT_NE(per_entry.find(8, s(18.6)), nullptr);
  EXPECT_NE(per_entry.entry(7), nullptr);
}

TEST(AodvRoutingTable, HousekeepingAgesRoutesOnlyWhenLookupsDoNot) {
  // By entry, the periodic call starts an expired route's delete period.
  RoutingTable per_entry(s(15), false);
  per_entry.insert(route(7, 3, 2, 10, s(3)));
  per_entry.housekeep(s(4));
  ASSERT_NE(per_entry.entry(7), nullptr);
  EXPECT_EQ(per_entry.entry(7)->state, RouteState::invalid);
  EXPECT_EQ(per_entry.entry(7)->expires, s(19));

  // ns-3.37 has no timer of the table's own: the route waits for the next lookup.
  RoutingTable ns3_rule(s(15), false, RouteAging::whole_table);
  ns3_rule.insert(route(7, 3, 2, 10, s(3)));
  ns3_rule.housekeep(s(4));
  ASSERT_NE(ns3_rule.entry(7), nullptr);
  EXPECT_EQ(ns3_rule.entry(7)->state, RouteState::valid);
  EXPECT_EQ(ns3_rule.find(7, s(5))->expires, s(20));
}

TEST(AodvRoutingTable, RouteInSearchDoesNotExpireByItself) {
  RoutingTable table(s(15));
  RouteEntry e = route(7, kNoNode, 1, 0, s(1));
  e.state = RouteState::in_search;
  table.insert(e);
  table.purge(s(100));
  ASSERT_NE(table.find(7, s(100)), nullptr);
  EXPECT_EQ(table.find_valid(7, s(100)), nullptr);
}

TEST(AodvRoutingTable, RefreshExtendsOnlyValidRoutesAndNeverShortens) {
  RoutingTable table(s(15));
  table.insert(route(7, 3, 2, 10, s(10)));
  EXPECT_TRUE(table.refresh(7, s(3), s(1)));
  EXPECT_EQ(table.find(7, s(1))->expires, s(10));
  EXPECT_TRUE(table.refresh(7, s(3), s(9)));
  EXPECT_EQ(table.find(7, s(9))->expires, s(12));
  EXPECT_FALSE(table.refresh(8, s(3), s(9)));
  table.invalidate(*table.find(7, s(9)), s(9));
  EXPECT_FALSE(table.refresh(7, s(3), s(9)));
}

TEST(AodvRoutingTable, ListsValidDestinationsThroughANextHop) {
  RoutingTable table(s(15));
  table.insert(route(7, 3, 2, 10, s(10)));
  table.insert(route(3, 3, 1, 4, s(10)));
  table.insert(route(9, 4, 2, 1, s(10)));
  table.insert(route(5, 3, 3, 8, s(10)));
  table.invalidate(*table.find(5, s(0)), s(0));
  const auto via = table.valid_destinations_via(3, s(1));
  ASSERT_EQ(via.size(), 2U);
  EXPECT_EQ(via[0], (UnreachableDestination{3, 4}));
  EXPECT_EQ(via[1], (UnreachableDestination{7, 10}));
}

TEST(AodvRoutingTable, AnEntrysAddressSurvivesOtherInsertsAndRemovals) {
  RoutingTable table(s(15));
  for (NodeId d = 0; d < 3000; ++d) table.insert(route(d, 1, 2, d, s(d % 2 == 0 ? 1 : 100)));
  const RouteEntry* kept = table.find(3, s(0));
  ASSERT_NE(kept, nullptr);
  table.purge(s(2));   // the even destinations' routes become invalid
  table.purge(s(20));  // and are deleted, delete_period later
  EXPECT_EQ(table.size(), 1500U);
  EXPECT_EQ(table.entry(2), nullptr);
  // Reuses the deleted entries' places, then grows.
  for (NodeId d = 3000; d < 6000; ++d) table.insert(route(d, 1, 2, d, s(100)));
  EXPECT_EQ(table.find(3, s(20)), kept);
  EXPECT_EQ(kept->destination, 3U);
  EXPECT_EQ(kept->seq, 3U);
  EXPECT_EQ(table.size(), 4500U);
  EXPECT_EQ(table.entry(5999)->seq, 5999U);
}

// A std::map with the same expiry rules as the reference: every lookup and size agree, for
// either aging (by entry, or the whole table at every lookup).
void check_against_a_map_of_routes(RouteAging aging) {
  RoutingTable table(s(2), true, aging);
  std::map<NodeId, RouteEntry> model;
  RandomStream random(42);
  const auto age = [](RouteEntry& e, SimTime now) {  // RoutingTable::age, restated
    if (e.expires >= now) return true;
    if (e.state == RouteState::valid) {
      e.state = RouteState::invalid;
      e.rreq_count = 0;
      e.expires = now + s(2);
      if (e.valid_seq) ++e.seq;
      return true;
    }
    return e.state != RouteState::invalid;
  };
  const auto age_model = [&model, &age](SimTime now) {
    for (auto it = model.begin(); it != model.end();) {
      it = age(it->second, now) ? std::next(it) : model.erase(it);
    }
  };
  for (int step = 0; step < 20000; ++step) {
    // Two steps an instant, so that a lookup may follow another at the same time.
    const int instant = step / 2;
    const SimTime now = s(instant * 0.002);
    const auto d = static_cast<NodeId>(random.below(300));
    switch (random.below(4)) {
      case 0: {
        const RouteEntry e = route(d, static_cast<NodeId>(random.below(300)), 1,
                                   static_cast<std::uint32_t>(step), now + s(random.uniform()));
        table.insert(e);
        model[d] = e;
        break;
      }
      case 1: {
        const RouteEntry* found = table.find(d, now);
        if (aging == RouteAging::whole_table) age_model(now);
        const auto it = model.find(d);
        if (it != model.end() && !age(it->second, now)) model.erase(it);
        const auto again = model.find(d);
        ASSERT_EQ(found == nullptr, again == model.end()) << step;
        if (found != nullptr) {
          ASSERT_EQ(found->seq, again->second.seq) << step;
          ASSERT_EQ(found->state, again->second.state) << step;
        }
        break;
      }
      case 2:
        ASSERT_EQ(table.erase(d), model.erase(d) == 1) << step;
        break;
      default:
        table.purge(now);
        age_model(now);
        break;
    }
    ASSERT_EQ(table.size(), model.size()) << step;
  }
}

TEST(AodvRoutingTable, MatchesAMapOfRoutesUnderRandomInsertsFindsAndPurges) {
  check_against_a_map_of_routes(RouteAging::per_entry);
}

TEST(AodvRoutingTable, MatchesAMapOfRoutesAgedWholeAtEveryLookup) {
  check_against_a_map_of_routes(RouteAging::whole_table);
}

TEST(AodvRoutingTable, ARouteToNoNodeIsRefused) {
  RoutingTable table(s(15));
  EXPECT_THROW(table.insert(route(kNoNode, 1, 1, 1, s(1))), std::logic_error);
  EXPECT_THROW(table.insert(route(kBroadcast, 1, 1, 1, s(1))), std::logic_error);
  EXPECT_EQ(table.size(), 0U);
  EXPECT_EQ(table.entry(kNoNode), nullptr);
}

TEST(AodvRoutingTable, ARouteOutsideTheNetworkIsRefused) {
  RoutingTable table(s(15));
  table.set_node_count(10);
  EXPECT_THROW(table.insert(route(10, 1, 1, 1, s(1))), std::logic_error);
  EXPECT_THROW(table.insert(route(4'000'000'000U, 1, 1, 1, s(1))), std::logic_error);
  EXPECT_EQ(table.size(), 0U);
  table.insert(route(9, 1, 1, 1, s(1)));
  EXPECT_EQ(table.size(), 1U);
  EXPECT_EQ(table.entry(10), nullptr);
}

TEST(AodvRoutingTable, PrecursorsAreAUniqueSortedSet) {
  RouteEntry e;
  EXPECT_TRUE(e.insert_precursor(5));
  EXPECT_TRUE(e.insert_precursor(2));
  EXPECT_FALSE(e.insert_precursor(5));
  EXPECT_EQ(e.precursors, (std::vector<NodeId>{2, 5}));
  EXPECT_TRUE(e.has_precursor(2));
  EXPECT_FALSE(e.has_precursor(3));
}

TEST(AodvRoutingTable, BlacklistExpires) {
  RoutingTable table(s(15));
  table.blacklist(4, s(5.6));
  EXPECT_TRUE(table.is_blacklisted(4, s(5)));
  EXPECT_FALSE(table.is_blacklisted(3, s(5)));
  EXPECT_FALSE(table.is_blacklisted(4, s(6)));
}

class AodvRequestQueue : public ::testing::Test {
 protected:
  static Packet packet(std::uint64_t uid, NodeId destination) {
    Packet p;
    p.uid = uid;
    p.source = 0;
    p.destination = destination;
    p.message_id = uid;
    return p;
  }
  RequestQueue queue_{3, from_seconds(30),
                      [this](const Packet& p, DropReason r) { drops_.emplace_back(p.uid, r); }};
  std::vector<std::pair<std::uint64_t, DropReason>> drops_;
};

TEST_F(AodvRequestQueue, FullQueueDropsTheOldestAsQueueFull) {
  EXPECT_TRUE(queue_.enqueue(packet(1, 5), s(0)));
  EXPECT_TRUE(queue_.enqueue(packet(2, 6), s(1)));
  EXPECT_FALSE(queue_.enqueue(packet(2, 6), s(1)));  // same packet twice
  EXPECT_TRUE(queue_.enqueue(packet(3, 5), s(2)));
  EXPECT_TRUE(queue_.enqueue(packet(4, 5), s(3)));
  ASSERT_EQ(drops_.size(), 1U);
  EXPECT_EQ(drops_[0], std::make_pair(std::uint64_t{1}, DropReason::queue_full));
  EXPECT_EQ(queue_.size(), 3U);
}

TEST_F(AodvRequestQueue, TakeReturnsOneDestinationInArrivalOrder) {
  queue_.enqueue(packet(1, 5), s(0));
  queue_.enqueue(packet(2, 6), s(0));
  queue_.enqueue(packet(3, 5), s(0));
  EXPECT_TRUE(queue_.has(5));
  const auto taken = queue_.take(5, s(1));
  ASSERT_EQ(taken.size(), 2U);
  EXPECT_EQ(taken[0].uid, 1U);
  EXPECT_EQ(taken[1].uid, 3U);
  EXPECT_FALSE(queue_.has(5));
  EXPECT_EQ(queue_.size(), 1U);
  EXPECT_TRUE(drops_.empty());
}

TEST_F(AodvRequestQueue, ExpiredPacketsAreDroppedAsBufferTimeout) {
  queue_.enqueue(packet(1, 5), s(0));
  queue_.enqueue(packet(2, 5), s(10));
  EXPECT_EQ(queue_.next_expiry(), s(30));
  queue_.purge(s(30));  // not yet: strictly after its expiry
  EXPECT_TRUE(drops_.empty());
  queue_.purge(s(31));
  ASSERT_EQ(drops_.size(), 1U);
  EXPECT_EQ(drops_[0], std::make_pair(std::uint64_t{1}, DropReason::buffer_timeout));
  queue_.drop_destination(5, DropReason::no_route, s(31));
  ASSERT_EQ(drops_.size(), 2U);
  EXPECT_EQ(drops_[1], std::make_pair(std::uint64_t{2}, DropReason::no_route));
  EXPECT_EQ(queue_.next_expiry(), kTimeNever);
}

TEST(AodvNeighbors, ExpireAfterTheirLifetimeOrWhenClosed) {
  Neighbors neighbors;
  neighbors.update(3, s(2), s(0));
  neighbors.update(4, s(2), s(0));
  neighbors.update(4, s(2), s(1));  // heard again
  neighbors.update(5, s(2), s(1));
  neighbors.update(5, s(0.5), s(1));  // a shorter lifetime never shortens
  EXPECT_EQ(neighbors.expiry(5), s(3));
  EXPECT_TRUE(neighbors.is_neighbor(3, s(2)));
  EXPECT_TRUE(neighbors.purge(s(2)).empty());
  neighbors.close(5);
  EXPECT_FALSE(neighbors.is_neighbor(5, s(2)));
  EXPECT_EQ(neighbors.purge(s(2.5)), (std::vector<NodeId>{3, 5}));
  EXPECT_EQ(neighbors.size(), 1U);
  EXPECT_TRUE(neighbors.is_neighbor(4, s(2.5)));
  EXPECT_EQ(neighbors.purge(s(3.1)), (std::vector<NodeId>{4}));
}

// ns-3's aodv-neighbor: a neighbour's link-layer address is looked up while it is unknown and
// kept once known; the MAC's report closes only a neighbour with a known address.
TEST(AodvNeighbors, MatchMacReportsByAResolvedAddressOnly) {
  Neighbors neighbors;
  EXPECT_TRUE(neighbors.update(3, s(2), s(0), false));  // new, address unresolved
  EXPECT_FALSE(neighbors.update(3, s(2), s(0.5), false));
  EXPECT_FALSE(neighbors.address_known(3));
  EXPECT_FALSE(neighbors.close_by_address(3));
  EXPECT_TRUE(neighbors.purge(s(1)).empty());
  EXPECT_FALSE(neighbors.update(3, s(2), s(1), true));  // resolved now
  EXPECT_FALSE(neighbors.update(3, s(2), s(1.5), false));
  EXPECT_TRUE(neighbors.address_known(3));      // kept
  EXPECT_FALSE(neighbors.close_by_address(4));  // not a neighbour
  EXPECT_TRUE(neighbors.close_by_address(3));
  EXPECT_EQ(neighbors.purge(s(1.5)), (std::vector<NodeId>{3}));
  EXPECT_TRUE(neighbors.empty());
  neighbors.update(4, s(2), s(2), false);
  neighbors.close(4);  // link_failure_match: next_hop closes whatever the address
  EXPECT_EQ(neighbors.purge(s(2)), (std::vector<NodeId>{4}));
}

TEST(AodvIdCache, RemembersPairsForItsLifetime) {
  IdCache cache(s(5.6));
  EXPECT_FALSE(cache.is_duplicate(1, 10, s(0)));
  EXPECT_TRUE(cache.is_duplicate(1, 10, s(1)));
  EXPECT_FALSE(cache.is_duplicate(2, 10, s(1)));  // other originator
  EXPECT_FALSE(cache.is_duplicate(1, 11, s(1)));  // other id
  EXPECT_TRUE(cache.contains(1, 10, s(5.6)));
  EXPECT_FALSE(cache.is_duplicate(1, 10, s(5.7)));  // forgotten, then recorded again
  cache.purge(s(6.7));
  EXPECT_EQ(cache.size(), 1U);
}

TEST(AodvDuplicateDetection, RecognisesCopiesBySourceAndUid) {
  DuplicateDetection dpd(s(5.6));
  Packet p;
  p.source = 3;
  p.uid = 99;
  EXPECT_FALSE(dpd.is_duplicate(p, s(0)));
  p.hops = 4;  // a relayed copy
  EXPECT_TRUE(dpd.is_duplicate(p, s(0.1)));
  p.uid = 100;
  EXPECT_FALSE(dpd.is_duplicate(p, s(0.1)));
}

TEST(AodvParameters, DefaultsAreNs3sAndDerivedTimesFollowRfc3561) {
  ParamSet params;
  for (const ParamSpec& spec : parameter_schema()) {
    params.set(spec.name, spec.default_value);
    if (spec.type == ParamType::real || spec.type == ParamType::integer) {
      EXPECT_FALSE(spec.unit.empty()) << spec.name << " has no unit";
    }
    EXPECT_FALSE(spec.help.empty()) << spec.name;
  }
  const AodvParameters p = parameters_from(params);
  EXPECT_EQ(p.hello_interval, s(1));
  EXPECT_EQ(p.allowed_hello_loss, 2U);
  EXPECT_EQ(p.active_route_timeout, s(3));
  EXPECT_EQ(p.net_diameter, 35U);
  EXPECT_EQ(p.node_traversal_time, s(0.04));
  EXPECT_EQ(p.net_traversal_time, s(2.8));
  EXPECT_EQ(p.path_discovery_time, s(5.6));
  EXPECT_EQ(p.next_hop_wait, s(0.05));
  EXPECT_EQ(p.my_route_timeout, s(11.2));
  EXPECT_EQ(p.blacklist_timeout, s(5.6));
  EXPECT_EQ(p.delete_period, s(15));
  EXPECT_EQ(p.rreq_retries, 2U);
  EXPECT_EQ(p.rreq_rate_limit, 10U);
  EXPECT_EQ(p.rerr_rate_limit, 10U);
  EXPECT_EQ(p.ttl_start, 1U);
  EXPECT_EQ(p.ttl_increment, 2U);
  EXPECT_EQ(p.ttl_threshold, 7U);
  EXPECT_EQ(p.timeout_buffer, 2U);
  EXPECT_EQ(p.max_queue_len, 64U);
  EXPECT_EQ(p.max_queue_time, s(30));
  EXPECT_FALSE(p.destination_only);
  EXPECT_TRUE(p.gratuitous_reply);
  EXPECT_TRUE(p.enable_hello);
  EXPECT_TRUE(p.increment_seqno_on_break);  // RFC 3561, not ns-3.37
  EXPECT_FALSE(p.enable_local_repair);
  EXPECT_TRUE(p.link_layer_feedback);
  EXPECT_FALSE(p.link_failure_any_next_hop);  // ns-3's matching by resolved neighbour address
  EXPECT_EQ(p.max_repair_ttl(), 10U);

  params.set("node_traversal_time_s", 0.01);
  params.set("delete_period_s", 2.0);
  const AodvParameters q = parameters_from(params);
  EXPECT_EQ(q.net_traversal_time, s(0.7));
  EXPECT_EQ(q.path_discovery_time, s(1.4));
  EXPECT_EQ(q.delete_period, s(2));
}

}  // namespace
}  // namespace swarmnet::aodv
