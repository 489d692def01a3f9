// Running a program found on PATH (sbatch, squeue, sacct, scontrol) and keeping what it printed:
// standard output and standard error apart, so that a refusal can be quoted in an error message.
#pragma once

#include <string>
#include <vector>

namespace swarmnet {

struct CapturedCommand {
  bool started = false;  // false: the program could not be run at all (`error` says why)
  int exit_code = -1;    // the exit status; 128 + signal when a signal ended it
  std::string output;    // standard output
  std::string errors;    // standard error
  std::string error;     // why it could not be started (e.g. "No such file or directory")
};

// Runs `arguments` (argv[0] looked up on PATH, as a shell would) with standard input from
// /dev/null and this process's environment, and waits for it.
CapturedCommand run_captured(const std::vector<std::string>& arguments);

// "sbatch: exit 1: sbatch: error: invalid partition specified: gpu" — the command's name, how
// it ended and the last non-empty line of its standard error, for an error message.
std::string describe_failure(const std::vector<std::string>& arguments,
                             const CapturedCommand& result);

}  // namespace swarmnet
