#include "network/node.hpp"

#include <utility>

#include "swarmnet/random.hpp"

namespace swarmnet {

Node::Node(NodeId id, const NodeServices& services, const PhyConfig& phy_config,
           const std::optional<ArpTimings>& arp, PluginInstance<Mac> mac,
           PluginInstance<Routing> routing)
    : id_(id),
      services_(services),
      phy_(phy_config, *this, &services.scheduler, derive_seed(services.phy_seed, {id})),
      mac_port_(*this),
      routing_port_(*this),
      arp_link_(*this),
      mac_(std::move(mac)),
      routing_(std::move(routing)) {
  if (arp) {
    arp_.emplace(id, *arp, services.scheduler, services.metrics,
                 derive_seed(services.arp_seed, {id}), arp_link_);
  }
}

void Node::attach() {
  mac_->attach(mac_port_);
  routing_->attach(routing_port_);
}

void Node::drop(const Packet& packet, DropReason reason) {
  if (services_.send_reports.awaiting()) {
    services_.send_reports.met(id_, packet, SendOutcome::dropped, services_.scheduler.now(),
                               kNoNode, 0, reason);
  }
  services_.metrics.dropped(reason);
  services_.trace.record(services_.scheduler.now(), PacketEvent::drop, id_, packet,
                         to_string(reason));
}

Packet Node::new_packet(NodeId destination) {
  Packet packet;
  packet.uid = services_.packet_uids.take();
  packet.source = id_;
  packet.destination = destination;
  packet.message_id = kNoMessage;
  packet.sent_at = services_.scheduler.now();
  return packet;
}

void Node::phy_collision(const Frame& frame) {
  if (frame.receiver == id_ || frame.receiver == kBroadcast) {
    services_.metrics.mac_count("collisions", 1);
  }
}

// ---- MacPort ----------------------------------------------------------------------------------

void Node::MacPort::count(std::string_view counter, std::uint64_t amount) {
  node_.services_.metrics.mac_count(counter, amount);
}

void Node::MacPort::transmit(Frame frame, SimTime duration) {
  SendReports& reports = node_.services_.send_reports;
  if (reports.awaiting() && frame.type == FrameType::data && frame.packet &&
      (frame.receiver == kBroadcast || !node_.mac_->acknowledges_unicasts())) {
    reports.met(node_.id_, *frame.packet, SendOutcome::sent, now(), frame.receiver);
  }
  node_.services_.metrics.frame_transmitted(frame.size_bytes());
  node_.services_.frames.record(node_.services_.scheduler.now(), node_.id_, frame);
  node_.services_.channel.transmit(node_.id_, std::move(frame), duration);
}

bool Node::MacPort::medium_busy() const { return node_.phy_.medium_busy(); }

void Node::MacPort::deliver(Packet packet, NodeId from) {
  if (packet.is_arp()) {
    // Only a node that runs ARP sends ARP frames, and then every node does.
    if (node_.arp_) node_.arp_->receive(packet);
    return;
  }
  ++packet.hops;
  node_.routing_->receive(std::move(packet), from);
}

void Node::MacPort::link_failed(const Packet& packet, NodeId next_hop) {
  node_.routing_->link_failed(packet, next_hop);
}

void Node::MacPort::drop(const Packet& packet, DropReason reason) {
  if (packet.is_arp()) {  // not an IP packet: counted as ARP's, not among packets.dropped
    node_.services_.metrics.arp_count("frames_dropped", 1);
    return;
  }
  node_.drop(packet, reason);
}

void Node::MacPort::acknowledged(const Packet& packet, NodeId next_hop, std::uint32_t attempts) {
  SendReports& reports = node_.services_.send_reports;
  if (reports.awaiting()) {
    reports.met(node_.id_, packet, SendOutcome::acknowledged, now(), next_hop, attempts);
  }
  if (NeighborTables* tables = node_.services_.neighbors) {
    tables->exchange_ended(node_.id_, next_hop, true, attempts, now());
  }
}

void Node::MacPort::gave_up(const Packet& /*packet*/, NodeId next_hop, std::uint32_t attempts) {
  if (NeighborTables* tables = node_.services_.neighbors) {
    tables->exchange_ended(node_.id_, next_hop, false, attempts, now());
  }
}

// ---- RoutingPort ------------------------------------------------------------------------------

void Node::RoutingPort::count(std::string_view counter, std::uint64_t amount) {
  node_.services_.metrics.routing_count(counter, amount);
}

Packet Node::RoutingPort::make_control_packet(NodeId destination) {
  return node_.new_packet(destination);
}

void Node::RoutingPort::send_to_mac(Packet packet, NodeId next_hop) {
  if (packet.is_control()) node_.services_.metrics.control_packet_sent(packet.size_bytes());
  if (node_.arp_ && next_hop != kBroadcast) {
    node_.arp_->send(std::move(packet), next_hop);
    return;
  }
  node_.mac_->enqueue(std::move(packet), next_hop);
}

bool Node::RoutingPort::link_address_known(NodeId neighbor) const {
  return !node_.arp_ || node_.arp_->resolved(neighbor);
}

// ---- ArpLink ----------------------------------------------------------------------------------

void Node::ArpLink::send_to_mac(Packet packet, NodeId next_hop) {
  node_.mac_->enqueue(std::move(packet), next_hop);
}

void Node::RoutingPort::deliver(const Packet& packet) {
  node_.services_.application.deliver(node_.id_, packet, now());
}

void Node::RoutingPort::drop(const Packet& packet, DropReason reason) {
  node_.drop(packet, reason);
}

void Node::RoutingPort::trace_forward(const Packet& packet) {
  if (!packet.is_control()) node_.services_.metrics.data_forwarded();
  node_.services_.trace.record(now(), PacketEvent::forward, node_.id_, packet);
}

}  // namespace swarmnet
