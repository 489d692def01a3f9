#include "aodv.hpp"

#include <algorithm>
#include <utility>

namespace swarmnet::aodv {

namespace {

constexpr SimTime kRateWindow = std::chrono::seconds(1);
constexpr SimTime kRateRetryDelay = std::chrono::microseconds(100);
constexpr std::uint32_t kMaxHopCount = 255;

std::uint32_t to_ms(SimTime duration) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(duration).count();
  return static_cast<std::uint32_t>(std::clamp<std::int64_t>(ms, 0, UINT32_MAX));
}

SimTime from_ms(std::uint32_t ms) { return std::chrono::milliseconds(ms); }

// An IP TTL of `hops` (ns-3 stores a hop count of up to 16 bits in an 8-bit TTL tag; a count
// beyond 255 is clamped here rather than wrapped).
std::uint8_t ttl_of(std::uint32_t hops) {
  return static_cast<std::uint8_t>(std::min<std::uint32_t>(hops, 255));
}

// A delay of a whole number of milliseconds drawn uniformly from [0, largest] (ns-3.37 draws
// its AODV jitters as UniformRandomVariable::GetInteger(0, 10) ms and its first HELLO as
// GetInteger(0, 100) ms: two nodes that draw the same millisecond transmit together).
SimTime whole_ms_up_to(RandomStream& random, SimTime largest) {
  const auto slots = std::chrono::duration_cast<std::chrono::milliseconds>(largest).count() + 1;
  return std::chrono::milliseconds(random.below(static_cast<std::uint64_t>(slots)));
}

// Whether a message names only nodes of the network (0..node_count-1) where it must. The route
// table is indexed by node id, so a corrupt header naming another id is refused rather than
// stored: a RREQ's originator gets a reverse route and a RREP's destination a forward one; a
// RREP's originator is the node that asked for it. A RREQ may ask for any destination (it
// becomes a route only once answered, by a node that exists).
bool names_known_nodes(const Message& message, std::size_t node_count) {
  if (const auto* rreq = std::get_if<Rreq>(&message)) return rreq->originator < node_count;
  if (const auto* rrep = std::get_if<Rrep>(&message)) {
    return rrep->destination < node_count && rrep->originator < node_count;
  }
  return true;
}

const char* counter_name(const Message& message) {
  if (std::holds_alternative<Rreq>(message)) return "control_rreq";
  if (const auto* rrep = std::get_if<Rrep>(&message)) {
    return rrep->is_hello() ? "control_hello" : "control_rrep";
  }
  if (std::holds_alternative<Rerr>(message)) return "control_rerr";
  return "control_rrep_ack";
}

void merge(std::vector<NodeId>& into, const std::vector<NodeId>& from) {
  for (const NodeId node : from) {
    const auto it = std::lower_bound(into.begin(), into.end(), node);
    if (it == into.end() || *it != node) into.insert(it, node);
  }
}

}  // namespace

PluginInfo Aodv::info() {
  return PluginInfo{
      "aodv", "1.1.0",
      "Ad hoc On-Demand Distance Vector routing (RFC 3561) with ns-3's default parameters",
      "Routes are discovered on demand: a node without a route buffers the packet (max_queue_len "
      "packets, max_queue_time_s each; overflow drops the oldest as queue_full, expiry as "
      "buffer_timeout) and broadcasts a RREQ with an expanding ring search (ttl_start, "
      "ttl_increment up to ttl_threshold, then net_diameter, rreq_retries times; ring timeout "
      "2 * node_traversal_time * (ttl + timeout_buffer), then net_traversal_time with binary "
      "backoff). After the last attempt the buffered packets are dropped as no_route. Nodes "
      "relay a RREQ once (RREQ-id cache, path_discovery_time_s) and learn the reverse route; the "
      "destination, or an intermediate node with a fresh enough route (unless destination_only), "
      "answers with a RREP unicast along the reverse path, plus a gratuitous RREP to the "
      "destination when gratuitous_reply is set. Routes carry destination sequence numbers, hop "
      "counts, lifetimes and precursor lists; fresher information (higher sequence number, or "
      "equal and fewer hops) replaces older, never the reverse. HELLOs (a RREP about oneself, "
      "every hello_interval_s, TTL 1; only a RREQ sent or relayed in the interval stands in for "
      "one) maintain neighbours, as do RREQs heard and data forwarded or delivered (ns-3: "
      "forwarding keeps both neighbours alive), while every AODV message heard, a duplicate RREQ "
      "included, makes its sender a one-hop route (ns-3's RecvAodv). A neighbour not heard for "
      "allowed_hello_loss HELLO intervals (its lifetime; traffic gives active_route_timeout_s) "
      "expires; as in ns-3's neighbour list, expired neighbours are found at a purge, which "
      "runs hello_interval_s after the previous one, whenever a new neighbour is recorded and "
      "at every MAC report (without HELLOs, enable_hello: false, neighbours still come from "
      "RREQs and traffic and still expire, the first one recorded starting the purges). With "
      "link_layer_feedback, a MAC's link_failed() report (the MAC dropped a unicast frame to "
      "that next hop: retry limit, and with dcf80211's default also a full queue or an expired "
      "wait, ns-3's DroppedMpdu; an ARP packet's drop counts as any other) closes the "
      "neighbour as ns-3.37 does (link_failure_match: neighbor_address): only if it is in the "
      "neighbour list with a link-layer address the node's ARP cache had resolved when it was "
      "recorded or refreshed (kept once known); a report for any other node, or for an "
      "unresolved neighbour, breaks nothing (link_failure_match: next_hop breaks the link to "
      "any reported next hop, SwarmNet's rule before ARP). A broken link or an expired "
      "neighbour invalidates the routes through it with their sequence number incremented "
      "(unless increment_seqno_on_break is false, ns-3.37's rule), and a RERR goes to the "
      "precursors (unicast to a single one, broadcast otherwise), which do the same. RREQs and "
      "RERRs are rate-limited per second (windows of one second from 0 s); a refused RREQ is "
      "tried again 100 us after the window turns, once per destination (with "
      "rate_limited_requests_stack, ns-3.37's rule, once per packet or retry that asked); "
      "broadcast control packets wait a random jitter of a whole number of milliseconds up to "
      "broadcast_jitter_max_s drawn from the node's stream (the first HELLO likewise, up to "
      "hello_start_jitter_max_s). A unicast control message goes to its neighbour over a valid "
      "route to it (refreshing it); without one it waits in the buffer while a RREQ searches for "
      "that neighbour, as ns-3's IP routing of AODV's own messages does. A RREP answering for a "
      "neighbour carries the A flag (as in ns-3, which never starts the RREP-ACK timer); with "
      "rrep_ack_required every RREP must be acknowledged with a RREP-ACK within next_hop_wait_s "
      "or the neighbour is blacklisted (its RREQs ignored) for blacklist_timeout_s. Optional "
      "local repair "
      "(enable_local_repair): a node that loses the next hop of a forwarded data packet within "
      "0.3 * net_diameter hops of the destination buffers it and searches once with TTL "
      "max(route hops, hops from source / 2) + local_add_ttl before reporting the break. "
      "Application broadcasts are rebroadcast with duplicate detection while their hop count is "
      "below data_ttl (enable_broadcast) and their sender's hop limit "
      "(SendOptions::hop_limit). Data packets carry no AODV header; a unicast packet that has "
      "travelled data_ttl hops, or its sender's hop limit, is dropped as ttl_expired, one without "
      "a route at a relay "
      "as no_route (with a RERR to its source). Control messages have their RFC sizes; the "
      "RREQ's reserved byte carries its TTL. Counters (routing.*): control_rreq, control_rrep, "
      "control_rerr, control_rrep_ack, control_hello (transmissions, originated or relayed), "
      "route_discoveries, rreq_rate_limited (requests the rate limit put off), link_failures "
      "(MAC reports received), link_breaks (breaks that invalidated a route), blacklisted, "
      "local_repairs, duplicates, malformed (control "
      "messages that do not decode, or that name a node outside the network as a RREQ's "
      "originator, a RREP's destination or originator, or their datagram's source), "
      "rrep_ttl_drops (with rrep_ip_ttl). "
      "Departures from ns-3, all from RFC 3561 and each a parameter with ns-3.37's reading: "
      "every route update follows section 6.2 (ns-3 overwrites reverse routes unconditionally: "
      "rreq_overwrites_reverse_route; it makes a neighbour's route forget its sequence number: "
      "neighbor_route_forgets_seqno); a destination sets its sequence number to the maximum of "
      "its own and the RREQ's (6.6.1; reply_seqno_plus_one_only); link breaks increment the "
      "sequence numbers they report (6.11), and so do expiring routes "
      "(increment_seqno_on_break); a broken link or a RERR reports only valid routes (6.11), "
      "where ns-3 reports routes in any state (rerr_covers_routes_in_any_state); a RREP updates a "
      "route's fields and keeps its precursors, where ns-3 replaces the entry, precursors and all, "
      "and takes a RREP for itself over a route in search whatever its freshness "
      "(rrep_replaces_route); a RREP for this node ends its discovery and releases the buffer "
      "when it leaves the route valid, where ns-3 ends only a discovery whose route the RREP "
      "found in search and sends the buffer over the route whatever its state "
      "(rrep_ends_search_only); a route ages when it is looked up, listed or at a periodic "
      "purge, where ns-3 ages every route at every lookup (lookups_age_all_routes); a RREQ the "
      "rate limit refuses waits once per destination, where "
      "ns-3 schedules every refused request on its own (rate_limited_requests_stack); a unicast "
      "message goes straight to its neighbour, where "
      "ns-3's IP takes the route to it (control_via_route_to_neighbor), and only AODV's own "
      "rules refresh routes on a message heard, where ns-3's IP refreshes the sender's too "
      "(ip_input_refreshes_routes). One more, "
      "SwarmNet's own, for loop freedom: a RREQ leaves the route to the neighbour it came from "
      "with its sequence number, where ns-3 (and RFC 3561 6.5) mark the number unknown until the "
      "neighbour's next HELLO or RREP, so that meanwhile no node answers a RREQ for that "
      "neighbour and discoveries reach further (rreq_invalidates_sender_seqno: true). Four "
      "control-message rules of ns-3.37 are parameters too, RFC 3561's reading by default: a "
      "RREP forwarded over an invalid reverse route (rrep_over_invalid_reverse_route), a "
      "RREP's IP TTL (rrep_ip_ttl), RERRs only to precursors with a valid route and after a "
      "jitter (rerr_to_valid_precursors), and buffered packets sent only on a RREP or at the "
      "discovery timer (queue_released_by_rrep_only).",
      parameter_schema()};
}

Aodv::Aodv(const PluginArgs& args)
    : params_(parameters_from(args.params)),
      random_(args.seed),
      table_(params_.delete_period, params_.increment_seqno_on_break,
             params_.lookups_age_all_routes ? RouteAging::whole_table : RouteAging::per_entry),
      queue_(params_.max_queue_len, params_.max_queue_time,
             [this](const Packet& packet, DropReason reason) { context_->drop(packet, reason); }),
      rreq_ids_(params_.path_discovery_time),
      broadcast_ids_(params_.path_discovery_time) {}

void Aodv::attach(RoutingContext& context) {
  context_ = &context;
  self_ = context.node();
  table_.set_node_count(context.node_count());
  if (params_.enable_hello) {
    context_->schedule(whole_ms_up_to(random_, params_.hello_start_jitter_max),
                       [this] { hello_timer_expired(); });
    // ns-3 (Start) arms the neighbour timer only with HELLOs; without them the first neighbour
    // recorded arms it (purge_neighbors).
    neighbor_timer_ = context_->schedule(params_.hello_interval, [this] {
      neighbor_timer_ = kNoTimer;
      purge_neighbors();
    });
  }
  context_->schedule(params_.hello_interval, [this] { housekeeping(); });
}

// ---- data -------------------------------------------------------------------------------------

void Aodv::send(Packet packet) {
  if (packet.destination == kBroadcast) {
    broadcast_ids_.is_duplicate(packet, now());  // our own copies coming back are not relayed
    context_->send_to_mac(std::move(packet), kBroadcast);
    return;
  }
  if (packet.destination == self_) {
    context_->deliver(packet);
    return;
  }
  if (const RouteEntry* route = table_.find_valid(packet.destination, now())) {
    const RouteEntry copy = *route;
    transmit_data(std::move(packet), copy);
    return;
  }
  const NodeId destination = packet.destination;
  buffer(std::move(packet));
  if (!discovery_under_way(destination)) send_request(destination);
}

void Aodv::receive(Packet packet, NodeId from) {
  if (!packet.is_control()) {
    if (packet.destination == kBroadcast) {
      deliver_broadcast(std::move(packet));
    } else if (packet.destination == self_) {
      keep_source_routes_alive(packet);
      context_->deliver(packet);
    } else {
      forward_data(std::move(packet));
    }
    return;
  }
  std::optional<Message> message = decode(packet.header);
  // The datagram's source becomes a route too (the sender, with control_via_route_to_neighbor).
  if (!message || !names_known_nodes(*message, context_->node_count()) ||
      packet.source >= context_->node_count()) {
    context_->count("malformed");
    return;
  }
  if (params_.control_via_route_to_neighbor && packet.destination != kBroadcast &&
      packet.destination != self_) {
    relay_control(std::move(packet), std::move(*message));
    return;
  }
  // ns-3.37's AODV knows the sender by the datagram's IP source: the link sender, unless a
  // node relayed it (control_via_route_to_neighbor), and then it takes the originator for a
  // neighbour all the same.
  const NodeId sender = params_.control_via_route_to_neighbor ? packet.source : from;
  if (params_.ip_input_refreshes_routes) {
    // ns-3.37 (RouteInput), before AODV reads the datagram: a broadcast refreshes the route to
    // its sender, one for this node also the way back, as data for this node does.
    if (packet.destination == kBroadcast) {
      table_.refresh(packet.source, params_.active_route_timeout, now());
    } else {
      keep_source_routes_alive(packet);
    }
  }
  // ns-3.37 (RecvAodv) makes the sender a one-hop route on every AODV message it hears, before
  // looking at it: duplicate RREQs and copies of our own RREQs too. In a flood a node thus learns
  // a direct route to every neighbour that relays it, not only to the first (the neighbour table
  // is not touched: only HELLOs, new RREQs and traffic feed it).
  update_route_to_neighbor(sender);
  if (auto* rreq = std::get_if<Rreq>(&*message)) {
    receive_request(*rreq, sender);
  } else if (auto* rrep = std::get_if<Rrep>(&*message)) {
    receive_reply(*rrep, sender);
  } else if (auto* rerr = std::get_if<Rerr>(&*message)) {
    receive_error(*rerr, sender);
  } else {
    receive_ack(sender);
  }
}

void Aodv::deliver_broadcast(Packet packet) {
  if (broadcast_ids_.is_duplicate(packet, now())) {
    context_->count("duplicates");
    return;
  }
  context_->deliver(packet);
  // The sender's hop limit (Packet::hop_limit) ends a broadcast's scope as data_ttl does.
  if (!params_.enable_broadcast || packet.hops >= params_.data_ttl ||
      !packet.may_travel_further()) {
    return;
  }
  context_->trace_forward(packet);
  context_->send_to_mac(std::move(packet), kBroadcast);
}

void Aodv::forward_data(Packet packet) {
  if (packet.hops >= params_.data_ttl || !packet.may_travel_further()) {
    context_->drop(packet, DropReason::ttl_expired);
    return;
  }
  if (const RouteEntry* route = table_.find_valid(packet.destination, now())) {
    const RouteEntry to_destination = *route;
    keep_forwarding_routes_alive(packet, to_destination);
    transmit_data(std::move(packet), to_destination);
    return;
  }
  context_->drop(packet, DropReason::no_route);
  report_no_route(packet);
}

void Aodv::relay_control(Packet packet, Message message) {
  // ns-3.37: the datagram is for another node, so IP forwards it (RouteInput, Forwarding) as it
  // would data, and IpForward takes one off its TTL and drops it at 0. A RREP's TTL rides in
  // its reserved bits (rrep_ip_ttl; without it, data_ttl's); RERRs and RREP-ACKs leave with 1.
  if (packet.source == self_) return;  // our own datagram come back: IP discards it silently
  const RouteEntry* route = table_.find_valid(packet.destination, now());
  if (route == nullptr) {
    context_->drop(packet, DropReason::no_route);
    report_no_route(packet);
    return;
  }
  const RouteEntry to_destination = *route;
  keep_forwarding_routes_alive(packet, to_destination);
  auto* rrep = std::get_if<Rrep>(&message);
  if (rrep != nullptr && params_.rrep_ip_ttl) {
    // The TTL in the header is what this node received: one off, and nothing left at 0.
    if (rrep->ttl <= 1) {
      context_->drop(packet, DropReason::ttl_expired);
      return;
    }
    rrep->ttl = static_cast<std::uint8_t>(rrep->ttl - 1);
    packet.header.clear();
    encode(*rrep, packet.header);
  } else {
    // A TTL of `sent_ttl` lasts for sent_ttl - 1 relays: `hops` links so far means hops - 1
    // relays before this one.
    const std::uint32_t sent_ttl = rrep != nullptr ? params_.data_ttl : 1U;
    if (packet.hops >= sent_ttl) {
      context_->drop(packet, DropReason::ttl_expired);
      return;
    }
  }
  context_->trace_forward(packet);
  transmit_control(std::move(packet), to_destination);
}

void Aodv::keep_source_routes_alive(const Packet& packet) {
  // ns-3.37 (RouteInput, unicast local delivery): the route to the source, the next hop back to
  // it and that neighbour stay alive.
  table_.refresh(packet.source, params_.active_route_timeout, now());
  if (const RouteEntry* to_origin = table_.find_valid(packet.source, now())) {
    const NodeId previous_hop = to_origin->next_hop;
    table_.refresh(previous_hop, params_.active_route_timeout, now());
    update_neighbor(previous_hop, params_.active_route_timeout);
  }
}

void Aodv::keep_forwarding_routes_alive(const Packet& packet, const RouteEntry& to_destination) {
  const SimTime t = now();
  // RFC 3561 6.2: using a route keeps it, its next hop, the source and the previous hop alive,
  // even when IP then drops the packet (ns-3.37 Forwarding, before IpForward's TTL check).
  table_.refresh(to_destination.destination, params_.active_route_timeout, t);
  table_.refresh(to_destination.next_hop, params_.active_route_timeout, t);
  table_.refresh(packet.source, params_.active_route_timeout, t);
  const RouteEntry* to_origin = table_.find(packet.source, t);
  const NodeId previous_hop = to_origin != nullptr ? to_origin->next_hop : kNoNode;
  if (previous_hop != kNoNode) table_.refresh(previous_hop, params_.active_route_timeout, t);
  // ns-3.37 (Forwarding) also keeps both neighbours alive: a relay does not learn from
  // forwarding that its next hop has gone (only HELLO loss or the MAC tells it). The packet
  // goes out on the route it found even if a purge these updates trigger breaks it (ns-3 has
  // taken its Ipv4Route by then).
  update_neighbor(to_destination.next_hop, params_.active_route_timeout);
  if (previous_hop != kNoNode) update_neighbor(previous_hop, params_.active_route_timeout);
}

void Aodv::report_no_route(const Packet& packet) {
  // RFC 3561 6.11 case ii: a RERR to the source of a packet this node cannot forward.
  const SimTime t = now();
  const RouteEntry* stale = table_.find(packet.destination, t);
  const std::uint32_t seq = stale != nullptr && stale->valid_seq ? stale->seq : 0;
  // ns-3.37 (SendRerrWhenNoRouteToForward) checks the limit but does not count this RERR.
  const bool room = params_.rerr_to_valid_precursors
                        ? rerr_rate_has_room()
                        : rate_allows(rerr_count_, params_.rerr_rate_limit);
  if (!room) return;
  Rerr rerr;
  rerr.destinations.push_back({packet.destination, seq});
  if (const RouteEntry* to_origin = table_.find_valid(packet.source, t)) {
    send_control(rerr, to_origin->next_hop);
  } else {
    broadcast_control(rerr);
  }
}

void Aodv::transmit_data(Packet packet, const RouteEntry& route) {
  table_.refresh(route.destination, params_.active_route_timeout, now());
  table_.refresh(route.next_hop, params_.active_route_timeout, now());
  if (packet.source != self_) context_->trace_forward(packet);
  context_->send_to_mac(std::move(packet), route.next_hop);
}

void Aodv::buffer(Packet packet) {
  queue_.enqueue(std::move(packet), now());
  arm_queue_timer();
}

void Aodv::arm_queue_timer() {
  const SimTime expiry = queue_.next_expiry();
  if (expiry == kTimeNever || expiry >= queue_timer_at_) return;
  context_->cancel(queue_timer_);
  queue_timer_at_ = expiry;
  // purge() drops packets whose expiry is strictly before now.
  queue_timer_ = context_->schedule(expiry - now() + SimTime{1}, [this] {
    queue_timer_ = kNoTimer;
    queue_timer_at_ = kTimeNever;
    queue_.purge(now());
    arm_queue_timer();
  });
}

void Aodv::send_queued(NodeId destination) {
  for (Packet& packet : queue_.take(destination, now())) {
    const RouteEntry* route = table_.find_valid(destination, now());
    if (route == nullptr) {
      buffer(std::move(packet));
      continue;
    }
    const RouteEntry copy = *route;  // transmitting may change the table under `route`
    transmit_queued(std::move(packet), copy);
  }
}

void Aodv::send_queued_over(NodeId destination, const RouteEntry& route) {
  if (route.state == RouteState::in_search) return;
  const RouteEntry copy = route;  // transmitting may change the table under `route`
  for (Packet& packet : queue_.take(destination, now())) transmit_queued(std::move(packet), copy);
}

void Aodv::transmit_queued(Packet packet, const RouteEntry& route) {
  if (packet.is_control()) {
    transmit_control(std::move(packet), route);
  } else {
    transmit_data(std::move(packet), route);
  }
}

// ---- route discovery --------------------------------------------------------------------------

void Aodv::send_request(NodeId destination) {
  if (!rate_allows(rreq_count_, params_.rreq_rate_limit)) {
    defer_request(destination);
    return;
  }
  const SimTime t = now();
  Rreq rreq;
  rreq.destination = destination;
  std::uint32_t ttl = params_.ttl_start;
  RouteEntry* route = table_.find(destination, t);
  if (route != nullptr) {
    if (route->state != RouteState::in_search) {
      ttl = std::min(route->hop_count + params_.ttl_increment, params_.net_diameter);
    } else {
      ttl = route->hop_count + params_.ttl_increment;
      if (ttl > params_.ttl_threshold) ttl = params_.net_diameter;
    }
    if (ttl == params_.net_diameter) ++route->rreq_count;
    if (route->valid_seq) {
      rreq.destination_seq = route->seq;
    } else {
      rreq.unknown_seq = true;
    }
    route->hop_count = ttl;
    route->state = RouteState::in_search;
    route->expires = t + params_.path_discovery_time;
  } else {
    rreq.unknown_seq = true;
    RouteEntry entry;
    entry.destination = destination;
    entry.hop_count = ttl;
    entry.state = RouteState::in_search;
    entry.expires = t + params_.path_discovery_time;
    entry.rreq_count = ttl == params_.net_diameter ? 1 : 0;
    table_.insert(std::move(entry));
  }
  context_->count("route_discoveries");
  originate_request(rreq, ttl);
  schedule_request_retry(destination);
}

// A request the rate limit refuses is tried again just after the window turns (ns-3.37's
// SendRequest: the rate-limit timer's delay left + 100 us).
void Aodv::defer_request(NodeId destination) {
  context_->count("rreq_rate_limited");
  const SimTime delay = next_rate_window() - now() + kRateRetryDelay;
  if (params_.rate_limited_requests_stack) {
    // ns-3.37 schedules every refused request on its own, with no timer to cancel: each packet
    // and each retry that asked sends its own RREQ when the window turns.
    context_->schedule(delay, [this, destination] { send_request(destination); });
    return;
  }
  auto& timer = discovery_timers_[destination];
  context_->cancel(timer);
  timer = context_->schedule(delay, [this, destination] {
    discovery_timers_.erase(destination);
    send_request(destination);
  });
}

void Aodv::originate_request(Rreq rreq, std::uint32_t ttl) {
  rreq.gratuitous = params_.gratuitous_reply;
  rreq.destination_only = params_.destination_only;
  rreq.originator = self_;
  rreq.originator_seq = ++seq_;
  rreq.id = ++rreq_id_;
  rreq.ttl = static_cast<std::uint8_t>(std::min<std::uint32_t>(ttl, kMaxHopCount));
  // Our own request, heard back from a neighbour, is a duplicate (RFC 3561 6.3).
  rreq_ids_.is_duplicate(self_, rreq.id, now());
  broadcast_control(rreq);
}

void Aodv::schedule_request_retry(NodeId destination) {
  const RouteEntry* route = table_.find(destination, now());
  SimTime retry = params_.net_traversal_time;
  if (route != nullptr && route->hop_count < params_.net_diameter) {
    retry = 2 * params_.node_traversal_time *
            static_cast<std::int64_t>(route->hop_count + params_.timeout_buffer);
  } else if (route != nullptr && route->rreq_count > 0) {
    retry = params_.net_traversal_time * (std::int64_t{1} << std::min(route->rreq_count - 1, 20U));
  }
  auto& timer = discovery_timers_[destination];
  context_->cancel(timer);
  timer = context_->schedule(retry, [this, destination] { request_timer_expired(destination); });
}

void Aodv::request_timer_expired(NodeId destination) {
  discovery_timers_.erase(destination);
  RouteEntry* route = table_.find(destination, now());
  if (route != nullptr && route->is_valid()) {
    repairing_.erase(destination);
    send_queued(destination);
    return;
  }
  if (repairing_.erase(destination) > 0) {
    // A local repair gets one attempt; then the break is reported (RFC 3561 6.12).
    if (route != nullptr) {
      Rerr rerr;
      rerr.destinations.push_back({destination, route->seq});
      const std::vector<NodeId> precursors = route->precursors;
      route->state = RouteState::invalid;
      route->expires = now() + params_.delete_period;
      send_error(rerr, precursors);
    }
    give_up(destination);
    return;
  }
  if (route == nullptr || route->state != RouteState::in_search ||
      route->rreq_count >= std::max(params_.rreq_retries, 1U)) {
    give_up(destination);
    return;
  }
  send_request(destination);
}

void Aodv::give_up(NodeId destination) {
  if (const RouteEntry* route = table_.find(destination, now());
      route != nullptr && !route->is_valid()) {
    table_.erase(destination);
  }
  queue_.drop_destination(destination, DropReason::no_route, now());
}

bool Aodv::discovery_under_way(NodeId destination) {
  if (!params_.queue_released_by_rrep_only) return discovery_timers_.contains(destination);
  // ns-3.37 (DeferredRouteOutput) asks for a route unless the entry is in search. Without an
  // entry, SwarmNet's reading lets a waiting timer (a refused request's, or a retry's) stand for
  // the search; with rate_limited_requests_stack, as in ns-3, nothing does: every packet asks.
  const RouteEntry* route = table_.find(destination, now());
  if (route != nullptr) return route->state == RouteState::in_search;
  return !params_.rate_limited_requests_stack && discovery_timers_.contains(destination);
}

void Aodv::end_search_early(const RouteEntry& route) {
  if (route.state == RouteState::in_search && !params_.queue_released_by_rrep_only) {
    end_discovery(route.destination);
  }
}

void Aodv::release_buffer_early(NodeId destination) {
  if (!params_.queue_released_by_rrep_only && queue_.has(destination)) send_queued(destination);
}

void Aodv::end_discovery(NodeId destination) {
  if (const auto it = discovery_timers_.find(destination); it != discovery_timers_.end()) {
    context_->cancel(it->second);
    discovery_timers_.erase(it);
  }
  repairing_.erase(destination);
}

bool Aodv::start_local_repair(const Packet& packet, RouteEntry& route) {
  if (!params_.enable_local_repair || packet.is_control() || packet.source == self_ ||
      route.hop_count > params_.max_repair_ttl() || discovery_timers_.contains(route.destination)) {
    return false;
  }
  if (!rate_allows(rreq_count_, params_.rreq_rate_limit)) return false;
  const NodeId destination = route.destination;
  const std::uint32_t ttl = std::max(route.hop_count, packet.hops / 2) + params_.local_add_ttl;
  context_->count("local_repairs");
  route.state = RouteState::in_search;
  route.seq += 1;  // RFC 3561 6.12: the destination sequence number is incremented
  route.valid_seq = true;
  route.expires = now() + params_.path_discovery_time;
  repairing_.insert(destination);

  Rreq rreq;
  rreq.destination = destination;
  rreq.destination_seq = route.seq;
  originate_request(rreq, ttl);
  const SimTime wait =
      2 * params_.node_traversal_time * static_cast<std::int64_t>(ttl + params_.timeout_buffer);
  discovery_timers_[destination] =
      context_->schedule(wait, [this, destination] { request_timer_expired(destination); });
  return true;
}

// ---- control messages in ----------------------------------------------------------------------

bool Aodv::fresher(const RouteEntry& entry, std::uint32_t seq, std::uint32_t hops) {
  if (!entry.valid_seq) return true;
  if (seq_newer(seq, entry.seq)) return true;
  return seq == entry.seq && (!entry.is_valid() || hops < entry.hop_count);
}

void Aodv::update_route_to_neighbor(NodeId neighbor) {
  const SimTime t = now();
  RouteEntry* route = table_.find(neighbor, t);
  if (route == nullptr) {
    RouteEntry entry;
    entry.destination = neighbor;
    entry.next_hop = neighbor;
    entry.hop_count = 1;
    entry.expires = t + params_.active_route_timeout;
    table_.insert(std::move(entry));
    return;
  }
  if (params_.neighbor_route_forgets_seqno) {
    forget_neighbor_seqno(*route, neighbor);
    return;
  }
  if (route->is_valid() && route->hop_count == 1 && route->next_hop == neighbor) {
    route->expires = std::max(route->expires, t + params_.active_route_timeout);
    return;
  }
  end_search_early(*route);
  // The sequence number and its validity stay (ns-3 clears the validity, which lets any later
  // advertisement with the same number replace this route: a loop if it leads back through a
  // node that routes via this one).
  route->state = RouteState::valid;
  route->next_hop = neighbor;
  route->hop_count = 1;
  route->rreq_count = 0;
  route->expires = std::max(route->expires, t + params_.active_route_timeout);
  release_buffer_early(neighbor);
}

void Aodv::forget_neighbor_seqno(RouteEntry& route, NodeId neighbor) {
  // ns-3.37 (UpdateRouteToNeighbor) changes only a copy of a one-hop route with a valid number,
  // so such a route is left as it is: its lifetime too, and an invalid one stays invalid.
  if (route.valid_seq && route.hop_count == 1) return;
  // Any other route is replaced by a new one-hop entry: number 0, unknown, no precursors.
  end_search_early(route);
  route.seq = 0;
  route.valid_seq = false;
  route.state = RouteState::valid;
  route.next_hop = neighbor;
  route.hop_count = 1;
  route.rreq_count = 0;
  route.precursors.clear();
  route.expires = std::max(route.expires, now() + params_.active_route_timeout);
  release_buffer_early(neighbor);
}

void Aodv::overwrite_reverse_route(RouteEntry& to_origin, const Rreq& rreq, NodeId from,
                                   std::uint32_t hops, SimTime lifetime) {
  // ns-3.37 (RecvRequest): the number only grows, but the next hop and the hop count are the
  // RREQ's whatever they replace, and the state is left alone (an invalid route stays invalid,
  // one in search stays in search).
  if (!to_origin.valid_seq || seq_newer(rreq.originator_seq, to_origin.seq)) {
    to_origin.seq = rreq.originator_seq;
  }
  to_origin.valid_seq = true;
  to_origin.next_hop = from;
  to_origin.hop_count = hops;
  if (to_origin.state != RouteState::in_search) to_origin.rreq_count = 0;
  to_origin.expires = std::max(to_origin.expires, now() + lifetime);
}

void Aodv::receive_request(const Rreq& received, NodeId from) {
  const SimTime t = now();
  if (table_.is_blacklisted(from, t)) return;  // RFC 3561 6.8
  if (received.originator == self_ || rreq_ids_.is_duplicate(received.originator, received.id, t)) {
    return;
  }
  Rreq rreq = received;
  const std::uint32_t hops = std::uint32_t{rreq.hop_count} + 1;
  rreq.hop_count = static_cast<std::uint8_t>(std::min(hops, kMaxHopCount));

  // Reverse route to the originator (RFC 3561 6.5).
  const SimTime reverse_lifetime =
      std::max(kTimeZero, 2 * params_.net_traversal_time -
                              2 * static_cast<std::int64_t>(hops) * params_.node_traversal_time);
  RouteEntry* to_origin = table_.find(rreq.originator, t);
  if (to_origin == nullptr) {
    RouteEntry entry;
    entry.destination = rreq.originator;
    entry.next_hop = from;
    entry.hop_count = hops;
    entry.seq = rreq.originator_seq;
    entry.valid_seq = true;
    entry.expires = t + reverse_lifetime;
    to_origin = &table_.insert(std::move(entry));
  } else if (params_.rreq_overwrites_reverse_route) {
    overwrite_reverse_route(*to_origin, rreq, from, hops, reverse_lifetime);
  } else if (fresher(*to_origin, rreq.originator_seq, hops)) {
    end_search_early(*to_origin);
    to_origin->seq = rreq.originator_seq;
    to_origin->valid_seq = true;
    to_origin->next_hop = from;
    to_origin->hop_count = hops;
    to_origin->state = RouteState::valid;
    to_origin->rreq_count = 0;
    to_origin->expires = std::max(to_origin->expires, t + reverse_lifetime);
  } else if (to_origin->is_valid() && to_origin->next_hop == from) {
    to_origin->expires = std::max(to_origin->expires, t + reverse_lifetime);
  }
  if (params_.rreq_invalidates_sender_seqno) {
    // ns-3.37 (RecvRequest, after the reverse route): the route to the neighbour the RREQ came
    // from becomes a valid one-hop route for active_route_timeout with the RREQ's originator
    // sequence number, marked unknown. Until a HELLO or a RREP restores it, no node answers a
    // RREQ for that neighbour (an intermediate reply needs a valid number): the neighbour's own
    // reply is awaited. When the sender is the originator this is the reverse route itself.
    if (RouteEntry* to_sender = table_.find(from, t)) {
      to_sender->expires = t + params_.active_route_timeout;
      to_sender->valid_seq = false;
      to_sender->seq = rreq.originator_seq;
      to_sender->state = RouteState::valid;
      to_sender->hop_count = 1;
      to_sender->next_hop = from;
    }
  }
  // ns-3.37 (RecvRequest) records the sender as a neighbour after learning the reverse route,
  // with or without HELLOs. A purge this triggers never erases `to_origin` (it has just been
  // found at this instant), though it may invalidate it.
  update_neighbor(from, params_.hello_lifetime());
  if (to_origin->is_valid()) release_buffer_early(rreq.originator);
  // ns-3.37 answers over the reverse route whatever its state: the reply goes to the neighbour
  // the RREQ came from.
  const bool reverse_usable = params_.rreq_overwrites_reverse_route || to_origin->is_valid();

  if (rreq.destination == self_) {
    if (reverse_usable) reply_as_destination(rreq, *to_origin);
    return;
  }
  if (RouteEntry* to_destination = table_.find(rreq.destination, t)) {
    if (to_destination->next_hop == from) return;  // replying would make a loop
    const bool fresh_enough =
        rreq.unknown_seq || seq_not_older(to_destination->seq, rreq.destination_seq);
    if (fresh_enough && to_destination->valid_seq) {
      if (!rreq.destination_only && to_destination->is_valid() && reverse_usable) {
        reply_as_intermediate(rreq, *to_destination, *to_origin);
        return;
      }
      rreq.destination_seq = to_destination->seq;
      rreq.unknown_seq = false;
    }
  }
  if (rreq.ttl < 2 || hops >= kMaxHopCount) return;
  rreq.ttl = static_cast<std::uint8_t>(rreq.ttl - 1);
  broadcast_control(rreq);
}

void Aodv::receive_reply(Rrep rrep, NodeId from) {
  const std::uint32_t hops = std::uint32_t{rrep.hop_count} + 1;
  rrep.hop_count = static_cast<std::uint8_t>(std::min(hops, kMaxHopCount));
  if (rrep.is_hello()) {
    receive_hello(rrep);
    return;
  }
  const SimTime t = now();
  if (rrep.destination == self_) return;
  if (rrep.ack_required) send_control(RrepAck{}, from);

  // Forward route to the destination (RFC 3561 6.7).
  RouteEntry* to_destination = table_.find(rrep.destination, t);
  const bool was_in_search =
      to_destination != nullptr && to_destination->state == RouteState::in_search;
  // ns-3.37 (RecvReply) also takes a RREP for this node over a route in search, fresher or not.
  const bool replaces_search =
      params_.rrep_replaces_route && rrep.originator == self_ && was_in_search;
  if (to_destination == nullptr || replaces_search ||
      fresher(*to_destination, rrep.destination_seq, hops)) {
    if (to_destination == nullptr) {
      RouteEntry entry;
      entry.destination = rrep.destination;
      entry.expires = t + from_ms(rrep.lifetime_ms);  // never stored already expired
      to_destination = &table_.insert(std::move(entry));
    }
    to_destination->next_hop = from;
    to_destination->hop_count = hops;
    to_destination->seq = rrep.destination_seq;
    to_destination->valid_seq = true;
    to_destination->state = RouteState::valid;
    to_destination->rreq_count = 0;
    to_destination->expires = t + from_ms(rrep.lifetime_ms);
    // ns-3.37 puts a new entry in the route's place: the nodes that relied on it are forgotten.
    if (params_.rrep_replaces_route) to_destination->precursors.clear();
  }

  if (rrep.originator == self_) {
    if (params_.rrep_ends_search_only) {
      // ns-3.37 (RecvReply) cancels the discovery timer only for a route the RREP found in
      // search: one a HELLO made valid first keeps its timer, which deletes the route if it has
      // broken by then. The buffer leaves over the route as it stands, whatever its state.
      if (was_in_search) end_discovery(rrep.destination);
      send_queued_over(rrep.destination, *to_destination);
    } else if (to_destination->is_valid()) {
      end_discovery(rrep.destination);
      send_queued(rrep.destination);
    }
    return;
  }

  // No reverse route: drop. ns-3.37 forwards over any route not in search, an invalid one too.
  RouteEntry* to_origin = params_.rrep_over_invalid_reverse_route
                              ? table_.find(rrep.originator, t)
                              : table_.find_valid(rrep.originator, t);
  if (to_origin == nullptr || to_origin->state == RouteState::in_search || hops >= kMaxHopCount) {
    return;
  }
  to_origin->expires = std::max(to_origin->expires, t + params_.active_route_timeout);
  if (to_destination->is_valid()) {
    // Precursors (RFC 3561 6.7): each end learns who relies on it.
    const NodeId toward_origin = to_origin->next_hop;
    const NodeId toward_destination = to_destination->next_hop;
    to_destination->insert_precursor(toward_origin);
    to_origin->insert_precursor(toward_destination);
    if (RouteEntry* next = table_.find(toward_destination, t))
      next->insert_precursor(toward_origin);
    if (RouteEntry* prev = table_.find(toward_origin, t))
      prev->insert_precursor(toward_destination);
  }
  if (params_.rrep_ip_ttl) {
    // ns-3.37 checks the IP TTL after the routes are updated, as the last step before forwarding.
    if (rrep.ttl < 2) {
      context_->count("rrep_ttl_drops");
      return;
    }
    rrep.ttl = static_cast<std::uint8_t>(rrep.ttl - 1);
  }
  rrep.ack_required = false;
  send_reply(rrep, to_origin->next_hop);
}

void Aodv::receive_hello(const Rrep& hello) {
  const SimTime t = now();
  const NodeId neighbor = hello.destination;
  RouteEntry* route = table_.find(neighbor, t);
  if (route == nullptr) {
    RouteEntry entry;
    entry.destination = neighbor;
    entry.expires = t + from_ms(hello.lifetime_ms);
    route = &table_.insert(std::move(entry));
  } else {
    route->expires = std::max(route->expires, t + params_.hello_lifetime());
  }
  end_search_early(*route);
  if (!route->valid_seq || seq_not_older(hello.destination_seq, route->seq)) {
    route->seq = hello.destination_seq;
  }
  route->valid_seq = true;
  route->state = RouteState::valid;
  route->hop_count = 1;
  route->next_hop = neighbor;
  route->rreq_count = 0;
  if (params_.enable_hello) update_neighbor(neighbor, params_.hello_lifetime());
  release_buffer_early(neighbor);
}

void Aodv::receive_error(const Rerr& rerr, NodeId from) {
  if (rerr.no_delete) return;  // a repair is under way upstream; routes stay
  if (params_.rerr_covers_routes_in_any_state) {
    relay_error_any_state(rerr, from);
    return;
  }
  const SimTime t = now();
  Rerr relay;
  std::vector<NodeId> precursors;
  for (const UnreachableDestination& d : rerr.destinations) {
    RouteEntry* route = table_.find_valid(d.destination, t);
    if (route == nullptr || route->next_hop != from) continue;
    adopt_reported_seqno(*route, d.seq);
    table_.invalidate(*route, t);
    merge(precursors, route->precursors);
    relay.destinations.push_back({d.destination, route->seq});
  }
  if (!relay.destinations.empty()) send_error(relay, precursors);
}

// ns-3.37's RecvError: every listed destination whose route, in any state, leads through the
// RERR's sender is reported on, with the number the RERR gave it, to that route's precursors;
// the RERR leaves before the valid ones among those routes are invalidated.
void Aodv::relay_error_any_state(const Rerr& rerr, NodeId from) {
  const SimTime t = now();
  Rerr relay;
  std::vector<NodeId> precursors;
  for (const UnreachableDestination& d : rerr.destinations) {
    RouteEntry* route = table_.find(d.destination, t);
    if (route == nullptr || route->next_hop != from) continue;
    if (route->is_valid()) adopt_reported_seqno(*route, d.seq);
    merge(precursors, route->precursors);
    relay.destinations.push_back(d);
  }
  if (relay.destinations.empty()) return;
  send_error(relay, precursors);
  invalidate_listed(relay);
}

void Aodv::invalidate_listed(const Rerr& rerr) {
  const SimTime t = now();
  for (const UnreachableDestination& d : rerr.destinations) {
    if (RouteEntry* route = table_.find_valid(d.destination, t)) table_.invalidate(*route, t);
  }
}

void Aodv::receive_ack(NodeId from) {
  const auto it = ack_timers_.find(from);
  if (it == ack_timers_.end()) return;
  context_->cancel(it->second);
  ack_timers_.erase(it);
}

// ---- control messages out ---------------------------------------------------------------------

void Aodv::reply_as_destination(const Rreq& rreq, const RouteEntry& to_origin) {
  if (params_.reply_seqno_plus_one_only) {
    // ns-3.37 (SendReply): one more only when exactly one more is asked for.
    if (!rreq.unknown_seq && rreq.destination_seq == seq_ + 1) ++seq_;
  } else if (!rreq.unknown_seq && seq_newer(rreq.destination_seq, seq_)) {
    // RFC 3561 6.6.1: at least the sequence number the originator asked for.
    seq_ = rreq.destination_seq;
  }
  Rrep rrep;
  rrep.destination = self_;
  rrep.destination_seq = seq_;
  rrep.originator = rreq.originator;
  rrep.lifetime_ms = to_ms(params_.my_route_timeout);
  rrep.ack_required = params_.rrep_ack_required;
  if (params_.rrep_ip_ttl) rrep.ttl = ttl_of(to_origin.hop_count);
  send_reply(rrep, to_origin.next_hop);
}

void Aodv::reply_as_intermediate(const Rreq& rreq, RouteEntry& to_destination,
                                 RouteEntry& to_origin) {
  const SimTime t = now();
  Rrep rrep;
  rrep.hop_count = static_cast<std::uint8_t>(std::min(to_destination.hop_count, kMaxHopCount));
  rrep.destination = to_destination.destination;
  rrep.destination_seq = to_destination.seq;
  rrep.originator = to_origin.destination;
  rrep.lifetime_ms = to_ms(to_destination.expires - t);
  // ns-3: answering for a neighbour, the link may be unidirectional; ask for an acknowledgement.
  rrep.ack_required = params_.rrep_ack_required || to_destination.hop_count == 1;
  if (params_.rrep_ip_ttl) rrep.ttl = ttl_of(to_origin.hop_count);
  to_destination.insert_precursor(to_origin.next_hop);
  to_origin.insert_precursor(to_destination.next_hop);
  send_reply(rrep, to_origin.next_hop);
  if (rreq.gratuitous) {
    Rrep gratuitous;
    gratuitous.hop_count = static_cast<std::uint8_t>(std::min(to_origin.hop_count, kMaxHopCount));
    gratuitous.destination = to_origin.destination;
    gratuitous.destination_seq = to_origin.seq;
    gratuitous.originator = to_destination.destination;
    gratuitous.lifetime_ms = to_ms(to_origin.expires - t);
    if (params_.rrep_ip_ttl) gratuitous.ttl = ttl_of(to_destination.hop_count);
    send_control(gratuitous, to_destination.next_hop);
  }
}

void Aodv::send_reply(const Rrep& rrep, NodeId next_hop) {
  Rrep out = rrep;
  out.ack_required = out.ack_required || params_.rrep_ack_required;
  // ns-3.37 sets the A flag when it answers for a neighbour but never starts the RREP-ACK timer,
  // so it never blacklists: only rrep_ack_required arms it.
  if (params_.rrep_ack_required && !ack_timers_.contains(next_hop)) {
    ack_timers_[next_hop] = context_->schedule(params_.next_hop_wait, [this, next_hop] {
      ack_timers_.erase(next_hop);
      table_.blacklist(next_hop, now() + params_.blacklist_timeout);
      context_->count("blacklisted");
    });
  }
  send_control(out, next_hop);
}

void Aodv::send_hello() {
  Rrep hello;
  hello.destination = self_;
  hello.destination_seq = seq_;
  hello.originator = self_;
  hello.lifetime_ms = to_ms(params_.hello_lifetime());
  broadcast_control(hello);
}

void Aodv::send_error(const Rerr& rerr, const std::vector<NodeId>& precursors) {
  if (precursors.empty()) return;
  for (std::size_t first = 0; first < rerr.destinations.size(); first += Rerr::kMaxDestinations) {
    Rerr part;
    part.no_delete = rerr.no_delete;
    const std::size_t last = std::min(rerr.destinations.size(), first + Rerr::kMaxDestinations);
    part.destinations.assign(rerr.destinations.begin() + static_cast<std::ptrdiff_t>(first),
                             rerr.destinations.begin() + static_cast<std::ptrdiff_t>(last));
    if (params_.rerr_to_valid_precursors) {
      if (!rerr_rate_has_room()) return;
      send_error_to_valid_precursors(part, precursors);
      continue;
    }
    if (!rate_allows(rerr_count_, params_.rerr_rate_limit)) return;
    if (precursors.size() == 1) {
      send_control(part, precursors.front());
    } else {
      broadcast_control(part);
    }
  }
}

void Aodv::send_error_to_valid_precursors(const Rerr& part, const std::vector<NodeId>& precursors) {
  const SimTime t = now();
  if (precursors.size() == 1) {
    const NodeId precursor = precursors.front();
    if (table_.find_valid(precursor, t) == nullptr) return;
    ++rerr_count_;
    // The route is looked up again when the jitter ends, as ns-3's socket does.
    context_->schedule(jitter(), [this, part, precursor] { send_control(part, precursor); });
    return;
  }
  const bool any_valid = std::any_of(precursors.begin(), precursors.end(), [&](NodeId node) {
    return table_.find_valid(node, t) != nullptr;
  });
  if (any_valid) broadcast_control(part);
}

void Aodv::send_control(const Message& message, NodeId next_hop) {
  Packet packet = context_->make_control_packet(next_hop);
  encode(message, packet.header);
  if (next_hop == kBroadcast) {
    context_->count(counter_name(message));
    context_->send_to_mac(std::move(packet), kBroadcast);
    return;
  }
  // ns-3.37 sends a unicast control message to a neighbour through its IP stack, whose route
  // lookup is AODV's own (RouteOutput): a valid route to the neighbour is used and refreshed like
  // any other; without one the message waits in the request queue while a RREQ searches for the
  // neighbour (on the dense grid row most of ns-3's discoveries are such searches).
  if (const RouteEntry* route = table_.find_valid(next_hop, now())) {
    const RouteEntry copy = *route;
    transmit_control(std::move(packet), copy);
    return;
  }
  buffer(std::move(packet));
  if (!discovery_under_way(next_hop)) send_request(next_hop);
}

void Aodv::transmit_control(Packet packet, const RouteEntry& route) {
  table_.refresh(route.destination, params_.active_route_timeout, now());
  table_.refresh(route.next_hop, params_.active_route_timeout, now());
  if (const std::optional<Message> message = decode(packet.header)) {
    context_->count(counter_name(*message));
  }
  // The message is for the neighbour itself. By default it goes to it directly even when its
  // route now leads through another node; with control_via_route_to_neighbor (ns-3.37's IP) it
  // takes that route, and the node there relays it (relay_control).
  const NodeId next_hop =
      params_.control_via_route_to_neighbor ? route.next_hop : packet.destination;
  context_->send_to_mac(std::move(packet), next_hop);
}

void Aodv::broadcast_control(const Message& message) {
  // ns-3.37 notes a broadcast for the HELLO rule only when it sends or relays a RREQ.
  if (std::holds_alternative<Rreq>(message)) last_broadcast_ = now();
  context_->schedule(jitter(), [this, message] { send_control(message, kBroadcast); });
}

// ---- link breakage ----------------------------------------------------------------------------

// The MAC dropped `packet`, a unicast MPDU to `next_hop` (ns-3's DroppedMpdu: retry limit, full
// queue or expired wait alike; an ARP packet too). ns-3.37 (NotifyTxError, ProcessTxError)
// closes the neighbour whose link-layer address is the MPDU's receiver, then purges: a next hop
// that is not a neighbour, or whose address the ARP cache had not resolved when it was recorded,
// breaks nothing, and neither does a broadcast; expired neighbours are reported all the same.
Route Aodv::route_to(NodeId destination) const {
  // Read as stored: a lookup would age the table, and asking must change nothing. A valid entry
  // past its lifetime is what the next lookup turns invalid, so it counts as none already.
  const RouteEntry* entry = table_.entry(destination);
  if (entry == nullptr || !entry->is_valid() || entry->expires < context_->now()) {
    return Route{RouteStatus::none, kNoNode, 0, {}};
  }
  return Route{RouteStatus::valid, entry->next_hop, entry->hop_count, {}};
}

void Aodv::link_failed(const Packet& packet, NodeId next_hop) {
  context_->count("link_failures");
  if (!params_.link_layer_feedback) return;
  if (params_.link_failure_any_next_hop) {
    // SwarmNet's rule before ARP (RFC 3561 6.11): any report breaks the link to its next hop.
    if (next_hop == kBroadcast) return;
    neighbors_.close(next_hop);
    const bool listed = neighbors_.expiry(next_hop) != kTimeZero;
    purge_neighbors(&packet, next_hop);
    if (!listed) link_broken(next_hop, &packet);
    return;
  }
  if (next_hop != kBroadcast) neighbors_.close_by_address(next_hop);
  purge_neighbors(&packet, next_hop);
}

void Aodv::update_neighbor(NodeId neighbor, SimTime lifetime) {
  const bool resolved = context_->link_address_known(neighbor);
  if (neighbors_.update(neighbor, lifetime, now(), resolved)) purge_neighbors();
}

void Aodv::purge_neighbors(const Packet* failed, NodeId failed_hop) {
  if (neighbors_.empty()) return;
  for (const NodeId broken : neighbors_.purge(now())) {
    link_broken(broken, broken == failed_hop ? failed : nullptr);
  }
  context_->cancel(neighbor_timer_);
  neighbor_timer_ = context_->schedule(params_.hello_interval, [this] {
    neighbor_timer_ = kNoTimer;
    purge_neighbors();
  });
}

void Aodv::link_broken(NodeId neighbor, const Packet* failed) {
  if (params_.rerr_covers_routes_in_any_state) {
    report_routes_via(neighbor, failed);
    return;
  }
  const SimTime t = now();
  std::vector<UnreachableDestination> unreachable = table_.valid_destinations_via(neighbor, t);
  if (unreachable.empty()) return;
  context_->count("link_breaks");
  Rerr rerr;
  std::vector<NodeId> precursors;
  for (const UnreachableDestination& d : unreachable) {
    RouteEntry* route = table_.find_valid(d.destination, t);
    if (route == nullptr) continue;
    if (repaired_locally(failed, *route)) continue;
    increment_broken_seqno(*route);
    table_.invalidate(*route, t);
    merge(precursors, route->precursors);
    rerr.destinations.push_back({d.destination, route->seq});
  }
  if (!rerr.destinations.empty()) send_error(rerr, precursors);
}

// ns-3.37's SendRerrWhenBreaksLinkToNextHop: nothing without a route to the neighbour; else the
// RERR lists the neighbour, whatever its route's next hop, and every route through it in any
// state, and goes to all their precursors before the valid ones are invalidated. A valid route
// that a local repair takes over is left out, as in link_broken.
void Aodv::report_routes_via(NodeId neighbor, const Packet* failed) {
  const SimTime t = now();
  const RouteEntry* to_neighbor = table_.find(neighbor, t);
  if (to_neighbor == nullptr) return;
  std::vector<UnreachableDestination> listed = table_.destinations_via(neighbor, t);
  const auto at = std::lower_bound(
      listed.begin(), listed.end(), neighbor,
      [](const UnreachableDestination& d, NodeId node) { return d.destination < node; });
  if (at == listed.end() || at->destination != neighbor) {
    listed.insert(at, {neighbor, to_neighbor->seq});
  }
  Rerr rerr;
  std::vector<NodeId> precursors;
  bool breaks_a_route = false;  // link_breaks counts breaks that end a valid route
  for (const UnreachableDestination& d : listed) {
    RouteEntry* route = table_.find(d.destination, t);
    if (route == nullptr) continue;
    if (route->is_valid()) {
      breaks_a_route = true;
      if (repaired_locally(failed, *route)) continue;
      increment_broken_seqno(*route);
    }
    merge(precursors, route->precursors);
    rerr.destinations.push_back({d.destination, route->seq});
  }
  if (breaks_a_route) context_->count("link_breaks");
  if (rerr.destinations.empty()) return;
  send_error(rerr, precursors);
  invalidate_listed(rerr);
}

bool Aodv::repaired_locally(const Packet* failed, RouteEntry& route) {
  // Only a data packet is repaired: never a control or an ARP packet.
  if (failed == nullptr || failed->is_control() || failed->is_arp() ||
      failed->destination != route.destination || !start_local_repair(*failed, route)) {
    return false;
  }
  buffer(*failed);
  return true;
}

void Aodv::increment_broken_seqno(RouteEntry& route) const {
  if (!params_.increment_seqno_on_break) return;  // RFC 3561 6.11; ns-3.37 keeps the number
  route.seq += 1;
  route.valid_seq = true;
}

void Aodv::adopt_reported_seqno(RouteEntry& route, std::uint32_t seq) const {
  // ns-3.37 (RecvError) ignores the numbers a RERR carries.
  if (!params_.increment_seqno_on_break) return;
  if (seq_newer(seq, route.seq) || !route.valid_seq) {
    route.seq = seq;
    route.valid_seq = true;
  }
}

// Forgets expired RREQ ids (memory only) and lets the route table keep itself
// (RoutingTable::housekeep: its blacklist, and its routes unless lookups age them). Neighbours
// have their own timer (purge_neighbors).
void Aodv::housekeeping() {
  const SimTime t = now();
  table_.housekeep(t);
  rreq_ids_.purge(t);
  context_->schedule(params_.hello_interval, [this] { housekeeping(); });
}

// ---- timers -----------------------------------------------------------------------------------

void Aodv::hello_timer_expired() {
  // ns-3: a broadcast since the last tick stands in for the HELLO.
  SimTime offset = kTimeZero;
  if (last_broadcast_ != kTimeNever) {
    offset = now() - last_broadcast_;
  } else {
    send_hello();
  }
  last_broadcast_ = kTimeNever;
  context_->schedule(std::max(kTimeZero, params_.hello_interval - offset),
                     [this] { hello_timer_expired(); });
}

void Aodv::turn_rate_window() {
  const std::int64_t window = now().count() / kRateWindow.count();
  if (window != rate_window_) {
    rate_window_ = window;
    rreq_count_ = 0;
    rerr_count_ = 0;
  }
}

bool Aodv::rate_allows(std::uint32_t& counter, std::uint32_t limit) {
  turn_rate_window();
  if (counter >= limit) return false;
  ++counter;
  return true;
}

bool Aodv::rerr_rate_has_room() {
  turn_rate_window();
  return rerr_count_ < params_.rerr_rate_limit;
}

SimTime Aodv::next_rate_window() const {
  return kRateWindow * (now().count() / kRateWindow.count() + 1);
}

SimTime Aodv::jitter() { return whole_ms_up_to(random_, params_.broadcast_jitter_max); }

}  // namespace swarmnet::aodv

SWARMNET_PLUGIN(swarmnet::aodv::Aodv)
