// A sweep on a Slurm cluster (docs/experiments.md, "On a cluster"): submitting the runs that are
// not finished as one job array (again after a failure: only what is missing), the state of
// every run from its directory and from Slurm, and results.csv collected from the run
// directories by the same function as a local sweep's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/slurm_submission.hpp"
#include "experiments/sweep_file.hpp"

namespace swarmnet {

// Submits every run of `runs` that has no summary.json and no queued or running task of an
// earlier submission into `sweep_dir` (made absolute) as one `sbatch --array` job (several
// when they are more than the cluster's MaxArraySize); prints each job id on stdout. `name` is the
// Slurm job name. Exit code: 0 submitted (or nothing left to submit), 1 sbatch, squeue or the sweep
// directory failed.
int slurm_submit_sweep(const std::filesystem::path& sweep_file, const SweepSpec& spec,
                       const std::vector<SweepRun>& runs, const std::filesystem::path& sweep_dir,
                       const std::string& name, const SlurmJobSettings& settings);

// Prints how many runs are done, running, pending, failed and not submitted, then a line for
// each failed run (its Slurm state, Slurm log and output) and each running one. Exit code 0.
int sweep_status(const std::vector<SweepRun>& runs, const std::filesystem::path& sweep_dir);

// Writes sweep_dir/results.csv from the run directories, exactly as a local sweep would (status
// ok, failed for a run whose task ended without summary.json, else not run). Exit code: 0 every
// run is finished, 1 otherwise.
int sweep_collect(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                  const std::filesystem::path& sweep_dir);

}  // namespace swarmnet
