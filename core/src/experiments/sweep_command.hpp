// `swarmnet sweep SWEEP.yaml [-j N] [--out DIR]` (docs/experiments.md).
#pragma once

#include <filesystem>
#include <string>

namespace swarmnet {

struct SweepOptions {
  std::filesystem::path file;
  unsigned jobs = 0;           // 0: number of cores
  std::filesystem::path out;   // "" : the sweep file's out, else runs/sweeps/<file stem>
  bool validate_only = false;  // check the sweep and every expanded scenario, run nothing
};

// Exit code: 0 every run finished, 1 some run failed, 2 bad sweep file or scenario,
// 128 + signal when interrupted.
int sweep_command(const SweepOptions& options);

}  // namespace swarmnet
