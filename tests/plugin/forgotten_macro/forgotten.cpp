// A complete routing plugin class, except that nobody wrote SWARMNET_PLUGIN(Forgotten).
#include "swarmnet/sdk.hpp"

namespace {

class Forgotten final : public swarmnet::Routing {
 public:
  static swarmnet::PluginInfo info() {
    return swarmnet::PluginInfo{"forgotten", "1.0.0", "a plugin without its registration", "", {}};
  }
  explicit Forgotten(const swarmnet::PluginArgs& /*args*/) {}
  void attach(swarmnet::RoutingContext& /*context*/) override {}
  void send(swarmnet::Packet /*packet*/) override {}
  void receive(swarmnet::Packet /*packet*/, swarmnet::NodeId /*from*/) override {}
};

}  // namespace

// Referenced so the class is compiled and its vtable emitted, as in a real plugin.
__attribute__((visibility("default"))) bool forgotten_plugin_is_routing() {
  return Forgotten::info().name == "forgotten";
}
