// AODV control messages (RFC 3561 section 5), carried in Packet::header.
//
// Every message starts with its type byte; fields are in network byte order, node ids stand in
// for IPv4 addresses (4 bytes). Sizes equal the RFC's and ns-3's (type header included), so that
// airtimes match: RREQ 24, RREP 20, RERR 4 + 8 per destination, RREP-ACK 2 bytes.
//
//   RREQ     0 type=1 | 1 flags J R G D U | 2 ttl (*) | 3 hop count | 4 RREQ id | 8 destination |
//            12 destination seq | 16 originator | 20 originator seq
//   RREP     0 type=2 | 1 flags R A, prefix size (low 5 bits) | 2 ttl (*) | 3 hop count |
//            4 destination | 8 destination seq | 12 originator | 16 lifetime (ms)
//   RERR     0 type=3 | 1 flag N | 2 reserved | 3 destination count | then per destination:
//            destination, destination seq
//   RREP-ACK 0 type=4 | 1 reserved
//
// (*) The RFC's reserved bits carry the IP TTL of a RREQ or RREP, which ns-3 keeps in the IP
// header: SwarmNet's 28-byte network header (swarmnet/packet.hpp) has no TTL field of its own.
// A RREP's TTL is 0 (none) unless rrep_ip_ttl is set. Data packets carry no AODV header at all;
// their TTL is derived from Packet::hops.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "swarmnet/ids.hpp"

namespace swarmnet::aodv {

enum class MessageType : std::uint8_t { rreq = 1, rrep = 2, rerr = 3, rrep_ack = 4 };

struct Rreq {
  bool join = false;              // J (multicast, unused)
  bool repair = false;            // R (multicast, unused)
  bool gratuitous = false;        // G: an intermediate replier also informs the destination
  bool destination_only = false;  // D: only the destination may reply
  bool unknown_seq = false;       // U: destination sequence number unknown
  std::uint8_t ttl = 0;           // IP TTL (see above)
  std::uint8_t hop_count = 0;
  std::uint32_t id = 0;
  NodeId destination = kNoNode;
  std::uint32_t destination_seq = 0;
  NodeId originator = kNoNode;
  std::uint32_t originator_seq = 0;

  static constexpr std::size_t kSize = 24;
  friend bool operator==(const Rreq&, const Rreq&) = default;
};

struct Rrep {
  bool repair = false;        // R (multicast, unused)
  bool ack_required = false;  // A: the receiver answers with a RREP-ACK
  std::uint8_t prefix_size = 0;
  std::uint8_t ttl = 0;  // IP TTL (see above); 0: none
  std::uint8_t hop_count = 0;
  NodeId destination = kNoNode;
  std::uint32_t destination_seq = 0;
  NodeId originator = kNoNode;
  std::uint32_t lifetime_ms = 0;

  static constexpr std::size_t kSize = 20;
  // A HELLO is a RREP about its sender (destination == originator), sent with TTL 1.
  [[nodiscard]] bool is_hello() const { return destination == originator; }
  friend bool operator==(const Rrep&, const Rrep&) = default;
};

struct UnreachableDestination {
  NodeId destination = kNoNode;
  std::uint32_t seq = 0;
  friend bool operator==(const UnreachableDestination&, const UnreachableDestination&) = default;
};

struct Rerr {
  bool no_delete = false;  // N: a local repair is under way, do not delete the route
  std::vector<UnreachableDestination> destinations;

  static constexpr std::size_t kMaxDestinations = 255;
  [[nodiscard]] std::size_t size() const { return 4 + 8 * destinations.size(); }
  friend bool operator==(const Rerr&, const Rerr&) = default;
};

struct RrepAck {
  static constexpr std::size_t kSize = 2;
  friend bool operator==(const RrepAck&, const RrepAck&) = default;
};

using Message = std::variant<Rreq, Rrep, Rerr, RrepAck>;

// Replace `out` by the message's bytes.
void encode(const Rreq& message, std::vector<std::uint8_t>& out);
void encode(const Rrep& message, std::vector<std::uint8_t>& out);
void encode(const Rerr& message, std::vector<std::uint8_t>& out);
void encode(const RrepAck& message, std::vector<std::uint8_t>& out);
void encode(const Message& message, std::vector<std::uint8_t>& out);
[[nodiscard]] std::vector<std::uint8_t> encode(const Message& message);

// The message in `bytes`, or nothing if the type is unknown or the length does not match it.
[[nodiscard]] std::optional<Message> decode(std::span<const std::uint8_t> bytes);

}  // namespace swarmnet::aodv
