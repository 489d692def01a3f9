// libFuzzer target: scenario text through the whole loader (parse, overrides, checks, plugins,
// resolved text). Any input must end in a Scenario or a ScenarioError, never a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenario/scenario_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  swarmnet::PluginLoader loader;  // the fuzz build's own plugins, found as a run would
  try {
    (void)swarmnet::load_scenario_text(text, "fuzz.yaml", loader);
  } catch (const swarmnet::ScenarioError&) {
    // The expected answer to a bad scenario.
  }
  return 0;
}
