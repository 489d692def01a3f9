// A sweep submitted to Slurm (docs/experiments.md, "On a cluster"): the files a submission
// writes into the sweep directory, the job-array script, and the `sbatch` call.
//
//   DIR/slurm/args/<run id>      the run's `swarmnet run` arguments, NUL-separated
//   DIR/slurm/submit-N.tasks     submission N's run ids, one per line: array index i is line i+1
//   DIR/slurm/submit-N.sh        submission N's job-array script
//   DIR/slurm/jobs               "N JOBID" per submission, in order
//   DIR/slurm/logs/JOBID_I.log   a task's Slurm output (the run's own is DIR/runs/<id>/output.log)
//
// Every path in the script is absolute and inside the sweep directory or the swarmnet binary's,
// so it runs wherever both are visible at the same paths (a shared filesystem).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace swarmnet {

struct SlurmJobSettings {
  std::string partition;                 // "": the cluster's default partition
  std::string time_limit;                // "": the partition's default (sbatch --time)
  unsigned cpus_per_run = 1;             // sbatch --cpus-per-task
  unsigned max_parallel = 0;             // array throttle %K; 0: none
  std::vector<std::string> sbatch_args;  // more #SBATCH lines, e.g. --account=abc
  std::filesystem::path swarmnet;        // the swarmnet the tasks run (absolute)
};

// One earlier submission, as recorded in DIR/slurm/jobs.
struct SlurmSubmission {
  int number = 0;                 // 1, 2, ...
  std::string job_id;             // the array's job id
  std::vector<std::string> runs;  // run id of each array index
};

// DIR/slurm
std::filesystem::path slurm_directory(const std::filesystem::path& sweep_dir);
// DIR/slurm/logs/JOBID_INDEX.log
std::filesystem::path slurm_task_log(const std::filesystem::path& sweep_dir,
                                     const std::string& job_id, std::size_t index);

// The job-array script of submission `number` with `tasks` array indices. `sweep_dir` and
// settings.swarmnet must be absolute. Throws std::invalid_argument for a value that cannot go
// into the script (a line break).
std::string job_array_script(const std::filesystem::path& sweep_dir, const std::string& name,
                             int number, std::size_t tasks, const SlurmJobSettings& settings);

// Every submission recorded in DIR/slurm/jobs, in order (none when there is no such file).
// Throws RunError for a record or task list that cannot be read.
std::vector<SlurmSubmission> read_submissions(const std::filesystem::path& sweep_dir);

// The most tasks one job array may have on this cluster: its MaxArraySize (`scontrol show
// config`; a task's index is below it), or Slurm's default, 1001, when scontrol does not say.
std::size_t slurm_max_array_size();

// Writes the arguments of each run, the task list and the script of the next submission, then
// submits it with `sbatch --parsable` and records its job id. `arguments[i]` are the
// `swarmnet run` arguments (without the executable) of `run_ids[i]`. Throws RunError naming the
// command and its standard error when sbatch is missing or refuses the job.
SlurmSubmission submit_job_array(const std::filesystem::path& sweep_dir, const std::string& name,
                                 const std::vector<std::string>& run_ids,
                                 const std::vector<std::vector<std::string>>& arguments,
                                 const SlurmJobSettings& settings);

}  // namespace swarmnet
