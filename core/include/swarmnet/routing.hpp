// Routing plugins: one instance per node, between the application above and the MAC below.
#pragma once

#include "swarmnet/node_context.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/route.hpp"

namespace swarmnet {

class RoutingContext : public NodeContext {
 public:
  // A new control packet from this node, with a fresh uid, source = this node.
  virtual Packet make_control_packet(NodeId destination) = 0;
  // Hands `packet` to the MAC for `next_hop` (or kBroadcast). Call trace_forward() first when
  // relaying another node's packet.
  virtual void send_to_mac(Packet packet, NodeId next_hop) = 0;
  // Gives a packet addressed to this node (or broadcast) to the local application.
  virtual void deliver(const Packet& packet) = 0;
  // Discards a packet (traced and counted).
  virtual void drop(const Packet& packet, DropReason reason) = 0;
  // Records that this node relays `packet` (packet trace "forward" event).
  virtual void trace_forward(const Packet& packet) = 0;
  // Whether this node's ARP cache holds a usable link-layer address for `neighbor` now (an
  // alive, unexpired entry; always true with network.arp: static). ns-3's AODV can match a MAC's
  // failure report to a neighbour only through such an entry (aodv-neighbor's LookupMacAddress).
  [[nodiscard]] virtual bool link_address_known(NodeId neighbor) const = 0;

 protected:
  ~RoutingContext() = default;
};

class Routing : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::routing;

  // Called once before any traffic; the context outlives the plugin instance.
  virtual void attach(RoutingContext& context) = 0;
  // From the local application: originate `packet` (uid, source, destination, payload are set).
  virtual void send(Packet packet) = 0;
  // From the MAC: `packet` arrived from neighbour `from` (hops already counted).
  virtual void receive(Packet packet, NodeId from) = 0;
  // From the MAC: `next_hop` did not acknowledge `packet`.
  virtual void link_failed(const Packet& /*packet*/, NodeId /*next_hop*/) {}
  // What this node's protocol holds now for `destination` (another node): RouteStatus none,
  // valid (with next_hop and hops), or not_tracked for a protocol that keeps no routes (the
  // default). The kernel asks at the end of a network window for the destinations controllers
  // asked about (RobotContext::route_to) and sets Route::as_of. A query only reads: it must not
  // age, refresh or otherwise change the protocol's state, so that asking changes no result.
  [[nodiscard]] virtual Route route_to(NodeId /*destination*/) const { return Route{}; }
};

}  // namespace swarmnet
