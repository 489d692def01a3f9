// AODV's parameters (RFC 3561 section 10) with ns-3's defaults, declared once: the schema the
// scenario validator and `swarmnet plugins aodv` read, and the typed values the protocol uses.
#pragma once

#include <cstdint>
#include <vector>

#include "swarmnet/params.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

struct AodvParameters {
  SimTime hello_interval = from_seconds(1.0);
  std::uint32_t allowed_hello_loss = 2;
  SimTime active_route_timeout = from_seconds(3.0);
  std::uint32_t net_diameter = 35;
  SimTime node_traversal_time = from_seconds(0.040);
  SimTime net_traversal_time = from_seconds(2.8);   // 2 * node_traversal_time * net_diameter
  SimTime path_discovery_time = from_seconds(5.6);  // 2 * net_traversal_time
  SimTime next_hop_wait = from_seconds(0.050);      // node_traversal_time + 10 ms
  SimTime my_route_timeout = from_seconds(11.2);    // 2 * max(path_discovery, active_route)
  SimTime blacklist_timeout = from_seconds(5.6);    // rreq_retries * net_traversal_time
  SimTime delete_period = from_seconds(15.0);       // 5 * max(active_route, hello_interval)
  std::uint32_t rreq_retries = 2;
  std::uint32_t rreq_rate_limit = 10;
  std::uint32_t rerr_rate_limit = 10;
  std::uint32_t ttl_start = 1;
  std::uint32_t ttl_increment = 2;
  std::uint32_t ttl_threshold = 7;
  std::uint32_t timeout_buffer = 2;
  std::uint32_t max_queue_len = 64;
  SimTime max_queue_time = from_seconds(30.0);
  bool destination_only = false;
  bool gratuitous_reply = true;
  bool enable_hello = true;
  bool link_layer_feedback = true;
  // Which MAC failure reports break a link (link_failure_match).
  bool link_failure_any_next_hop = false;  // false: "neighbor_address" (ns-3); true: "next_hop"
  bool increment_seqno_on_break = true;
  bool rreq_invalidates_sender_seqno = false;
  // ns-3.37's control-message rules (aodv-routing-protocol.cc); false is RFC 3561's reading.
  bool rrep_over_invalid_reverse_route = false;
  bool rrep_ip_ttl = false;
  bool rerr_to_valid_precursors = false;
  bool queue_released_by_rrep_only = false;
  // ns-3.37's route-update rules, where RFC 3561's reading keeps routes loop free.
  bool rreq_overwrites_reverse_route = false;
  bool neighbor_route_forgets_seqno = false;
  bool reply_seqno_plus_one_only = false;
  bool control_via_route_to_neighbor = false;
  bool ip_input_refreshes_routes = false;
  bool rerr_covers_routes_in_any_state = false;
  bool rrep_replaces_route = false;
  // ns-3.37's rate limit: every refused RREQ is sent on its own once the window turns.
  bool rate_limited_requests_stack = false;
  // ns-3.37's RecvReply: a RREP ends only a discovery whose route it found in search.
  bool rrep_ends_search_only = false;
  // ns-3.37's route table (Purge): every lookup ages every route, not only the one looked up.
  bool lookups_age_all_routes = false;
  bool enable_broadcast = true;
  bool enable_local_repair = false;
  std::uint32_t local_add_ttl = 2;
  bool rrep_ack_required = false;
  std::uint32_t data_ttl = 64;
  SimTime broadcast_jitter_max = from_seconds(0.010);
  SimTime hello_start_jitter_max = from_seconds(0.100);

  [[nodiscard]] SimTime hello_lifetime() const {
    return hello_interval * static_cast<std::int64_t>(allowed_hello_loss);
  }
  // Largest hop count to a destination for which a broken link is repaired locally
  // (MAX_REPAIR_TTL = 0.3 * NET_DIAMETER).
  [[nodiscard]] std::uint32_t max_repair_ttl() const { return (3 * net_diameter) / 10; }
};

// The schema: every parameter with unit, default, range and help. Durations that RFC 3561
// derives from others default to 0, meaning "derive as the RFC and ns-3 do".
std::vector<ParamSpec> parameter_schema();

// Typed values from validated parameters (defaults filled), deriving the 0 ("auto") durations.
AodvParameters parameters_from(const ParamSet& params);

}  // namespace swarmnet::aodv
