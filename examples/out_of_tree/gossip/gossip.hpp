// `gossip` routing (an out-of-tree example): probabilistic flooding. The originator broadcasts;
// every node that hears a packet for the first time relays it with probability p.
#pragma once

#include <cstdint>
#include <set>
#include <utility>

#include "swarmnet/random.hpp"
#include "swarmnet/routing.hpp"

namespace example::gossip {

class Gossip final : public swarmnet::Routing {
 public:
  static swarmnet::PluginInfo info();
  explicit Gossip(const swarmnet::PluginArgs& args);

  void attach(swarmnet::RoutingContext& context) override { context_ = &context; }
  void send(swarmnet::Packet packet) override;
  void receive(swarmnet::Packet packet, swarmnet::NodeId from) override;

 private:
  void relay(swarmnet::Packet packet);

  swarmnet::RoutingContext* context_ = nullptr;
  double probability_;
  std::uint32_t hop_limit_;
  double jitter_max_s_;
  swarmnet::RandomStream random_;
  std::set<std::pair<swarmnet::NodeId, std::uint64_t>> seen_;  // (source, uid)
};

}  // namespace example::gossip
