// `flooding` routing: every node relays every packet it sees for the first time, once.
#pragma once

#include <cstdint>

#include "duplicate_cache.hpp"
#include "flooding_header.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/routing.hpp"

namespace swarmnet::flooding {

class Flooding final : public Routing {
 public:
  static PluginInfo info();
  explicit Flooding(const PluginArgs& args);

  void attach(RoutingContext& context) override { context_ = &context; }
  void send(Packet packet) override;
  void receive(Packet packet, NodeId from) override;

 private:
  void forward(Packet packet);

  RoutingContext* context_ = nullptr;
  std::uint8_t ttl_;
  double jitter_max_s_;
  DuplicateCache cache_;
  RandomStream random_;
  std::uint32_t next_sequence_ = 0;
};

}  // namespace swarmnet::flooding
