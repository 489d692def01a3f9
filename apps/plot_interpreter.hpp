// Which python3 draws figures: one that imports matplotlib. Debian's /usr/bin/python3 first
// (where the bootstrap installs python3-matplotlib), then each python3 on PATH in order. A bare
// `python3` is often another one (pyenv, a virtualenv, conda) without matplotlib.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace swarmnet {

struct PlotInterpreter {
  std::filesystem::path python;  // empty when none imports matplotlib
  std::vector<std::filesystem::path> tried;
};

// Tries `preferred`, then `python3` in each directory of `path_list` (colon-separated, as PATH),
// each once, running `PYTHON -c "import matplotlib"`.
PlotInterpreter find_plot_interpreter(const std::filesystem::path& preferred,
                                      const std::string& path_list);

// The message for when none was found: what was tried and what to install.
std::string no_plot_interpreter_message(const PlotInterpreter& search);

}  // namespace swarmnet
