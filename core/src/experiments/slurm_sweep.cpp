#include "experiments/slurm_sweep.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>

#include "experiments/slurm_status.hpp"
#include "experiments/sweep_lock.hpp"
#include "experiments/sweep_plan.hpp"
#include "experiments/sweep_results.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/run_error.hpp"
#include "session/exit_codes.hpp"

namespace swarmnet {

namespace {

enum class RunState { kDone, kRunning, kPending, kFailed, kNotSubmitted, kUnknown };

struct RunStatus {
  RunState state = RunState::kNotSubmitted;
  std::optional<SlurmTaskId> task;  // the run's task in its latest submission
  SlurmTaskState slurm;             // what Slurm says about that task, where it says anything
};

struct SweepState {
  std::vector<RunStatus> runs;  // in run order
  std::vector<std::string> notes;
  bool queue_known = true;
};

// Slurm first, then the run directories: a task that ends between the two is seen as done.
SweepState sweep_state(const std::vector<SweepRun>& runs, const std::filesystem::path& sweep_dir) {
  SweepState state;
  state.runs.resize(runs.size());
  std::map<std::string, SlurmTaskId> latest;  // run id -> its task in the latest submission
  std::vector<std::string> job_ids;
  for (const auto& submission : read_submissions(sweep_dir)) {
    job_ids.push_back(submission.job_id);
    for (std::size_t i = 0; i < submission.runs.size(); ++i) {
      latest[submission.runs[i]] = {submission.job_id, i};
    }
  }
  const SlurmQuery query = query_slurm(job_ids);
  state.notes = query.notes;
  state.queue_known = query.queue_known;
  const auto finished = finished_runs(runs, sweep_dir);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    RunStatus& status = state.runs[i];
    bool active = false;  // queued, running, or ending
    if (const auto task = latest.find(runs[i].id); task != latest.end()) {
      status.task = task->second;
      if (const auto q = query.queued.find(task->second); q != query.queued.end()) {
        status.slurm = q->second;
        active = true;
      } else if (const auto e = query.ended.find(task->second); e != query.ended.end()) {
        status.slurm = e->second;
        active = slurm_state_is_active(e->second.state);  // sacct may lag behind squeue
      }
    }
    if (finished[i].status == "ok") {
      status.state = RunState::kDone;
    } else if (!status.task) {
      status.state = RunState::kNotSubmitted;
    } else if (active) {
      status.state =
          slurm_state_is_pending(status.slurm.state) ? RunState::kPending : RunState::kRunning;
    } else if (!query.queue_known) {
      status.state = RunState::kUnknown;
    } else {
      status.state = RunState::kFailed;
    }
  }
  return state;
}

std::size_t count(const SweepState& state, RunState which) {
  std::size_t n = 0;
  for (const auto& run : state.runs) n += run.state == which ? 1 : 0;
  return n;
}

std::string task_name(const SlurmTaskId& task) {
  return task.first + "_" + std::to_string(task.second);
}

void print_notes(const SweepState& state) {
  for (const auto& note : state.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
}

}  // namespace

int slurm_submit_sweep(const std::filesystem::path& sweep_file, const SweepSpec& spec,
                       const std::vector<SweepRun>& runs, const std::filesystem::path& sweep_dir,
                       const std::string& name, const SlurmJobSettings& settings) {
  const std::filesystem::path out = std::filesystem::absolute(sweep_dir).lexically_normal();
  try {
    std::filesystem::create_directories(out / "runs");
    const SweepLock lock(out);
    {
      std::ifstream in(sweep_file, std::ios::binary);
      write_file_atomically(out / "sweep.yaml",
                            std::string(std::istreambuf_iterator<char>(in), {}));
    }
    const SweepState state = sweep_state(runs, out);
    if (!state.queue_known) {
      print_notes(state);
      std::fprintf(stderr,
                   "swarmnet: error: cannot tell which runs of %s are still queued or running, so "
                   "nothing was submitted\n",
                   out.string().c_str());
      return kExitRunFailed;
    }
    std::vector<std::string> ids;
    std::vector<std::vector<std::string>> arguments;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const RunState s = state.runs[i].state;
      if (s != RunState::kFailed && s != RunState::kNotSubmitted) continue;
      ids.push_back(runs[i].id);
      arguments.push_back(run_arguments(spec, runs[i], run_directory(out, runs[i])));
    }
    const std::size_t done = count(state, RunState::kDone);
    const std::size_t active = count(state, RunState::kRunning) + count(state, RunState::kPending);
    if (ids.empty()) {
      std::fprintf(stderr,
                   "sweep: nothing to submit: %zu runs into %s/: %zu done, %zu queued or "
                   "running\n",
                   runs.size(), out.string().c_str(), done, active);
      return kExitSuccess;
    }
    // One array when the cluster allows it; else several, each at most MaxArraySize tasks.
    const std::size_t per_array = slurm_max_array_size();
    std::vector<SlurmSubmission> submitted;
    for (std::size_t first = 0; first < ids.size(); first += per_array) {
      const std::size_t last = std::min(ids.size(), first + per_array);
      const auto from = static_cast<std::ptrdiff_t>(first);
      const auto to = static_cast<std::ptrdiff_t>(last);
      try {
        submitted.push_back(submit_job_array(
            out, name, std::vector<std::string>(ids.begin() + from, ids.begin() + to),
            std::vector<std::vector<std::string>>(arguments.begin() + from, arguments.begin() + to),
            settings));
      } catch (const std::exception& error) {
        if (submitted.empty()) throw;
        throw RunError(std::string(error.what()) + "; " + std::to_string(first) + " of " +
                       std::to_string(ids.size()) +
                       " runs were submitted before it: submit again for the rest");
      }
      std::printf("%s\n", submitted.back().job_id.c_str());
    }
    const std::string limit = settings.max_parallel > 0
                                  ? "at most " + std::to_string(settings.max_parallel) +
                                        " at a time" + (submitted.size() > 1 ? " in each" : "")
                                  : "no limit on tasks at a time";
    std::string arrays;
    if (submitted.size() == 1) {
      arrays = "Slurm job array " + submitted.front().job_id + " (submission " +
               std::to_string(submitted.front().number) + ", " + limit + ")";
    } else {
      arrays = "Slurm job arrays";
      for (const auto& submission : submitted) {
        arrays += (&submission == &submitted.front() ? " " : ", ") + submission.job_id + " (" +
                  std::to_string(submission.runs.size()) + " runs)";
      }
      arrays +=
          " (this cluster's MaxArraySize is " + std::to_string(per_array) + "; " + limit + ")";
    }
    std::fprintf(stderr,
                 "sweep: %zu runs into %s/: %zu done, %zu queued or running before, %zu "
                 "submitted (%zu failed before) as %s\n",
                 runs.size(), out.string().c_str(), done, active, ids.size(),
                 count(state, RunState::kFailed), arrays.c_str());
    std::fprintf(stderr, "sweep: follow it with: swarmnet sweep %s --out %s --status\n",
                 sweep_file.string().c_str(), out.string().c_str());
    return kExitSuccess;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitRunFailed;
  }
}

int sweep_status(const std::vector<SweepRun>& runs, const std::filesystem::path& sweep_dir) {
  SweepState state;
  try {
    state = sweep_state(runs, sweep_dir);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitRunFailed;
  }
  std::printf("%s: %zu runs: %zu done, %zu running, %zu pending, %zu failed, %zu not submitted",
              sweep_dir.string().c_str(), runs.size(), count(state, RunState::kDone),
              count(state, RunState::kRunning), count(state, RunState::kPending),
              count(state, RunState::kFailed), count(state, RunState::kNotSubmitted));
  if (const std::size_t unknown = count(state, RunState::kUnknown); unknown > 0) {
    std::printf(", %zu unknown (submitted, not finished, Slurm not reachable)", unknown);
  }
  std::printf("\n");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunStatus& run = state.runs[i];
    if (run.state == RunState::kRunning) {
      std::printf("  running: %s (Slurm task %s)\n", runs[i].id.c_str(),
                  task_name(*run.task).c_str());
    }
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunStatus& run = state.runs[i];
    if (run.state != RunState::kFailed) continue;
    const auto output = run_directory(sweep_dir, runs[i]) / kRunOutputLog;
    const std::string reason = last_output_line(output);
    std::printf("  failed: %s (Slurm task %s: %s%s; Slurm log: %s; output: %s%s%s)\n",
                runs[i].id.c_str(), task_name(*run.task).c_str(),
                run.slurm.state.empty() ? "state no longer known" : run.slurm.state.c_str(),
                run.slurm.exit_code.empty() ? "" : (", exit " + run.slurm.exit_code).c_str(),
                slurm_task_log(sweep_dir, run.task->first, run.task->second).string().c_str(),
                output.string().c_str(), reason.empty() ? "" : ": ", reason.c_str());
  }
  print_notes(state);
  return kExitSuccess;
}

int sweep_collect(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                  const std::filesystem::path& sweep_dir) {
  try {
    const SweepState state = sweep_state(runs, sweep_dir);
    std::vector<SweepRunResult> results = finished_runs(runs, sweep_dir);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      // finished_runs read the directories after Slurm was asked: "ok" there wins.
      if (results[i].status != "ok" && state.runs[i].state == RunState::kFailed) {
        results[i].status = "failed";
      }
    }
    write_file_atomically(sweep_dir / "results.csv", results_csv(spec, results));
    std::size_t ok = 0;
    std::size_t failed = 0;
    for (const auto& result : results) {
      ok += result.status == "ok" ? 1 : 0;
      failed += result.status == "failed" ? 1 : 0;
    }
    print_notes(state);
    std::fprintf(stderr,
                 "sweep: %zu of %zu runs finished, %zu failed, %zu not finished; results in %s\n",
                 ok, runs.size(), failed, runs.size() - ok - failed,
                 (sweep_dir / "results.csv").string().c_str());
    return ok == runs.size() ? kExitSuccess : kExitRunFailed;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace swarmnet
