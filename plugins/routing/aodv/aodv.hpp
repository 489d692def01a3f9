// `aodv` routing: Ad hoc On-Demand Distance Vector routing (RFC 3561) with ns-3's defaults.
//
// The protocol proper; its parts are separate units: packet formats (aodv_packet), the route
// table (routing_table), the buffer of packets awaiting a route (request_queue), neighbours
// (neighbors), the RREQ-id cache and broadcast duplicate detection (id_cache,
// duplicate_detection) and the parameters (aodv_parameters). Where the RFC leaves a choice, ns-3's
// aodv-routing-protocol.cc is followed; departures from it are listed in info().
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>

#include "aodv_packet.hpp"
#include "aodv_parameters.hpp"
#include "duplicate_detection.hpp"
#include "id_cache.hpp"
#include "neighbors.hpp"
#include "request_queue.hpp"
#include "routing_table.hpp"
#include "sequence_number.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/routing.hpp"

namespace swarmnet::aodv {

class Aodv final : public Routing {
 public:
  static PluginInfo info();
  explicit Aodv(const PluginArgs& args);

  void attach(RoutingContext& context) override;
  void send(Packet packet) override;
  void receive(Packet packet, NodeId from) override;
  void link_failed(const Packet& packet, NodeId next_hop) override;
  [[nodiscard]] Route route_to(NodeId destination) const override;

  // Read-only views for tests that compile the plugin's sources in (the kernel never sees them).
  [[nodiscard]] const RoutingTable& routing_table() const { return table_; }
  [[nodiscard]] const RequestQueue& request_queue() const { return queue_; }
  [[nodiscard]] const Neighbors& neighbors() const { return neighbors_; }
  [[nodiscard]] const AodvParameters& parameters() const { return params_; }
  [[nodiscard]] std::uint32_t sequence_number() const { return seq_; }
  [[nodiscard]] bool discovering(NodeId destination) const {
    return discovery_timers_.contains(destination);
  }

 private:
  [[nodiscard]] SimTime now() const { return context_->now(); }

  // Data.
  void forward_data(Packet packet);
  // What a packet for this node refreshes: the route to its source and the way back.
  void keep_source_routes_alive(const Packet& packet);
  // What forwarding a packet along a valid route refreshes (RFC 3561 6.2, ns-3.37 Forwarding).
  void keep_forwarding_routes_alive(const Packet& packet, const RouteEntry& to_destination);
  // The RERR a node sends to the source of a packet it has no route to forward.
  void report_no_route(const Packet& packet);
  void deliver_broadcast(Packet packet);
  void transmit_data(Packet packet, const RouteEntry& route);
  void buffer(Packet packet);
  void arm_queue_timer();
  void send_queued(NodeId destination);
  // Every packet waiting for `destination` over `route` (unless in search), whatever its state.
  void send_queued_over(NodeId destination, const RouteEntry& route);
  // A buffered packet, control or data, over `route` (pass a copy, not a table entry: sending
  // may change the table).
  void transmit_queued(Packet packet, const RouteEntry& route);

  // Route discovery.
  void send_request(NodeId destination);
  void defer_request(NodeId destination);
  // Fills in what every RREQ this node originates carries (flags, originator, sequence number,
  // id, TTL), notes its id as seen and broadcasts it.
  void originate_request(Rreq rreq, std::uint32_t ttl);
  void request_timer_expired(NodeId destination);
  void schedule_request_retry(NodeId destination);
  void give_up(NodeId destination);
  // A discovery for `destination` is under way, and a packet for it only needs to wait. By
  // default while its timer runs; with queue_released_by_rrep_only as ns-3.37 decides it, by the
  // route being in search (its timer may outlive the search there).
  [[nodiscard]] bool discovery_under_way(NodeId destination);
  // Cancels the discovery for `destination`, if one runs (a local repair included).
  void end_discovery(NodeId destination);
  // A route became valid through something other than a RREP for this node (a HELLO, a RREQ, any
  // AODV message from the neighbour). By default that ends the search for it and sends its
  // buffer; with queue_released_by_rrep_only (ns-3.37) both wait for the discovery timer.
  // `route` is the entry as it was before the update (its state tells whether it was in search).
  void end_search_early(const RouteEntry& route);
  void release_buffer_early(NodeId destination);
  bool start_local_repair(const Packet& packet, RouteEntry& route);

  // Control messages in.
  void receive_request(const Rreq& rreq, NodeId from);
  void receive_reply(Rrep rrep, NodeId from);
  void receive_hello(const Rrep& hello);
  void receive_error(const Rerr& rerr, NodeId from);
  // ns-3.37's reading of a RERR (rerr_covers_routes_in_any_state).
  void relay_error_any_state(const Rerr& rerr, NodeId from);
  // Invalidates the valid routes to the destinations `rerr` lists.
  void invalidate_listed(const Rerr& rerr);
  void receive_ack(NodeId from);
  void update_route_to_neighbor(NodeId neighbor);
  // A unicast control message for another node, relayed as IP (control_via_route_to_neighbor).
  void relay_control(Packet packet, Message message);
  // ns-3.37's readings of two route updates (neighbor_route_forgets_seqno,
  // rreq_overwrites_reverse_route); RFC 3561's are in the callers.
  void forget_neighbor_seqno(RouteEntry& route, NodeId neighbor);
  void overwrite_reverse_route(RouteEntry& to_origin, const Rreq& rreq, NodeId from,
                               std::uint32_t hops, SimTime lifetime);

  // Control messages out.
  void reply_as_destination(const Rreq& rreq, const RouteEntry& to_origin);
  void reply_as_intermediate(const Rreq& rreq, RouteEntry& to_destination, RouteEntry& to_origin);
  void send_reply(const Rrep& rrep, NodeId next_hop);
  void send_hello();
  void send_error(const Rerr& rerr, const std::vector<NodeId>& precursors);
  // ns-3.37's SendRerrMessage (rerr_to_valid_precursors): one RERR of at most 255 destinations.
  void send_error_to_valid_precursors(const Rerr& part, const std::vector<NodeId>& precursors);
  void send_control(const Message& message, NodeId next_hop);
  void transmit_control(Packet packet, const RouteEntry& route);
  void broadcast_control(const Message& message);

  // Neighbours (ns-3's aodv-neighbor). Records `neighbor` as heard, with whether this node's
  // ARP cache resolves it now; a new neighbour purges the list, as ns-3's Neighbors::Update does.
  void update_neighbor(NodeId neighbor, SimTime lifetime);
  // ns-3's Neighbors::Purge: reports expired and closed neighbours as broken links (`failed`, the
  // packet the MAC dropped, goes with `failed_hop`'s break) and re-arms the neighbour timer; an
  // empty list is left alone (no timer).
  void purge_neighbors(const Packet* failed = nullptr, NodeId failed_hop = kNoNode);

  // Link breakage (RFC 3561 section 6.11).
  void link_broken(NodeId neighbor, const Packet* failed);
  // ns-3.37's reading of a broken link (rerr_covers_routes_in_any_state).
  void report_routes_via(NodeId neighbor, const Packet* failed);
  // A valid route whose link broke under `failed`: true if a local repair took it over (the
  // packet is buffered).
  bool repaired_locally(const Packet* failed, RouteEntry& route);
  // With increment_seqno_on_break (RFC 3561 6.11): a broken route's number goes up by one, and a
  // RERR's newer number is adopted.
  void increment_broken_seqno(RouteEntry& route) const;
  void adopt_reported_seqno(RouteEntry& route, std::uint32_t seq) const;
  void housekeeping();

  // Timers.
  void hello_timer_expired();
  // Counts one message against `limit` in this second's window, if it has room.
  bool rate_allows(std::uint32_t& counter, std::uint32_t limit);
  // Whether this second's window has room for a RERR, without counting it (ns-3.37 checks its
  // RERR limit before every RERR but counts only those unicast to a single precursor).
  bool rerr_rate_has_room();
  void turn_rate_window();
  [[nodiscard]] SimTime next_rate_window() const;
  [[nodiscard]] SimTime jitter();
  // `candidate` (seq, hops) should replace `entry` (RFC 3561 section 6.2).
  [[nodiscard]] static bool fresher(const RouteEntry& entry, std::uint32_t seq, std::uint32_t hops);

  AodvParameters params_;
  RoutingContext* context_ = nullptr;
  NodeId self_ = kNoNode;
  RandomStream random_;
  RoutingTable table_;
  RequestQueue queue_;
  Neighbors neighbors_;
  IdCache rreq_ids_;
  DuplicateDetection broadcast_ids_;

  std::uint32_t seq_ = 0;
  std::uint32_t rreq_id_ = 0;
  std::map<NodeId, TimerId> discovery_timers_;
  std::set<NodeId> repairing_;  // destinations whose discovery is a local repair
  std::map<NodeId, TimerId> ack_timers_;
  TimerId queue_timer_ = kNoTimer;
  TimerId neighbor_timer_ = kNoTimer;  // ns-3's Neighbors timer (one hello_interval after a purge)
  SimTime queue_timer_at_ = kTimeNever;
  SimTime last_broadcast_ = kTimeNever;  // kTimeNever: no broadcast since the last HELLO tick

  std::int64_t rate_window_ = -1;  // index of the current one-second rate-limit window
  std::uint32_t rreq_count_ = 0;
  std::uint32_t rerr_count_ = 0;
};

}  // namespace swarmnet::aodv
