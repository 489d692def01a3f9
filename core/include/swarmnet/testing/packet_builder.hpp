// SDK test kit: packets and frames as the kernel would hand them to a plugin, built field by
// field in one expression:
//
//   Packet p = PacketBuilder().from(3).to(7).message(42).payload_bytes(100).hops(1).build();
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "swarmnet/packet.hpp"

namespace swarmnet::testing {

class PacketBuilder {
 public:
  PacketBuilder& uid(std::uint64_t value) {
    packet_.uid = value;
    return *this;
  }
  PacketBuilder& from(NodeId source) {
    packet_.source = source;
    return *this;
  }
  PacketBuilder& to(NodeId destination) {
    packet_.destination = destination;
    return *this;
  }
  PacketBuilder& broadcast() {
    packet_.destination = kBroadcast;
    return *this;
  }
  // An application message (a data packet); without it the packet is control.
  PacketBuilder& message(std::uint64_t id) {
    packet_.message_id = id;
    return *this;
  }
  PacketBuilder& sent_at(SimTime at) {
    packet_.sent_at = at;
    return *this;
  }
  PacketBuilder& hops(std::uint32_t value) {
    packet_.hops = value;
    return *this;
  }
  PacketBuilder& header(std::vector<std::uint8_t> bytes) {
    packet_.header = std::move(bytes);
    return *this;
  }
  // `count` application bytes of value `fill`.
  PacketBuilder& payload_bytes(std::size_t count, std::byte fill = std::byte{0}) {
    packet_.payload = std::make_shared<const Payload>(count, fill);
    return *this;
  }
  [[nodiscard]] Packet build() const { return packet_; }

 private:
  Packet packet_;
};

// A data frame carrying `packet` from `transmitter` to `receiver` (or kBroadcast), as a MAC's
// on_receive() sees it.
inline Frame data_frame(Packet packet, NodeId transmitter, NodeId receiver,
                        std::uint32_t header_bytes = 28, double bitrate_bps = 6e6) {
  Frame frame;
  frame.type = FrameType::data;
  frame.transmitter = transmitter;
  frame.receiver = receiver;
  frame.header_bytes = header_bytes;
  frame.bitrate_bps = bitrate_bps;
  frame.packet = std::move(packet);
  return frame;
}

// A control frame (ack, rts, cts) with no packet.
inline Frame control_frame(FrameType type, NodeId transmitter, NodeId receiver,
                           std::uint32_t bytes = 14) {
  Frame frame;
  frame.type = type;
  frame.transmitter = transmitter;
  frame.receiver = receiver;
  frame.header_bytes = bytes;
  return frame;
}

}  // namespace swarmnet::testing
