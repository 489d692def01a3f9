// What travels through the network half: packets (network layer) inside frames (MAC layer).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

// Bytes every packet carries below routing: an IPv4 (20) and a UDP (8) header, as in ns-3's
// application traffic and AODV control packets, so that frame sizes and airtimes match.
inline constexpr std::uint32_t kNetworkHeaderBytes = 28;

inline constexpr std::uint64_t kNoMessage = std::numeric_limits<std::uint64_t>::max();

// What a frame's MSDU is to the link layer. ARP packets are the kernel's own (network/arp.hpp):
// a MAC sends them like any packet, routing never sees them. An ARP packet carries no header or
// payload bytes, so its size is the 28 bytes of an ARP header for Ethernet and IPv4, which
// equals kNetworkHeaderBytes.
enum class LinkProtocol : std::uint8_t {
  ipv4,         // an IP packet: application data or a routing protocol's control packet
  arp_request,  // broadcast: who has `destination`? tell `source`
  arp_reply,    // unicast to the requester: `source` is here
};

using Payload = std::vector<std::byte>;

struct Packet {
  std::uint64_t uid = 0;    // unique in a run; copies made by forwarding keep it
  NodeId source = kNoNode;  // originator
  NodeId destination = kBroadcast;
  std::uint64_t message_id = kNoMessage;  // the application message carried; kNoMessage: control
  SimTime sent_at{};                      // when the originator's application handed it down
  // The controller port the message is for (swarmnet/controller.hpp). Carried beside the bytes,
  // not in them: it adds nothing to a frame's size. Routing copies it with the packet.
  std::uint16_t port = 0;
  std::uint32_t hops = 0;  // links traversed so far; the kernel counts them on reception
  // The sender's limit on links (SendOptions::hop_limit), 0 for none; carried beside the bytes
  // like `port`. Every routing plugin honours it: see may_travel_further().
  std::uint8_t hop_limit = 0;
  LinkProtocol protocol = LinkProtocol::ipv4;
  std::vector<std::uint8_t> header;        // the routing protocol's own header, serialised by it
  std::shared_ptr<const Payload> payload;  // application bytes (null for control packets)

  [[nodiscard]] bool is_control() const { return message_id == kNoMessage; }
  [[nodiscard]] bool is_arp() const { return protocol != LinkProtocol::ipv4; }
  // Whether a node that received this packet may relay it: false once it has crossed its
  // sender's hop_limit. A routing plugin then delivers it if it is for this node and relays it
  // no further (a broadcast has reached its scope: not a drop; a unicast for another node is
  // dropped as ttl_expired).
  [[nodiscard]] bool may_travel_further() const { return hop_limit == 0 || hops < hop_limit; }
  [[nodiscard]] std::uint32_t payload_bytes() const {
    return payload ? static_cast<std::uint32_t>(payload->size()) : 0U;
  }
  [[nodiscard]] std::uint32_t size_bytes() const {
    return kNetworkHeaderBytes + static_cast<std::uint32_t>(header.size()) + payload_bytes();
  }
};

enum class FrameType : std::uint8_t { data, ack, rts, cts };

struct Frame {
  FrameType type = FrameType::data;
  NodeId transmitter = kNoNode;
  NodeId receiver = kBroadcast;    // next hop, or kBroadcast
  std::uint32_t header_bytes = 0;  // MAC header and FCS
  double bitrate_bps = 0.0;        // rate of the payload part, for the PHY's error model
  std::uint16_t sequence = 0;
  bool retry = false;
  SimTime nav{};                 // duration field (virtual carrier sense), 0 if unused
  std::uint64_t uid = 0;         // unique per transmission; assigned by the kernel
  std::optional<Packet> packet;  // the MSDU, for data frames

  [[nodiscard]] std::uint32_t size_bytes() const {
    return header_bytes + (packet ? packet->size_bytes() : 0U);
  }
};

// Why a node discarded a packet. Every drop is traced and counted in summary.json.
enum class DropReason : std::uint8_t {
  no_route,        // routing has no route and will not find one
  queue_full,      // an interface or routing buffer was full
  ttl_expired,     // hop limit reached
  retry_limit,     // the MAC gave up after its retries
  buffer_timeout,  // waited too long for a route
  arp_queue_full,  // ARP's pending queue for the next hop was full (network/arp.hpp)
  arp_unresolved,  // the next hop answered no ARP request
};

inline const char* to_string(DropReason reason) {
  switch (reason) {
    case DropReason::no_route:
      return "no_route";
    case DropReason::queue_full:
      return "queue_full";
    case DropReason::ttl_expired:
      return "ttl_expired";
    case DropReason::retry_limit:
      return "retry_limit";
    case DropReason::buffer_timeout:
      return "buffer_timeout";
    case DropReason::arp_queue_full:
      return "arp_queue_full";
    case DropReason::arp_unresolved:
      return "arp_unresolved";
  }
  return "?";
}

}  // namespace swarmnet
