// What a sweep will run, shared by the local runner and the Slurm submission: every expanded
// scenario checked first, the sweep directory, each run's `swarmnet run` command line, and which
// runs are finished (their directory holds summary.json).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweep_file.hpp"
#include "experiments/sweep_results.hpp"

namespace swarmnet {

// Checks every expanded scenario as `swarmnet validate` would; each problem once, located in the
// sweep file where a swept or fixed value caused it. Empty when every run is valid.
std::vector<std::string> validate_runs(const SweepSpec& spec, const std::vector<SweepRun>& runs);

// The sweep directory: `out` when given, else the sweep file's out, else runs/sweeps/<file stem>.
std::filesystem::path sweep_directory(const SweepSpec& spec, const std::filesystem::path& file,
                                      const std::filesystem::path& out);

// The arguments after the executable's name that run `run` into `dir`:
// run BASE --set ... --seed S --out DIR --quiet --overwrite (a redone run replaces what it left).
std::vector<std::string> run_arguments(const SweepSpec& spec, const SweepRun& run,
                                       const std::filesystem::path& dir);

// A run's directory inside the sweep directory: DIR/runs/<id>.
std::filesystem::path run_directory(const std::filesystem::path& sweep_dir, const SweepRun& run);

// One result per run, in run order: "ok" when its directory holds summary.json (a run writes it
// last), else "not run".
std::vector<SweepRunResult> finished_runs(const std::vector<SweepRun>& runs,
                                          const std::filesystem::path& sweep_dir);

// The last non-empty line of a text file ("" when it cannot be read): a failed run's reason.
std::string last_output_line(const std::filesystem::path& path);

// The run's stdout and stderr, beside its own run.log.
inline constexpr const char* kRunOutputLog = "output.log";

}  // namespace swarmnet
