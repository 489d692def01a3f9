// `swarmnet plot RESULTS.csv --x COLUMN --y METRIC [--by COLUMNS] --out FIG.png ...`
// (docs/experiments.md): runs the figure script (share/swarmnet/scripts/plot.py beside the
// command) with a python3 that has matplotlib (plot_interpreter.hpp), its arguments passed
// through unchanged.
#pragma once

#include <string>
#include <vector>

namespace swarmnet {

// Replaces this process with the script on success; returns an exit code (2, message on
// stderr) when no interpreter or no script is found or the script cannot be started.
int plot_command(const std::vector<std::string>& arguments);

}  // namespace swarmnet
