// The plugin ABI: what a plugin library exports and how the kernel recognises it.
//
// A plugin library exports exactly one C symbol, `swarmnet_plugin_entry`, returning a
// PluginEntry. The loader reads `abi_version` before touching anything else: only when it equals
// the kernel's kAbiVersion is `descriptor` interpreted. A plugin author never writes this by
// hand; the class declares its kind (by deriving from the kind's interface) and its info, and one
// line registers it:
//
//   class Flooding final : public swarmnet::Routing {
//    public:
//     static swarmnet::PluginInfo info();
//     explicit Flooding(const swarmnet::PluginArgs& args);
//     ...
//   };
//   SWARMNET_PLUGIN(Flooding)
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "swarmnet/params.hpp"

namespace swarmnet {

// Bumped whenever a change to any SDK header changes the layout or the virtual tables that a
// plugin and the kernel share. 3: RobotContext's ports, axle and arena; Physics::object_poses and
// Arena::objects. 4: world plugins, RobotContext's readings and requests. 5:
// RobotContext::show_state, WorldContext::show_object and hide_object (what the viewer draws).
// 6: Packet::protocol (ARP), RoutingContext::link_address_known. 7: RobotContext::neighbors.
// 8: send options and reports (RobotContext::send's options, send_reports; Packet::hop_limit;
// MacContext::acknowledged; Mac::acknowledges_unicasts). 9: RobotContext::route_to and
// Routing::route_to; RadioNeighbor's unicast exchanges; MacContext::gave_up. 10:
// RobotContext::sample, WorldContext::sample. 11: RobotContext::range_and_bearing and
// set_range_and_bearing_data.
inline constexpr std::uint32_t kAbiVersion = 11;

enum class PluginKind : std::uint8_t { physics, propagation, mac, routing, controller, world };

inline const char* to_string(PluginKind kind) {
  switch (kind) {
    case PluginKind::physics:
      return "physics";
    case PluginKind::propagation:
      return "propagation";
    case PluginKind::mac:
      return "mac";
    case PluginKind::routing:
      return "routing";
    case PluginKind::controller:
      return "controller";
    case PluginKind::world:
      return "world";
  }
  return "?";
}

// Root of every plugin object; the kernel destroys objects through it.
class Plugin {
 public:
  Plugin() = default;
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;
  Plugin(Plugin&&) = delete;
  Plugin& operator=(Plugin&&) = delete;
  virtual ~Plugin() = default;
};

// What a plugin says about itself: shown by `swarmnet plugins NAME` and used by the validator.
struct PluginInfo {
  std::string name;         // as written in scenarios: lower_snake_case
  std::string version;      // semantic version of the plugin
  std::string summary;      // one line
  std::string description;  // full text: model, assumptions, references
  std::vector<ParamSpec> params;
};

// What an instance is made from.
struct PluginArgs {
  ParamSet params;                // validated, defaults filled
  std::uint64_t seed = 0;         // this instance's own stream seed
  std::uint64_t shared_seed = 0;  // the same for every instance of this plugin in one run
  std::uint32_t instance = 0;     // robot/node index for per-robot and per-node plugins, else 0
  std::uint32_t instance_count = 1;
};

struct PluginDescriptor {
  PluginKind kind;
  PluginInfo info;
  std::function<std::unique_ptr<Plugin>(const PluginArgs&)> create;
};

extern "C" {
struct SwarmnetPluginEntry {
  std::uint32_t abi_version;
  const void* descriptor;  // const PluginDescriptor*, valid only when abi_version matches
};
}

inline constexpr const char* kPluginEntrySymbol = "swarmnet_plugin_entry";

template <typename PluginClass>
PluginDescriptor make_descriptor() {
  return PluginDescriptor{PluginClass::kKind, PluginClass::info(),
                          [](const PluginArgs& args) -> std::unique_ptr<Plugin> {
                            return std::make_unique<PluginClass>(args);
                          }};
}

}  // namespace swarmnet

// Registers PluginClass as this library's plugin. Use once per library, at namespace scope.
#define SWARMNET_PLUGIN(PluginClass)                                                          \
  extern "C" __attribute__((visibility("default"))) const ::swarmnet::SwarmnetPluginEntry*    \
  swarmnet_plugin_entry() {                                                                   \
    static const ::swarmnet::PluginDescriptor descriptor =                                    \
        ::swarmnet::make_descriptor<PluginClass>();                                           \
    static const ::swarmnet::SwarmnetPluginEntry entry{::swarmnet::kAbiVersion, &descriptor}; \
    return &entry;                                                                            \
  }
