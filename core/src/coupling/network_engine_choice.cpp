#include "coupling/network_engine_choice.hpp"

#include "network/network_simulator.hpp"
#include "ns3_host/ns3_network_engine.hpp"

namespace swarmnet {

std::unique_ptr<NetworkEngine> make_network_engine(const Scenario& scenario, PluginLoader& loader,
                                                   std::ostream* packet_trace,
                                                   std::ostream* frame_trace,
                                                   bool (*stop_requested)()) {
  const NetworkSettings settings = scenario.network_settings();
  if (settings.network.engine == NetworkEngineKind::ns3) {
    return std::make_unique<Ns3NetworkEngine>(settings, stop_requested);
  }
  auto simulator = std::make_unique<NetworkSimulator>(settings, loader, packet_trace, frame_trace);
  simulator->set_interrupt_check(stop_requested);
  return simulator;
}

}  // namespace swarmnet
