// The ns-3 engine module (libswarmnet_ns3_engine.so), loaded the first time a run asks for ns-3
// and kept for the life of the process: ns-3's libraries register TypeIds and singletons in
// static constructors, which do not survive being unloaded and loaded again.
#pragma once

#include <filesystem>
#include <memory>

#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet {

// Where the module is looked for: $SWARMNET_NS3_ENGINE when set, else the running command's
// engine directory (plugin/executable_layout.hpp).
[[nodiscard]] std::filesystem::path ns3_engine_module_path();

// Creates an ns-3 network from `config` with the module, loading it on first use. Throws
// std::runtime_error naming the module's path and what failed: missing (ns-3 not installed when
// SwarmNet was built), unloadable (dlerror's text), of another API version, or refusing
// `config`.
[[nodiscard]] std::unique_ptr<ns3engine::Network> create_ns3_network(
    const ns3engine::Config& config);

}  // namespace swarmnet
