// The network engine a scenario's `network.engine` names, for a run's network half and for a
// replay alike.
#pragma once

#include <memory>
#include <ostream>

#include "network/network_engine.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// SwarmNet's own simulator (writing `packet_trace` and `frame_trace` when not null), or ns-3
// (which writes neither: the scenario check refuses output.packet_trace and output.frame_trace
// with it). Throws what the engine's set-up throws. `stop_requested`, when given, is polled by
// either engine inside every window (SwarmNet's every 4096 events, ns-3's every millisecond of
// simulated time); a true answer throws SimulationInterrupted.
[[nodiscard]] std::unique_ptr<NetworkEngine> make_network_engine(
    const Scenario& scenario, PluginLoader& loader, std::ostream* packet_trace,
    std::ostream* frame_trace = nullptr, bool (*stop_requested)() = nullptr);

}  // namespace swarmnet
