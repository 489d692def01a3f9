#include "gossip.hpp"

#include <utility>

namespace example::gossip {

using namespace swarmnet;

PluginInfo Gossip::info() {
  return PluginInfo{
      "gossip",
      "1.0.0",
      "Gossip: flooding where each node relays a packet only with probability p",
      "The originator sends every packet as a MAC broadcast. A node that hears a packet for the "
      "first time (recognised by source and uid) delivers it if it is addressed to it or "
      "broadcast; unless it is the destination, it then relays it with probability p, after a "
      "random delay of up to jitter_max_s, while the packet has travelled fewer than hop_limit "
      "hops. Counters: routing.gossip_relays, routing.gossip_suppressed, routing.duplicates. "
      "Haas, Halpern and Li, 'Gossip-based ad hoc routing', INFOCOM 2002.",
      {
          real_param("p", 0.7, "", "probability that a node relays a packet it hears first", 0.0,
                     1.0),
          integer_param("hop_limit", 16, "hops", "packets are not relayed beyond this many hops", 1,
                        255),
          real_param("jitter_max_s", 0.005, "s", "largest random delay before a relay", 0.0, 1.0),
      }};
}

Gossip::Gossip(const PluginArgs& args)
    : probability_(args.params.real("p")),
      hop_limit_(static_cast<std::uint32_t>(args.params.integer("hop_limit"))),
      jitter_max_s_(args.params.real("jitter_max_s")),
      random_(args.seed) {}  // this node's own stream: runs are reproducible

void Gossip::send(Packet packet) {
  seen_.emplace(packet.source, packet.uid);  // our own copies coming back are not relayed
  context_->send_to_mac(std::move(packet), kBroadcast);
}

void Gossip::receive(Packet packet, NodeId /*from*/) {
  if (!seen_.emplace(packet.source, packet.uid).second) {
    context_->count("duplicates");
    return;
  }
  const NodeId self = context_->node();
  if (packet.destination == self || packet.destination == kBroadcast) context_->deliver(packet);
  if (packet.destination == self || packet.hops >= hop_limit_) return;
  if (!random_.bernoulli(probability_)) {
    context_->count("gossip_suppressed");
    return;
  }
  const SimTime delay = from_seconds(random_.uniform(0.0, jitter_max_s_));
  context_->schedule(delay,
                     [this, packet = std::move(packet)]() mutable { relay(std::move(packet)); });
}

void Gossip::relay(Packet packet) {
  context_->count("gossip_relays");
  context_->trace_forward(packet);
  context_->send_to_mac(std::move(packet), kBroadcast);
}

}  // namespace example::gossip

SWARMNET_PLUGIN(example::gossip::Gossip)
