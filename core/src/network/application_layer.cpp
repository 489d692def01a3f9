#include "network/application_layer.hpp"

namespace swarmnet {

ApplicationLayer::ApplicationLayer(std::size_t node_count, NetworkMetrics& metrics,
                                   PacketTraceWriter& trace, PacketUidSource& uids,
                                   SendReports& reports)
    : metrics_(metrics), trace_(trace), uids_(uids), reports_(reports), seen_(node_count) {}

void ApplicationLayer::inject(const Message& message, SimTime now, Routing& source_routing) {
  Packet packet;
  packet.uid = uids_.take();
  packet.source = message.source;
  packet.destination = message.destination;
  packet.message_id = message.message_id;
  packet.sent_at = now;
  packet.port = message.port;
  packet.payload = message.payload;
  packet.hop_limit = message.hop_limit;
  if (message.report) reports_.expect(message.message_id, message.source, message.port);
  const bool broadcast = packet.destination == kBroadcast;
  metrics_.message_sent(broadcast);
  if (!broadcast) awaiting_.insert(packet.message_id);
  trace_.record(now, PacketEvent::send, packet.source, packet);
  if (packet.destination == packet.source) {
    if (message.report) reports_.met(packet.source, packet, SendOutcome::sent, now, packet.source);
    deliver(packet.source, packet, now);
    return;
  }
  source_routing.send(std::move(packet));
}

bool ApplicationLayer::deliver(NodeId receiver, const Packet& packet, SimTime now) {
  if (packet.is_control() || receiver >= seen_.size()) return false;
  auto& seen = seen_[receiver];
  // Forget messages older than the window (the set is ordered by sent_at).
  const std::int64_t horizon = (now - kDuplicateWindow).count();
  while (!seen.empty() && seen.begin()->first < horizon) seen.erase(seen.begin());
  if (!seen.emplace(packet.sent_at.count(), packet.message_id).second) {
    metrics_.duplicate_suppressed();
    return false;
  }

  if (packet.destination == kBroadcast) {
    metrics_.broadcast_delivered();
  } else if (receiver == packet.destination && awaiting_.erase(packet.message_id) == 1) {
    metrics_.unicast_delivered(now - packet.sent_at, packet.hops);
  }
  trace_.record(now, PacketEvent::deliver, receiver, packet);
  if (output_ != nullptr) {
    Delivery delivery;
    delivery.message_id = packet.message_id;
    delivery.source = packet.source;
    delivery.destination = packet.destination;
    delivery.receiver = receiver;
    delivery.sent_at = packet.sent_at;
    delivery.delivered_at = now;
    delivery.hops = packet.hops;
    delivery.port = packet.port;
    if (packet.payload) delivery.payload = *packet.payload;
    output_->push_back(std::move(delivery));
  }
  return true;
}

}  // namespace swarmnet
