// libFuzzer target: a hello's scenario text as `swarmnet net --listen` reads it. Any input must end
// in a Scenario or a ScenarioError, and whatever the text holds (plugin_paths under any spelling,
// repeated, aliased), the plugin search path stays the server's own: the process aborts otherwise.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "scenario/scenario_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::vector<std::filesystem::path> host = {"/nonexistent/server-plugins"};
  swarmnet::PluginLoader loader(host);
  const auto before = loader.search_path();
  try {
    const swarmnet::Scenario scenario =
        swarmnet::load_peer_scenario_text(text, "the robot half's scenario", loader, host);
    if (scenario.plugin_paths != host) std::abort();
  } catch (const swarmnet::ScenarioError&) {
    // The expected answer to a bad scenario.
  }
  if (loader.search_path() != before) std::abort();  // a path from the peer reached the loader
  return 0;
}
