#include "ideal_mac.hpp"

namespace swarmnet::ideal_mac {

PluginInfo IdealMac::info() {
  return PluginInfo{
      "ideal_mac",
      "1.0.0",
      "Contention-free MAC: FIFO queue, serialisation delay only, no ACK or retries",
      "Packets from routing wait in a FIFO interface queue of queue_limit packets (the frame on "
      "the air is not counted); a packet arriving at a full queue is dropped with reason "
      "queue_full. Frames leave one at a time, back to back, without carrier sense or backoff, "
      "each on the air for (header_bytes + packet bytes) * 8 / bitrate_bps seconds (rounded to "
      "the nanosecond). There is no acknowledgement and no retry: a unicast frame that its next "
      "hop does not hear is simply lost, and routing is not told. Received frames addressed to "
      "this node or broadcast go up to routing; others are ignored. Whether frames that overlap "
      "at a receiver survive is the PHY's decision (the threshold PHY keeps both).",
      {
          real_param("bitrate_bps", 6.0e6, "bit/s", "transmission rate of every frame", 1.0,
                     1.0e12),
          integer_param("header_bytes", 28, "B",
                        "MAC header and FCS added to every packet (802.11: 24 + 4)", 0, 65535),
          integer_param("queue_limit", 50, "packets",
                        "interface queue capacity; more waiting packets are dropped (queue_full)",
                        1, 1000000),
      }};
}

IdealMac::IdealMac(const PluginArgs& args)
    : bitrate_bps_(args.params.real("bitrate_bps")),
      header_bytes_(static_cast<std::uint32_t>(args.params.integer("header_bytes"))),
      queue_limit_(static_cast<std::size_t>(args.params.integer("queue_limit"))) {}

SimTime IdealMac::airtime(std::uint32_t packet_bytes) const {
  const double bits = 8.0 * static_cast<double>(header_bytes_ + packet_bytes);
  return from_seconds(bits / bitrate_bps_);
}

void IdealMac::enqueue(Packet packet, NodeId next_hop) {
  if (!transmitting_) {
    start(std::move(packet), next_hop);
    return;
  }
  if (queue_.size() >= queue_limit_) {
    context_->drop(packet, DropReason::queue_full);
    return;
  }
  queue_.emplace_back(std::move(packet), next_hop);
}

void IdealMac::start(Packet packet, NodeId next_hop) {
  Frame frame;
  frame.type = FrameType::data;
  frame.receiver = next_hop;
  frame.header_bytes = header_bytes_;
  frame.bitrate_bps = bitrate_bps_;
  frame.sequence = next_sequence_++;
  const SimTime duration = airtime(packet.size_bytes());
  frame.packet = std::move(packet);
  transmitting_ = true;
  context_->transmit(std::move(frame), duration);
}

void IdealMac::on_transmit_end() {
  transmitting_ = false;
  if (queue_.empty()) return;
  auto [packet, next_hop] = std::move(queue_.front());
  queue_.pop_front();
  start(std::move(packet), next_hop);
}

void IdealMac::on_receive(const Frame& frame, const RxInfo& /*info*/) {
  if (frame.type != FrameType::data || !frame.packet) return;
  if (frame.receiver != context_->node() && frame.receiver != kBroadcast) return;
  context_->deliver(*frame.packet, frame.transmitter);
}

}  // namespace swarmnet::ideal_mac

SWARMNET_PLUGIN(swarmnet::ideal_mac::IdealMac)
