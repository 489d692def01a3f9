// The module's two entry points (ns3_engine_api.hpp); ns3_engine.map exports them and nothing
// else.
#include "ns3_engine/ns3_engine_api.hpp"
#include "ns3_engine/ns3_network.hpp"

extern "C" {

std::uint32_t swarmnet_ns3_engine_api_version() { return swarmnet::ns3engine::kApiVersion; }

swarmnet::ns3engine::Network* swarmnet_ns3_engine_create(
    const swarmnet::ns3engine::Config& config) {
  return new swarmnet::ns3engine::Ns3Network(config);
}
}
