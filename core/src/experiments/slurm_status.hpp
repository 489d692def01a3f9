// What Slurm says about a sweep's array tasks: `squeue` for the tasks still queued or running,
// then `sacct` for those that ended, or, where accounting is not configured (sacct refuses),
// `scontrol show job` for as long as slurmctld keeps a finished job (MinJobAge, 300 s by
// default). The parsers are separate from the calls so that they can be tested on text.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace swarmnet {

// An array task: the array's job id and the task's index.
using SlurmTaskId = std::pair<std::string, std::size_t>;

struct SlurmTaskState {
  std::string state;      // Slurm's: PENDING, RUNNING, COMPLETED, FAILED, TIMEOUT, CANCELLED, ...
  std::string exit_code;  // "1:0" (status:signal) where known
};

// Whether a task in this state may still run (it is queued, starting, running or being ended):
// such a task is neither resubmitted nor counted as failed.
bool slurm_state_is_active(const std::string& state);
// Whether it is queued rather than running.
bool slurm_state_is_pending(const std::string& state);

// `squeue -h -r -o %F|%K|%T` (one line per array task: array job id, index, state); lines of
// jobs that are not array tasks are skipped.
std::map<SlurmTaskId, SlurmTaskState> parse_squeue(const std::string& text);
// `sacct -n -P -X -o JobID,State,ExitCode`: "12_3|FAILED|1:0"; a pending range "12_[4-9%2]" and
// lines of jobs that are not array tasks are skipped. "CANCELLED by 0" becomes CANCELLED.
std::map<SlurmTaskId, SlurmTaskState> parse_sacct(const std::string& text);
// `scontrol -o show job ID`: one line of KEY=VALUE per task (ArrayJobId, ArrayTaskId, JobState,
// ExitCode); a line for a pending range (ArrayTaskId=4-9%2) is skipped.
std::map<SlurmTaskId, SlurmTaskState> parse_scontrol(const std::string& text);

struct SlurmQuery {
  bool queue_known = false;  // squeue answered: active tasks are exactly those in `queued`
  std::map<SlurmTaskId, SlurmTaskState> queued;  // from squeue
  std::map<SlurmTaskId, SlurmTaskState> ended;   // from sacct, else scontrol
  std::vector<std::string> notes;  // what could not be asked, and what was used instead
};

// Asks squeue, then sacct (or scontrol) about the tasks of `job_ids`.
SlurmQuery query_slurm(const std::vector<std::string>& job_ids);

}  // namespace swarmnet
