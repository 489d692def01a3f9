#include "coupling/network_engine_choice.hpp"

#include "network/network_simulator.hpp"
#include "ns3_host/ns3_network_engine.hpp"

namespace swarmnet {

std::unique_ptr<NetworkEngine> make_network_engine(const Scenario& scenario, PluginLoader& loader,
                                                   const NetworkTraceStreams& traces,
                                                   bool (*stop_requested)()) {
  const NetworkSettings settings = scenario.network_settings();
  if (settings.network.engine == NetworkEngineKind::ns3) {
    return std::make_unique<Ns3NetworkEngine>(settings, stop_requested);
  }
  auto simulator = std::make_unique<NetworkSimulator>(settings, loader, traces.packets,
                                                      traces.frames, traces.sensing);
  simulator->set_interrupt_check(stop_requested);
  return simulator;
}

}  // namespace swarmnet
