#include "direct.hpp"

namespace swarmnet::direct {

PluginInfo Direct::info() {
  return PluginInfo{
      "direct",
      "1.1.0",
      "Single-hop delivery: every packet goes straight to its destination, nothing is relayed",
      "send() hands the packet to the MAC with the destination as next hop (a broadcast stays a "
      "MAC broadcast). A received packet is delivered if it is addressed to this node or "
      "broadcast, and otherwise ignored. No header, no control traffic, no parameters: the "
      "baseline against which multi-hop protocols are measured. route_to() answers its rule, "
      "not a measured link: a valid one-hop route to every other node.",
      {}};
}

Direct::Direct(const PluginArgs& /*args*/) {}

void Direct::send(Packet packet) {
  const NodeId next_hop = packet.destination;
  context_->send_to_mac(std::move(packet), next_hop);
}

Route Direct::route_to(NodeId destination) const {
  return Route{RouteStatus::valid, destination, 1, {}};
}

void Direct::receive(Packet packet, NodeId /*from*/) {
  if (packet.destination == context_->node() || packet.destination == kBroadcast) {
    context_->deliver(packet);
  }
}

}  // namespace swarmnet::direct

SWARMNET_PLUGIN(swarmnet::direct::Direct)
