#include "network/arp.hpp"

#include <cmath>
#include <utility>

namespace swarmnet {

Arp::Arp(NodeId self, const ArpTimings& timings, Scheduler& scheduler, NetworkMetrics& metrics,
         std::uint64_t seed, Link& link)
    : self_(self),
      cache_(timings),
      scheduler_(scheduler),
      metrics_(metrics),
      random_(seed),
      link_(link) {}

void Arp::send(Packet packet, NodeId next_hop) {
  switch (cache_.lookup(next_hop, packet, scheduler_.now())) {
    case ArpCache::Lookup::send:
      link_.send_to_mac(std::move(packet), next_hop);
      return;
    case ArpCache::Lookup::request: {
      // Only the first request of a resolution is jittered; retries leave at the timer's tick.
      const double jitter_ms =
          std::floor(random_.uniform(0.0, cache_.timings().request_jitter_max_ms));
      scheduler_.schedule_in(from_seconds(jitter_ms / 1000.0),
                             [this, next_hop] { send_request(next_hop); });
      start_timer_if_needed();
      return;
    }
    case ArpCache::Lookup::queued:
      return;
    case ArpCache::Lookup::drop_queue_full:
      link_.drop(packet, DropReason::arp_queue_full);
      return;
    case ArpCache::Lookup::drop_dead:
      link_.drop(packet, DropReason::arp_unresolved);
      return;
  }
}

void Arp::receive(const Packet& packet) {
  if (packet.destination != self_) return;  // a request for another node's address
  if (packet.protocol == LinkProtocol::arp_request) {
    send_reply(packet.source);
  } else if (packet.protocol == LinkProtocol::arp_reply) {
    reply_received(packet.source);
  }
}

bool Arp::resolved(NodeId neighbor) const { return cache_.resolved(neighbor, scheduler_.now()); }

Packet Arp::make_arp_packet(LinkProtocol protocol, NodeId destination) {
  Packet packet = link_.make_packet(destination);
  packet.protocol = protocol;
  return packet;
}

void Arp::send_request(NodeId neighbor) {
  metrics_.arp_count("requests_sent", 1);
  link_.send_to_mac(make_arp_packet(LinkProtocol::arp_request, neighbor), kBroadcast);
}

void Arp::send_reply(NodeId requester) {
  metrics_.arp_count("replies_sent", 1);
  link_.send_to_mac(make_arp_packet(LinkProtocol::arp_reply, requester), requester);
}

void Arp::reply_received(NodeId neighbor) {
  auto released = cache_.reply_received(neighbor, scheduler_.now());
  if (!released) {  // no request of ours is outstanding for it: ns-3 drops the reply
    metrics_.arp_count("replies_ignored", 1);
    return;
  }
  metrics_.arp_count("resolved", 1);
  for (Packet& packet : *released) link_.send_to_mac(std::move(packet), neighbor);
}

void Arp::start_timer_if_needed() {
  if (!cache_.timer_needed()) return;
  cache_.timer_started();
  scheduler_.schedule_in(cache_.timings().wait_reply_timeout, [this] { wait_reply_timeout(); });
}

void Arp::wait_reply_timeout() {
  const ArpCache::Timeout timeout = cache_.wait_reply_timeout(scheduler_.now());
  for (const NodeId neighbor : timeout.retry) send_request(neighbor);
  metrics_.arp_count("failed", timeout.died.size());
  for (const Packet& packet : timeout.dropped) link_.drop(packet, DropReason::arp_unresolved);
  start_timer_if_needed();
}

}  // namespace swarmnet
