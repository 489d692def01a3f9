// The network engine a scenario's `network.engine` names, for a run's network half and for a
// replay alike.
#pragma once

#include <memory>
#include <ostream>

#include "network/network_engine.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// Where the network engine writes its traces; each may be null (not written).
struct NetworkTraceStreams {
  std::ostream* packets = nullptr;  // packets.csv (network/packet_trace.hpp)
  std::ostream* frames = nullptr;   // frames.csv (network/frame_trace.hpp)
  std::ostream* sensing = nullptr;  // sensing.csv (network/sensing_trace.hpp)
};

// SwarmNet's own simulator (writing the traces that are not null), or ns-3 (which writes none:
// the scenario check refuses output.packet_trace, output.frame_trace and output.sensing_trace
// with it). Throws what the engine's set-up throws. `stop_requested`, when given, is polled by
// either engine inside every window (SwarmNet's every 4096 events, ns-3's every millisecond of
// simulated time); a true answer throws SimulationInterrupted.
[[nodiscard]] std::unique_ptr<NetworkEngine> make_network_engine(
    const Scenario& scenario, PluginLoader& loader, const NetworkTraceStreams& traces,
    bool (*stop_requested)() = nullptr);

}  // namespace swarmnet
