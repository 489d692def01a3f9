// AODV's route table (RFC 3561 section 2): one entry per destination with its sequence number,
// hop count, next hop, expiry and precursors, plus the blacklist of neighbours whose link was
// found unidirectional.
//
// Expiry is applied lazily and deterministically from the `now` handed to each call: a valid
// route past its expiry becomes invalid and is kept for `delete_period` (so that its sequence
// number is still known), an invalid route past that is deleted; a route in search is left to
// the route discovery that owns it. An expiring route's sequence number is incremented, as
// RFC 3561 section 6.11 does for a broken link: otherwise rule (iii) of section 6.2 (same
// number, route inactive) lets the node accept a longer route with the same number through
// upstream nodes that still route via it, a loop the random-mobility tests found. A table made
// with `increment_seq_on_expiry` false keeps the number, as ns-3.37 does.
//
// When an expired route ages is the table's `RouteAging`: by default an entry ages when it is
// looked up itself, when the routes through a neighbour are listed, and at purge(); ns-3.37's
// table ages every entry at every lookup, so that an expired valid route becomes invalid, and
// starts its delete_period, at the node's first lookup after it expired, for any destination.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include "aodv_packet.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

enum class RouteState : std::uint8_t { valid, invalid, in_search };

enum class RouteAging : std::uint8_t {
  per_entry,    // an entry ages when it is itself looked up; every entry at purge() and listings
  whole_table,  // ns-3.37 (RoutingTable::Purge): every lookup first ages every entry
};

const char* to_string(RouteState state);

struct RouteEntry {
  NodeId destination = kNoNode;
  NodeId next_hop = kNoNode;
  std::uint32_t hop_count = 0;
  std::uint32_t seq = 0;
  bool valid_seq = false;
  RouteState state = RouteState::valid;
  SimTime expires{};               // absolute time
  std::vector<NodeId> precursors;  // sorted, unique
  std::uint32_t rreq_count = 0;    // RREQs sent at the network diameter in this discovery

  [[nodiscard]] bool is_valid() const { return state == RouteState::valid; }
  // Adds `node`; returns false if it was already a precursor.
  bool insert_precursor(NodeId node);
  [[nodiscard]] bool has_precursor(NodeId node) const;
};

class RoutingTable {
 public:
  explicit RoutingTable(SimTime delete_period, bool increment_seq_on_expiry = true,
                        RouteAging aging = RouteAging::per_entry)
      : delete_period_(delete_period),
        increment_seq_on_expiry_(increment_seq_on_expiry),
        aging_(aging) {}

  // Bounds the destinations to the network's nodes 0..node_count-1 (the table is indexed by node
  // id: an unbounded id would size it to gigabytes). Until set, any id below kNoNode is taken.
  void set_node_count(std::size_t node_count) { node_count_ = node_count; }

  // The entry for `destination` after expiry at `now`, or null. Under RouteAging::whole_table
  // every entry ages first, as in ns-3.37's LookupRoute.
  RouteEntry* find(NodeId destination, SimTime now);
  // As find(), but only a valid route.
  RouteEntry* find_valid(NodeId destination, SimTime now);

  // Inserts `entry`, replacing any entry for the same destination; returns the stored entry.
  // A destination outside the network (or kNoNode, kBroadcast) throws std::logic_error.
  // insert() and erase() age nothing: the plugin looks the destination up first, at the same
  // instant, which has aged the table as ns-3.37's AddRoute and DeleteRoute do.
  RouteEntry& insert(RouteEntry entry);
  bool erase(NodeId destination);

  // Invalidates a valid route (kept for delete_period); its hop count and sequence number stay.
  void invalidate(RouteEntry& entry, SimTime now) const;
  // Makes a valid route live at least until now + lifetime, and resets its RREQ count; false if
  // there is no valid route to `destination`.
  bool refresh(NodeId destination, SimTime lifetime, SimTime now);

  // Valid routes whose next hop is `next_hop`, as (destination, sequence number), by destination.
  [[nodiscard]] std::vector<UnreachableDestination> valid_destinations_via(NodeId next_hop,
                                                                           SimTime now);
  // As valid_destinations_via(), but routes in any state: invalid and in search too (ns-3.37's
  // GetListOfDestinationWithNextHop).
  [[nodiscard]] std::vector<UnreachableDestination> destinations_via(NodeId next_hop, SimTime now);

  // Applies expiry to every entry, and forgets expired blacklist entries.
  void purge(SimTime now);
  // The plugin's periodic call: forgets expired blacklist entries and, under per_entry aging,
  // ages every entry (a route's delete period starts here if no lookup of it came first). Under
  // whole_table the entries are left to the lookups: ns-3.37's table has no timer of its own,
  // and one would start a delete period before ns-3's first lookup after the expiry does.
  void housekeep(SimTime now);

  // The blacklist (RFC 3561 section 6.8).
  void blacklist(NodeId neighbor, SimTime until) { blacklist_[neighbor] = until; }
  [[nodiscard]] bool is_blacklisted(NodeId neighbor, SimTime now);

  // The entry for `destination` as stored, without applying expiry, or null (inspection).
  [[nodiscard]] const RouteEntry* entry(NodeId destination) const;
  [[nodiscard]] std::size_t size() const { return slots_.size() - free_slots_.size(); }
  [[nodiscard]] SimTime delete_period() const { return delete_period_; }

 private:
  // Applies expiry to one entry; returns false if the entry must be deleted.
  bool age(RouteEntry& entry, SimTime now) const;
  // Applies expiry to every entry, once per instant: every entry the plugin writes at `now`
  // that is not in search expires at `now` or later, so a second walk at the same instant
  // would change nothing.
  void age_all(SimTime now);
  // Forgets expired blacklist entries only (is_blacklisted() ignores them anyway: memory).
  void forget_expired_blacklist(SimTime now);
  // Routes through `next_hop` after expiry, valid ones only or all, sorted by destination.
  std::vector<UnreachableDestination> list_via(NodeId next_hop, SimTime now, bool valid_only);

  // 1 + the slot of `destination`'s entry, or 0 for none.
  [[nodiscard]] std::uint32_t slot_of(NodeId destination) const {
    return destination < slot_of_.size() ? slot_of_[destination] : 0;
  }
  // The stored entry for `destination`, or null.
  [[nodiscard]] RouteEntry* stored(NodeId destination) {
    const std::uint32_t slot = slot_of(destination);
    return slot == 0 ? nullptr : &slots_[slot - 1];
  }
  void remove(NodeId destination);

  SimTime delete_period_;
  bool increment_seq_on_expiry_;
  RouteAging aging_;
  SimTime aged_all_at_ = kTimeNever;  // the instant of the last age_all()
  // Looked up several times per packet: indexed by destination (node ids are dense), one array
  // read where a hash table took a division and a chain walk (5% of a 400-robot run). Entries
  // live in a deque, so the addresses find() hands out stay valid while others are inserted, as
  // they did in the hash table; a removed entry's slot is reused. Walks (purge, list_via) go in
  // slot order, which reaches no result: each entry ages alone, and list_via sorts what it lists.
  std::vector<std::uint32_t> slot_of_;  // by destination: 1 + its slot, or 0 for none
  std::deque<RouteEntry> slots_;        // a free slot's destination is kNoNode
  std::vector<std::uint32_t> free_slots_;
  std::size_t node_count_ = kNoNode;
  std::map<NodeId, SimTime> blacklist_;
};

}  // namespace swarmnet::aodv
