// Routing `direct` and `aodv`: a message is one UDP datagram to the destination's IPv4 address
// (or to 255.255.255.255 for a broadcast message). With static routing on one subnet that is a
// single hop, like SwarmNet's `direct`; with ns-3's AODV installed the IP layer finds the route.
#pragma once

#include <ns3/node.h>
#include <ns3/ptr.h>
#include <ns3/socket.h>

#include "replay_endpoint.hpp"

namespace swarmnet::validation {

class DatagramEndpoint final : public ReplayEndpoint {
 public:
  DatagramEndpoint(ns3::Ptr<ns3::Node> node, std::uint32_t node_id, ReplayWorld& world);

  void send(std::uint32_t index) override;

 private:
  void receive(ns3::Ptr<ns3::Socket> socket);

  std::uint32_t node_id_;
  ReplayWorld& world_;
  ns3::Ptr<ns3::Socket> socket_;
};

}  // namespace swarmnet::validation
