// `swarmnet sweep SWEEP.yaml [-j N] [--out DIR]` (docs/experiments.md), and on a Slurm cluster
// `--slurm [job options]`, `--status`, `--collect` (slurm_sweep.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "experiments/slurm_submission.hpp"

namespace swarmnet {

enum class SweepAction {
  kRun,          // run every unfinished run here, -j at a time
  kSlurmSubmit,  // submit every unfinished run to Slurm as one job array
  kStatus,       // print the state of every run
  kCollect,      // write results.csv from the run directories
};

struct SweepOptions {
  std::filesystem::path file;
  unsigned jobs = 0;           // 0: number of cores
  std::filesystem::path out;   // "" : the sweep file's out, else runs/sweeps/<file stem>
  bool validate_only = false;  // check the sweep and every expanded scenario, run nothing
  SweepAction action = SweepAction::kRun;
  SlurmJobSettings slurm;  // kSlurmSubmit; swarmnet "" : this executable
};

// Exit code: 0 every run finished, 1 some run failed, 2 bad sweep file or scenario,
// 128 + signal when interrupted. With --slurm, --status, --collect: slurm_sweep.hpp.
int sweep_command(const SweepOptions& options);

}  // namespace swarmnet
