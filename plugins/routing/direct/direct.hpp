// `direct` routing: one hop, no relaying. A packet reaches its destination only if the
// destination hears the source.
#pragma once

#include "swarmnet/routing.hpp"

namespace swarmnet::direct {

class Direct final : public Routing {
 public:
  static PluginInfo info();
  explicit Direct(const PluginArgs& args);

  void attach(RoutingContext& context) override { context_ = &context; }
  void send(Packet packet) override;
  void receive(Packet packet, NodeId from) override;
  [[nodiscard]] Route route_to(NodeId destination) const override;

 private:
  RoutingContext* context_ = nullptr;
};

}  // namespace swarmnet::direct
