// Routing `flooding` in ns-3: a small flooding protocol over UDP broadcast that behaves like
// SwarmNet's flooding plugin (plugins/routing/flooding/), written independently of it:
// - every packet is a UDP datagram to 255.255.255.255 carrying a 9-byte header (originator u32,
//   sequence u32, ttl u8, little-endian) and then the payload;
// - a node acts once on each (originator, sequence) pair, remembered in a FIFO cache of
//   `cache_size` entries; the originator records its own packets so that it never relays them;
// - the destination of a unicast message delivers it and does not relay it; for a broadcast
//   message every node delivers it and relays it; any other node relays it;
// - relaying decrements the ttl; a packet whose ttl would reach 0 is dropped instead;
// - a relay waits a delay drawn uniformly from [0, jitter_max_s] before it is sent.
// The IP destination is the broadcast address, so the message's destination travels out of band
// (the schedule, looked up by the message index in the payload), as in SwarmNet where it is a
// field of the packet whose bytes the 28-byte IPv4+UDP header stands for.
#pragma once

#include <ns3/node.h>
#include <ns3/ptr.h>
#include <ns3/random-variable-stream.h>
#include <ns3/socket.h>

#include <cstdint>
#include <set>
#include <vector>

#include "replay_endpoint.hpp"

namespace swarmnet::validation {

struct FloodingConfig {
  std::uint32_t ttl = 32;
  double jitter_max_s = 0.005;
  std::size_t cache_size = 4096;
};

struct FloodingCounters {
  std::uint64_t forwards = 0;
  std::uint64_t duplicates = 0;
  std::uint64_t ttl_expired = 0;
};

class FloodingEndpoint final : public ReplayEndpoint {
 public:
  static constexpr std::size_t kHeaderBytes = 9;

  FloodingEndpoint(ns3::Ptr<ns3::Node> node, std::uint32_t node_id, ReplayWorld& world,
                   const FloodingConfig& config, FloodingCounters& counters,
                   ns3::Ptr<ns3::UniformRandomVariable> jitter);

  void send(std::uint32_t index) override;

 private:
  // Records the pair; true if it had not been seen (FIFO eviction when full).
  bool remember(std::uint32_t originator, std::uint32_t sequence);
  void receive(ns3::Ptr<ns3::Socket> socket);
  void broadcast(const std::vector<std::uint8_t>& bytes);

  std::uint32_t node_id_;
  ReplayWorld& world_;
  FloodingConfig config_;
  FloodingCounters& counters_;
  ns3::Ptr<ns3::UniformRandomVariable> jitter_;
  ns3::Ptr<ns3::Socket> socket_;
  std::uint32_t next_sequence_ = 0;
  std::set<std::uint64_t> seen_;
  std::vector<std::uint64_t> seen_order_;  // ring in insertion order
  std::size_t seen_next_ = 0;
};

}  // namespace swarmnet::validation
