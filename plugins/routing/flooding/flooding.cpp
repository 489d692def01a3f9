#include "flooding.hpp"

#include <utility>

namespace swarmnet::flooding {

PluginInfo Flooding::info() {
  return PluginInfo{
      "flooding",
      "1.0.0",
      "Blind flooding with duplicate detection, TTL and random rebroadcast jitter",
      "The originator sends every packet as a MAC broadcast with a 9-byte header (originator, "
      "sequence number, ttl). A node that receives a packet it has not seen before (by "
      "originator and sequence, in a FIFO cache of cache_size entries) acts on it once: the "
      "destination of a unicast packet delivers it and does not relay it; for a broadcast packet "
      "every node delivers it and relays it; any other node relays it. Relaying decrements the "
      "ttl; a packet whose ttl would reach 0 is dropped (ttl_expired) instead, so a packet "
      "travels at most `ttl` hops. A packet that has crossed its sender's hop limit "
      "(SendOptions::hop_limit) is relayed no further: a broadcast is then delivered and left "
      "there, a unicast for another node dropped as ttl_expired. A relay waits a delay drawn "
      "uniformly from [0, jitter_max_s] "
      "from the node's own random stream before it is handed to the MAC, to spread neighbours' "
      "rebroadcasts. Later copies are discarded (counted as routing.duplicates); packets with a "
      "header of the wrong size are discarded as routing.malformed.",
      {
          integer_param("ttl", 32, "hops", "hops a packet may travel from its originator", 1, 255),
          real_param("jitter_max_s", 0.005, "s", "largest random delay before a rebroadcast", 0.0,
                     10.0),
          integer_param(
              "cache_size", 4096, "packets",
              "(originator, sequence) pairs remembered for duplicate detection (FIFO; memory "
              "grows with the pairs held, 24 to 48 bytes each, not with this limit)",
              1, 10000000),
      }};
}

Flooding::Flooding(const PluginArgs& args)
    : ttl_(static_cast<std::uint8_t>(args.params.integer("ttl"))),
      jitter_max_s_(args.params.real("jitter_max_s")),
      cache_(static_cast<std::size_t>(args.params.integer("cache_size"))),
      random_(args.seed) {}

void Flooding::send(Packet packet) {
  const FloodingHeader header{context_->node(), next_sequence_++, ttl_};
  cache_.insert(header.originator, header.sequence);  // our own copies come back: not relayed
  encode(header, packet.header);
  context_->send_to_mac(std::move(packet), kBroadcast);
}

void Flooding::receive(Packet packet, NodeId /*from*/) {
  std::optional<FloodingHeader> header = decode(packet.header);
  if (!header) {
    context_->count("malformed");
    return;
  }
  if (!cache_.insert(header->originator, header->sequence)) {
    context_->count("duplicates");
    return;
  }
  if (packet.destination == context_->node()) {
    context_->deliver(packet);
    return;
  }
  if (packet.destination == kBroadcast) context_->deliver(packet);
  if (!packet.may_travel_further()) {
    // The sender's hop limit: a broadcast has reached its scope; a unicast cannot reach its
    // destination.
    if (packet.destination != kBroadcast) context_->drop(packet, DropReason::ttl_expired);
    return;
  }
  if (header->ttl <= 1) {
    context_->drop(packet, DropReason::ttl_expired);
    return;
  }
  --header->ttl;
  encode(*header, packet.header);
  const SimTime jitter = from_seconds(random_.uniform(0.0, jitter_max_s_));
  context_->schedule(
      jitter, [this, relayed = std::move(packet)]() mutable { forward(std::move(relayed)); });
}

void Flooding::forward(Packet packet) {
  context_->trace_forward(packet);
  context_->send_to_mac(std::move(packet), kBroadcast);
}

}  // namespace swarmnet::flooding

SWARMNET_PLUGIN(swarmnet::flooding::Flooding)
