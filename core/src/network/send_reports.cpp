#include "network/send_reports.hpp"

namespace swarmnet {

void SendReports::expect(std::uint64_t message_id, NodeId source, std::uint16_t port) {
  awaiting_[message_id] = {source, port};
}

void SendReports::met(NodeId node, const Packet& packet, SendOutcome outcome, SimTime now,
                      NodeId next_hop, std::uint32_t attempts, DropReason reason) {
  // A relay's copy of the message is not its sender's business: only the source node reports.
  if (packet.source != node || packet.is_control() || packet.is_arp()) return;
  const auto it = awaiting_.find(packet.message_id);
  if (it == awaiting_.end()) return;
  AddressedSendReport& report = ready_.emplace_back();
  report.source = it->second.source;
  report.port = it->second.port;
  report.report.message_id = packet.message_id;
  report.report.outcome = outcome;
  report.report.reason = outcome == SendOutcome::dropped ? reason : DropReason::no_route;
  report.report.at = now;
  report.report.next_hop = outcome == SendOutcome::dropped ? kNoNode : next_hop;
  report.report.attempts = outcome == SendOutcome::acknowledged ? attempts : 0;
  awaiting_.erase(it);
}

void SendReports::collect(std::vector<AddressedSendReport>& out) {
  out.insert(out.end(), ready_.begin(), ready_.end());
  ready_.clear();
}

}  // namespace swarmnet
