// Each node's endpoint for the robots' messages: one UDP socket on port 9 that sends a message's
// payload bytes and reports each message its application receives as an Arrival. Which message
// a packet is travels in its MessageTag, never in the payload, which is the robot's own bytes.
#pragma once

#include <ns3/ipv4-address.h>
#include <ns3/node.h>
#include <ns3/ptr.h>
#include <ns3/random-variable-stream.h>
#include <ns3/socket.h>

#include <cstdint>
#include <set>
#include <vector>

#include "ns3_engine/ns3_counters.hpp"
#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {

class MessageTag;

// What every endpoint shares. `arrivals` is set only while a window runs.
struct EndpointWorld {
  std::vector<ns3::Ipv4Address> addresses;  // by node id
  std::uint16_t port = 9;
  std::vector<Arrival>* arrivals = nullptr;
  Counts* counts = nullptr;

  // Reports `tag`'s message at `receiver` now (not at its own source).
  void arrive(const MessageTag& tag, std::uint32_t receiver, std::uint32_t hops) const;
};

class Endpoint {
 public:
  Endpoint() = default;
  Endpoint(const Endpoint&) = delete;
  Endpoint& operator=(const Endpoint&) = delete;
  Endpoint(Endpoint&&) = delete;
  Endpoint& operator=(Endpoint&&) = delete;
  virtual ~Endpoint() = default;

  // Hands `message` (whose source is this endpoint's node) to the network now.
  virtual void send(const Message& message) = 0;
};

// Routing `direct`, `aodv`, `olsr` and `dsdv`: a message is one UDP datagram to the
// destination's address (255.255.255.255 for a broadcast), its payload exactly the message's.
// With static routing on one subnet that is one hop; with a routing protocol the IP layer finds
// the route. Hops come from the received IP TTL.
class DatagramEndpoint final : public Endpoint {
 public:
  DatagramEndpoint(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
                   const EndpointWorld& world);

  void send(const Message& message) override;

 private:
  void receive(ns3::Ptr<ns3::Socket> socket);

  std::uint32_t node_id_;
  const EndpointWorld& world_;
  ns3::Ptr<ns3::Socket> socket_;
};

// Routing `flooding`, as SwarmNet's flooding plugin (plugins/routing/flooding/) and the ns-3
// replay (tests/validation/flooding_endpoint.hpp) do it: every packet is a UDP broadcast of a
// 9-byte header (originator u32, sequence u32, ttl u8, little-endian) and the payload; a node acts
// once on each (originator, sequence), remembered in a FIFO cache (the originator remembers its
// own); the destination delivers and does not relay, for a broadcast every node delivers and
// relays, any other node relays; a relay decrements the ttl (a packet whose ttl would reach 0 is
// dropped instead) and waits a delay drawn uniformly from [0, jitter_max_s].
class FloodingEndpoint final : public Endpoint {
 public:
  static constexpr std::uint32_t kHeaderBytes = 9;

  FloodingEndpoint(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
                   const EndpointWorld& world, const FloodingParams& params,
                   const ns3::Ptr<ns3::UniformRandomVariable>& jitter);

  void send(const Message& message) override;

 private:
  // Records the pair; true if it had not been seen (FIFO eviction when full).
  bool remember(std::uint32_t originator, std::uint32_t sequence);
  void receive(ns3::Ptr<ns3::Socket> socket);
  void broadcast(const std::vector<std::uint8_t>& bytes, const MessageTag& tag);

  std::uint32_t node_id_;
  const EndpointWorld& world_;
  FloodingParams params_;
  ns3::Ptr<ns3::UniformRandomVariable> jitter_;
  ns3::Ptr<ns3::Socket> socket_;
  std::uint32_t next_sequence_ = 0;
  std::set<std::uint64_t> seen_;
  std::vector<std::uint64_t> seen_order_;  // ring in insertion order
  std::size_t seen_next_ = 0;
};

}  // namespace swarmnet::ns3engine
