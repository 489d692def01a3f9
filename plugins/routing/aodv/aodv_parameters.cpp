#include "aodv_parameters.hpp"

#include <algorithm>

namespace swarmnet::aodv {

namespace {

constexpr double kDerived = 0.0;  // a duration of 0 means "derive it as RFC 3561 does"

std::uint32_t count_param(const ParamSet& params, const char* name) {
  return static_cast<std::uint32_t>(params.integer(name));
}

SimTime seconds_param(const ParamSet& params, const char* name) {
  return from_seconds(params.real(name));
}

// The parameter's value, or `derived` when it is 0.
SimTime derived_or(const ParamSet& params, const char* name, SimTime derived) {
  const SimTime value = seconds_param(params, name);
  return value == kTimeZero ? derived : value;
}

}  // namespace

std::vector<ParamSpec> parameter_schema() {
  constexpr double kDay = 86400.0;
  return {
      real_param("hello_interval_s", 1.0, "s", "HELLO emission interval (HELLO_INTERVAL)", 0.001,
                 kDay),
      integer_param("allowed_hello_loss", 2, "messages",
                    "HELLOs that may be missed before the link is taken for broken", 1, 1000),
      real_param("active_route_timeout_s", 3.0, "s",
                 "lifetime a route gets, or keeps at least, when it is used", 0.001, kDay),
      integer_param("net_diameter", 35, "hops", "largest hop count between two nodes", 1, 255),
      real_param("node_traversal_time_s", 0.040, "s",
                 "conservative one-hop traversal time, queueing and MAC included", 1e-6, 60.0),
      real_param("net_traversal_time_s", kDerived, "s",
                 "time to cross the network; 0: 2 * node_traversal_time_s * net_diameter", 0.0,
                 kDay),
      real_param("path_discovery_time_s", kDerived, "s",
                 "lifetime of RREQ ids in the cache; 0: 2 * net_traversal_time_s", 0.0, kDay),
      real_param("next_hop_wait_s", kDerived, "s",
                 "time to wait for a RREP-ACK; 0: node_traversal_time_s + 0.01", 0.0, kDay),
      real_param("my_route_timeout_s", kDerived, "s",
                 "lifetime in a destination's RREP; 0: 2 * max(path_discovery_time_s, "
                 "active_route_timeout_s)",
                 0.0, kDay),
      real_param("blacklist_timeout_s", kDerived, "s",
                 "how long RREQs from a neighbour that did not acknowledge a RREP are ignored; "
                 "0: rreq_retries * net_traversal_time_s",
                 0.0, kDay),
      real_param("delete_period_s", kDerived, "s",
                 "how long an invalid route is kept before deletion; 0: 5 * "
                 "max(active_route_timeout_s, hello_interval_s)",
                 0.0, kDay),
      integer_param("rreq_retries", 2, "requests",
                    "RREQs at the network diameter before the destination is given up", 0, 100),
      integer_param("rreq_rate_limit", 10, "1/s", "most RREQs a node originates per second", 1,
                    100000),
      integer_param("rerr_rate_limit", 10, "1/s", "most RERRs a node originates per second", 1,
                    100000),
      integer_param("ttl_start", 1, "hops", "TTL of the first RREQ of an expanding ring search", 1,
                    255),
      integer_param("ttl_increment", 2, "hops", "TTL added at each ring of the search", 1, 255),
      integer_param("ttl_threshold", 7, "hops",
                    "TTL beyond which the search uses net_diameter directly", 1, 255),
      integer_param("timeout_buffer", 2, "hops",
                    "extra hops in the ring traversal time, for congestion", 0, 255),
      integer_param("max_queue_len", 64, "packets",
                    "data packets buffered during route discovery; more drop the oldest "
                    "(queue_full)",
                    1, 1000000),
      real_param("max_queue_time_s", 30.0, "s",
                 "longest a packet waits for a route before it is dropped (buffer_timeout)", 0.001,
                 kDay),
      bool_param("destination_only", false, "RREQs carry the D flag: only the destination replies"),
      bool_param("gratuitous_reply", true,
                 "RREQs carry the G flag: an intermediate node that replies also sends a RREP to "
                 "the destination"),
      bool_param("enable_hello", true,
                 "send HELLO messages and detect broken links by their loss (false: neighbours "
                 "are still recorded from RREQs and data traffic and still expire, as in ns-3)"),
      bool_param("link_layer_feedback", true,
                 "take the MAC's report that it dropped a unicast frame to a neighbour "
                 "(link_failed: retry limit, and with dcf80211's link_failure_reports: "
                 "every_drop also a full queue or an expired wait) as a broken link; false: "
                 "such reports are counted and ignored"),
      text_param("link_failure_match", "neighbor_address",
                 "which link_failed() reports break a link. neighbor_address (ns-3.37): only a "
                 "report for a current neighbour whose link-layer address the ARP cache had "
                 "resolved when it was recorded or refreshed (ns-3 matches the dropped MPDU's "
                 "receiver address); a report for any other node, or a broadcast, breaks no "
                 "link. next_hop (SwarmNet before ARP, RFC 3561 6.11): a report breaks the "
                 "link to its next hop whether or not it is a known neighbour",
                 {"neighbor_address", "next_hop"}),
      bool_param("increment_seqno_on_break", true,
                 "a route that breaks or expires has its destination sequence number incremented "
                 "(RFC 3561 6.11), and a RERR's newer number is adopted; false: ns-3.37's rule, "
                 "the number stays as it was, so that any node with an equally fresh route may "
                 "answer the next RREQ"),
      bool_param("rreq_invalidates_sender_seqno", false,
                 "true: ns-3.37's rule (RecvRequest): a RREQ heard from a neighbour leaves the "
                 "route to that neighbour valid but without a valid sequence number (it takes "
                 "the RREQ's originator number), so that no node answers a RREQ for the "
                 "neighbour as an intermediate until a HELLO or a RREP from it gives one back; "
                 "false: the route keeps its number and its validity, which keeps routes loop "
                 "free (with true, a RREP with an equal number may replace the route)"),
      bool_param("rrep_over_invalid_reverse_route", false,
                 "true: ns-3.37's rule (RecvReply): a RREP is forwarded over any route to its "
                 "originator that is not in search, an invalid one included (it stays invalid; "
                 "its lifetime is extended to active_route_timeout_s, and the RREP goes to the "
                 "route's next hop over a valid route to that neighbour, or waits for one); "
                 "false: only over a valid reverse route (RFC 3561 6.7)"),
      bool_param("rrep_ip_ttl", false,
                 "true: ns-3.37's rule (SendReply, SendReplyByIntermediateNode, RecvReply): a "
                 "RREP leaves with an IP TTL of its sender's hop count to the originator (a "
                 "gratuitous RREP: to the destination), every forwarder takes one off, and one "
                 "that receives it with a TTL below 2 drops it (counted as rrep_ttl_drops); "
                 "false: a RREP is forwarded until it reaches its originator"),
      bool_param("rerr_to_valid_precursors", false,
                 "true: ns-3.37's rule (SendRerrMessage): a RERR is sent only if a precursor has "
                 "a valid route (a single precursor without one gets none), after a jitter of "
                 "whole milliseconds up to broadcast_jitter_max_s, and only RERRs unicast to a "
                 "single precursor count toward rerr_rate_limit; false: a RERR leaves at once, "
                 "a single precursor without a valid route is searched for, and every RERR "
                 "counts"),
      bool_param("queue_released_by_rrep_only", false,
                 "true: ns-3.37's rule (RecvReply, RouteRequestTimerExpire): packets buffered "
                 "for a destination leave only when a RREP for this node arrives or the "
                 "discovery timer fires with a valid route; a HELLO, a RREQ or any AODV message "
                 "that makes the route valid neither ends the discovery nor sends the buffer, so "
                 "new packets take the route at once and overtake them; false: any route that "
                 "becomes valid ends its discovery and sends its buffer"),
      bool_param("rreq_overwrites_reverse_route", false,
                 "true: ns-3.37's rule (RecvRequest): a new RREQ makes the node it came from the "
                 "next hop to its originator with the RREQ's hop count, whatever the freshness "
                 "of the route it replaces, and leaves the route's state as it was (an invalid "
                 "route stays invalid); the node answers as destination or intermediate even "
                 "over such a route, through the neighbour the RREQ came from; false: the "
                 "reverse route is updated only by a fresher RREQ (RFC 3561 6.2), which makes it "
                 "valid, and a node answers only over a valid reverse route"),
      bool_param("neighbor_route_forgets_seqno", false,
                 "true: ns-3.37's rule (UpdateRouteToNeighbor): an AODV message from a neighbour "
                 "whose route is not a one-hop route with a valid sequence number makes it a "
                 "valid one-hop route with sequence number 0, marked unknown, and no precursors "
                 "(any later RREP for the neighbour may then replace it); a one-hop route with a "
                 "valid number is left as it is, an invalid one included, and not refreshed "
                 "(ip_input_refreshes_routes does that in ns-3); false: the route keeps its "
                 "sequence number, marked known or not as before, and its precursors, becomes "
                 "valid and is refreshed, which keeps routes loop free"),
      bool_param("reply_seqno_plus_one_only", false,
                 "true: ns-3.37's rule (SendReply): a destination answering a RREQ increments "
                 "its sequence number only if the RREQ asks for exactly its number plus one, "
                 "and otherwise answers with its own number; false: it answers with the larger "
                 "of its own number and the one asked for (RFC 3561 6.6.1)"),
      bool_param("control_via_route_to_neighbor", false,
                 "true: ns-3.37's IP (SendTo, RouteOutput, Forwarding, IpForward): a unicast AODV "
                 "message (RREP, RERR, RREP-ACK) to a neighbour goes as an IP datagram along the "
                 "route to that neighbour, so where the route leads through another node that "
                 "node relays it, or drops it when its IP TTL runs out (a RERR's and a "
                 "RREP-ACK's is 1, a RREP's its hop count with rrep_ip_ttl, else data_ttl) or it "
                 "has no route "
                 "(with a RERR to the sender); the neighbour takes the message as coming from its "
                 "sender, whom it then holds for a neighbour; false: the message goes straight "
                 "to the neighbour"),
      bool_param("ip_input_refreshes_routes", false,
                 "true: ns-3.37's IP (RouteInput) before AODV reads a message: a broadcast one "
                 "refreshes the valid route to its sender for active_route_timeout_s, one "
                 "addressed to this node also the valid route to the next hop back toward its "
                 "sender and that neighbour's entry, as data for this node does; false: only "
                 "AODV's own rules refresh routes when a message is heard"),
      bool_param("rerr_covers_routes_in_any_state", false,
                 "true: ns-3.37's rule (SendRerrWhenBreaksLinkToNextHop, RecvError): a broken "
                 "link to a neighbour with a route in any state is reported for the neighbour "
                 "itself and every route through it, invalid and in-search ones included, and a "
                 "RERR is relayed for every destination it lists whose route in any state leads "
                 "through its sender, with the numbers it carried; the RERR goes to all those "
                 "routes' precursors, then the valid ones among them are invalidated; false: "
                 "only valid routes through the neighbour or the sender are reported and "
                 "invalidated (RFC 3561 6.11)"),
      bool_param("rrep_replaces_route", false,
                 "true: ns-3.37's rule (RecvReply): a RREP that updates the route to its "
                 "destination puts a new entry in its place, so the route's precursors are "
                 "forgotten (a later break reports to none of them), and a RREP for this node "
                 "replaces a route in search whatever its freshness; false: the RREP updates the "
                 "route's next hop, hop count, number and lifetime and its precursors stay, and "
                 "only a fresher RREP updates a route (RFC 3561 6.7)"),
      bool_param("rate_limited_requests_stack", false,
                 "true: ns-3.37's rule (SendRequest, DeferredRouteOutput): a RREQ refused by "
                 "rreq_rate_limit is scheduled on its own for just after the one-second window "
                 "turns, and every packet that finds no route in search asks again meanwhile, so "
                 "the refused requests pile up and each sends a RREQ when its turn comes, the "
                 "TTL rising and the retries counting with each (the window's limit still "
                 "holds); false: one refused request per destination waits for the next window, "
                 "and packets that arrive meanwhile wait with it"),
      bool_param("rrep_ends_search_only", false,
                 "true: ns-3.37's rule (RecvReply): a RREP for this node cancels the discovery "
                 "timer only if it finds the route in search, and sends the buffered packets "
                 "over the route as it stands after the update, whatever its state; a route "
                 "that a HELLO or another AODV message made valid first keeps its timer, and "
                 "if the route has broken when it fires the route is deleted, its sequence "
                 "number with it, and the packets waiting for it dropped; false: a RREP that "
                 "leaves the route valid ends the discovery and sends the buffer over it (RFC "
                 "3561 6.7)"),
      bool_param("lookups_age_all_routes", false,
                 "true: ns-3.37's rule (RoutingTable::Purge, which LookupRoute, LookupValidRoute, "
                 "AddRoute, DeleteRoute, GetListOfDestinationWithNextHop and "
                 "InvalidateRoutesWithDst call): every route lookup first ages every route of "
                 "the table, so an expired valid route becomes invalid, and starts its "
                 "delete_period_s, at the node's first lookup after it expired, whatever "
                 "destination that lookup is for, and an invalid route past its delete period is "
                 "deleted then; the table has no timer of its own (a neighbour's expiry lists the "
                 "routes through it, which ages them, as in ns-3); false: a route ages when it is "
                 "looked up itself, every route when the routes through a neighbour are listed, "
                 "and every hello_interval_s"),
      bool_param("enable_broadcast", true,
                 "rebroadcast application broadcasts (with duplicate detection and data_ttl)"),
      bool_param("enable_local_repair", false,
                 "repair a broken link near the destination instead of reporting it at once"),
      integer_param("local_add_ttl", 2, "hops", "TTL added to a local repair's RREQ", 0, 255),
      bool_param("rrep_ack_required", false,
                 "request a RREP-ACK for every RREP sent (ns-3 requests one only when an "
                 "intermediate node answers for its neighbour)"),
      integer_param("data_ttl", 64, "hops", "IP TTL of data packets (hops they may travel)", 1,
                    255),
      real_param("broadcast_jitter_max_s", 0.010, "s",
                 "largest random delay before a broadcast control packet (ns-3: 10 ms)", 0.0, 10.0),
      real_param("hello_start_jitter_max_s", 0.100, "s",
                 "largest random delay before a node's first HELLO", 0.0, kDay),
  };
}

AodvParameters parameters_from(const ParamSet& params) {
  AodvParameters p;
  p.hello_interval = seconds_param(params, "hello_interval_s");
  p.allowed_hello_loss = count_param(params, "allowed_hello_loss");
  p.active_route_timeout = seconds_param(params, "active_route_timeout_s");
  p.net_diameter = count_param(params, "net_diameter");
  p.node_traversal_time = seconds_param(params, "node_traversal_time_s");
  p.rreq_retries = count_param(params, "rreq_retries");
  p.net_traversal_time =
      derived_or(params, "net_traversal_time_s",
                 2 * p.node_traversal_time * static_cast<std::int64_t>(p.net_diameter));
  p.path_discovery_time = derived_or(params, "path_discovery_time_s", 2 * p.net_traversal_time);
  p.next_hop_wait =
      derived_or(params, "next_hop_wait_s", p.node_traversal_time + from_seconds(0.010));
  p.my_route_timeout = derived_or(params, "my_route_timeout_s",
                                  2 * std::max(p.path_discovery_time, p.active_route_timeout));
  p.blacklist_timeout =
      derived_or(params, "blacklist_timeout_s",
                 p.net_traversal_time * static_cast<std::int64_t>(std::max(p.rreq_retries, 1U)));
  p.delete_period =
      derived_or(params, "delete_period_s", 5 * std::max(p.active_route_timeout, p.hello_interval));
  p.rreq_rate_limit = count_param(params, "rreq_rate_limit");
  p.rerr_rate_limit = count_param(params, "rerr_rate_limit");
  p.ttl_start = count_param(params, "ttl_start");
  p.ttl_increment = count_param(params, "ttl_increment");
  p.ttl_threshold = count_param(params, "ttl_threshold");
  p.timeout_buffer = count_param(params, "timeout_buffer");
  p.max_queue_len = count_param(params, "max_queue_len");
  p.max_queue_time = seconds_param(params, "max_queue_time_s");
  p.destination_only = params.boolean("destination_only");
  p.gratuitous_reply = params.boolean("gratuitous_reply");
  p.enable_hello = params.boolean("enable_hello");
  p.link_layer_feedback = params.boolean("link_layer_feedback");
  p.link_failure_any_next_hop = params.text("link_failure_match") == "next_hop";
  p.increment_seqno_on_break = params.boolean("increment_seqno_on_break");
  p.rreq_invalidates_sender_seqno = params.boolean("rreq_invalidates_sender_seqno");
  p.rrep_over_invalid_reverse_route = params.boolean("rrep_over_invalid_reverse_route");
  p.rrep_ip_ttl = params.boolean("rrep_ip_ttl");
  p.rerr_to_valid_precursors = params.boolean("rerr_to_valid_precursors");
  p.queue_released_by_rrep_only = params.boolean("queue_released_by_rrep_only");
  p.rreq_overwrites_reverse_route = params.boolean("rreq_overwrites_reverse_route");
  p.neighbor_route_forgets_seqno = params.boolean("neighbor_route_forgets_seqno");
  p.reply_seqno_plus_one_only = params.boolean("reply_seqno_plus_one_only");
  p.control_via_route_to_neighbor = params.boolean("control_via_route_to_neighbor");
  p.ip_input_refreshes_routes = params.boolean("ip_input_refreshes_routes");
  p.rerr_covers_routes_in_any_state = params.boolean("rerr_covers_routes_in_any_state");
  p.rrep_replaces_route = params.boolean("rrep_replaces_route");
  p.rate_limited_requests_stack = params.boolean("rate_limited_requests_stack");
  p.rrep_ends_search_only = params.boolean("rrep_ends_search_only");
  p.lookups_age_all_routes = params.boolean("lookups_age_all_routes");
  p.enable_broadcast = params.boolean("enable_broadcast");
  p.enable_local_repair = params.boolean("enable_local_repair");
  p.local_add_ttl = count_param(params, "local_add_ttl");
  p.rrep_ack_required = params.boolean("rrep_ack_required");
  p.data_ttl = count_param(params, "data_ttl");
  p.broadcast_jitter_max = seconds_param(params, "broadcast_jitter_max_s");
  p.hello_start_jitter_max = seconds_param(params, "hello_start_jitter_max_s");
  return p;
}

}  // namespace swarmnet::aodv
