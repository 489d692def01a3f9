// The ns-3 engine's set-up from a validated scenario's network settings: every plugin and key
// mapped onto ns-3's TypeIds and attributes through ns3_counterparts.hpp. The scenario check
// (scenario/ns3_engine_check.cpp) has refused what does not map, so this only translates.
#pragma once

#include "network/network_settings.hpp"
#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet {

// Throws std::invalid_argument naming the plugin or key when `settings` holds something the
// check would have refused (a scenario that bypassed it: settings built by hand).
[[nodiscard]] ns3engine::Config ns3_config_for(const NetworkSettings& settings);

}  // namespace swarmnet
