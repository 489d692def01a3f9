// One run of a scenario: the robot half in this thread, the network half beside it, coupled by
// the step protocol; outputs in the scenario's run directory.
#pragma once

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "coupling/network_link.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

struct RunOptions {
  std::FILE* progress = stderr;  // progress line target (shown only on a terminal); null: none
  LinkOptions link;              // how to reach the network half
  bool overwrite = false;        // replace an earlier run in the run directory (--overwrite)
};

struct RunOutcome {
  std::filesystem::path dir;
  nlohmann::ordered_json summary;
};

// Runs `scenario` to completion and writes its run directory. Plugins are created with `loader`,
// the one that resolved them when the scenario was validated (load_scenario), so that a run
// resolves each plugin once. Throws RunError (or the error that stopped the run) with a message
// naming what failed. Outputs reach their final names only once the whole run succeeded; a
// failed run leaves only scenario.resolved.yaml and run.log, which then ends with the error
// (also on a full disk: its room is reserved when the run starts).
RunOutcome run_scenario(const Scenario& scenario, PluginLoader& loader, const RunOptions& options);

}  // namespace swarmnet
