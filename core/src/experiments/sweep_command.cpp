#include "experiments/sweep_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "coupling/process_spawn.hpp"
#include "coupling/stop_signal.hpp"
#include "experiments/slurm_sweep.hpp"
#include "experiments/sweep_file.hpp"
#include "experiments/sweep_lock.hpp"
#include "experiments/sweep_plan.hpp"
#include "experiments/sweep_results.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "plugin/executable_layout.hpp"
#include "session/exit_codes.hpp"

namespace swarmnet {

namespace {

std::string format_duration(double seconds) {
  const long long s = std::llround(seconds);
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, (s / 60) % 60);
  } else if (s >= 60) {
    std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%llds", s);
  }
  return text;
}

std::filesystem::path self_executable() {
  auto path = running_executable();
  return path.empty() ? std::filesystem::path("swarmnet") : path;
}

struct Child {
  pid_t pid = 0;
  std::size_t run = 0;
  std::chrono::steady_clock::time_point start;
};

// Starts `swarmnet run` for one run, its output into the run directory's output.log.
pid_t spawn_run(const std::filesystem::path& exe, const SweepSpec& spec, const SweepRun& run,
                const std::filesystem::path& dir) {
  std::vector<std::string> args = {exe.string()};
  for (auto& argument : run_arguments(spec, run, dir)) args.push_back(std::move(argument));
  SpawnRequest request;
  request.executable = exe;
  request.arguments = std::move(args);
  request.output_file = dir / kRunOutputLog;
  // The run dies with the sweep (SIGTERM, so it still cleans up): no orphans after a kill.
  request.extra_environment = {std::string(kParentVariable) + "=" + std::to_string(::getpid())};
  std::string error;
  return spawn_process(request, error);
}

class SweepProgress {
 public:
  SweepProgress(std::size_t total, std::size_t skipped)
      : terminal_(::isatty(STDERR_FILENO) != 0),
        total_(total),
        done_(skipped),
        start_(std::chrono::steady_clock::now()) {}

  void finished(const std::string& id, bool ok, double seconds, const std::string& detail) {
    ++done_;
    ++ran_;
    if (!ok) ++failed_;
    if (terminal_) {
      if (!ok) std::fprintf(stderr, "\r\033[KFAILED %s: %s\n", id.c_str(), detail.c_str());
      draw();
    } else {
      std::fprintf(stderr, "[%zu/%zu] %s %s (%.1f s)%s%s\n", done_, total_, ok ? "ok" : "FAILED",
                   id.c_str(), seconds, ok ? "" : ": ", ok ? "" : detail.c_str());
    }
  }
  void draw() const {
    if (!terminal_) return;
    constexpr int kWidth = 30;
    const int filled = total_ > 0 ? static_cast<int>(kWidth * done_ / total_) : kWidth;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kWidth, '.');
    std::string eta = "ETA --";
    if (ran_ > 0) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      eta = "ETA " + format_duration(elapsed / static_cast<double>(ran_) *
                                     static_cast<double>(total_ - done_));
    }
    std::fprintf(stderr, "\r\033[K[%s] %zu/%zu done, %zu failed, %s", bar.c_str(), done_, total_,
                 failed_, eta.c_str());
    std::fflush(stderr);
  }
  void end() const {
    if (terminal_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool terminal_;
  std::size_t total_;
  std::size_t done_;
  std::size_t ran_ = 0;
  std::size_t failed_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

int sweep_command(const SweepOptions& options) {
  SweepSpec spec;
  std::vector<SweepRun> runs;
  try {
    spec = load_sweep(options.file);
    runs = spec.expand();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitBadInput;
  }
  const std::filesystem::path out = sweep_directory(spec, options.file, options.out);
  if (options.action == SweepAction::kStatus) return sweep_status(runs, out);
  if (options.action == SweepAction::kCollect) return sweep_collect(spec, runs, out);
  if (const auto problems = validate_runs(spec, runs); !problems.empty()) {
    std::fprintf(stderr, "swarmnet: error: the sweep %s gives invalid scenarios:\n",
                 options.file.string().c_str());
    for (const auto& line : problems) std::fprintf(stderr, "%s\n", line.c_str());
    return kExitBadInput;
  }
  if (options.validate_only) {
    std::printf("%s: valid sweep: %zu runs (%zu combinations x %zu seeds) of %s into %s\n",
                options.file.string().c_str(), runs.size(), runs.size() / spec.seeds.size(),
                spec.seeds.size(), spec.base.string().c_str(), out.string().c_str());
    return 0;
  }
  if (options.action == SweepAction::kSlurmSubmit) {
    SlurmJobSettings settings = options.slurm;
    if (settings.swarmnet.empty()) settings.swarmnet = self_executable();
    settings.swarmnet = std::filesystem::absolute(settings.swarmnet).lexically_normal();
    return slurm_submit_sweep(options.file, spec, runs, out,
                              "swarmnet-" + options.file.stem().string(), settings);
  }

  const std::filesystem::path runs_dir = out / "runs";
  std::error_code ec;
  std::filesystem::create_directories(runs_dir, ec);
  if (ec) {
    std::fprintf(stderr, "swarmnet: error: cannot create %s: %s\n", runs_dir.string().c_str(),
                 ec.message().c_str());
    return kExitRunFailed;
  }
  std::optional<SweepLock> lock;
  try {
    lock.emplace(out);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitRunFailed;
  }
  {
    std::ifstream in(options.file, std::ios::binary);
    write_file_atomically(out / "sweep.yaml", std::string(std::istreambuf_iterator<char>(in), {}));
  }

  std::vector<SweepRunResult> results = finished_runs(runs, out);
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (results[i].status != "ok") pending.push_back(i);
  }
  const std::size_t skipped = runs.size() - pending.size();
  const unsigned jobs =
      options.jobs > 0 ? options.jobs : std::max(1U, std::thread::hardware_concurrency());
  std::fprintf(stderr, "sweep: %zu runs into %s/: %zu finished before, %zu to run, %u at a time\n",
               runs.size(), out.string().c_str(), skipped, pending.size(), jobs);

  install_stop_handlers();
  const std::filesystem::path exe = self_executable();
  SweepProgress progress(runs.size(), skipped);
  std::vector<Child> children;
  std::size_t next = 0;
  std::size_t failed = 0;
  bool stopping = false;
  progress.draw();
  while (next < pending.size() || !children.empty()) {
    if (!stopping && stop_signal() != 0) {
      stopping = true;
      for (const auto& child : children) ::kill(child.pid, SIGTERM);
    }
    while (!stopping && next < pending.size() && children.size() < jobs) {
      const std::size_t index = pending[next++];
      const auto dir = runs_dir / runs[index].id;
      std::filesystem::create_directories(dir, ec);
      const pid_t pid = spawn_run(exe, spec, runs[index], dir);
      if (pid <= 0) {
        results[index].status = "failed";
        ++failed;
        progress.finished(runs[index].id, false, 0.0, "cannot start " + exe.string());
        continue;
      }
      children.push_back({pid, index, std::chrono::steady_clock::now()});
    }
    if (stopping && children.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      progress.draw();
      continue;
    }
    const auto it = std::ranges::find_if(children, [&](const Child& c) { return c.pid == pid; });
    if (it == children.end()) continue;
    const Child child = *it;
    children.erase(it);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - child.start).count();
    SweepRunResult& result = results[child.run];
    const auto dir = runs_dir / runs[child.run].id;
    const bool ok =
        WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(result.summary);
    if (stopping && !ok) continue;  // interrupted: redone next time
    result.status = ok ? "ok" : "failed";
    if (!ok) ++failed;
    const auto log = std::filesystem::exists(dir / kLogFile) ? dir / kLogFile : dir / kRunOutputLog;
    progress.finished(runs[child.run].id, ok, seconds,
                      last_output_line(dir / kRunOutputLog) + " (log: " + log.string() + ")");
  }
  progress.end();

  try {
    write_file_atomically(out / "results.csv", results_csv(spec, results));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return kExitRunFailed;
  }
  std::size_t ok_runs = 0;
  for (const auto& result : results) ok_runs += result.status == "ok" ? 1 : 0;
  std::fprintf(stderr,
               "sweep: %zu of %zu runs finished (%zu skipped as already done), %zu failed; "
               "results in %s\n",
               ok_runs, runs.size(), skipped, failed, (out / "results.csv").string().c_str());
  if (const int signal = stop_signal(); signal != 0) {
    std::fprintf(stderr, "sweep: interrupted; run the same command again to finish\n");
    return 128 + signal;
  }
  if (failed > 0) {
    for (const auto& result : results) {
      if (result.status != "failed") continue;
      const auto dir = runs_dir / result.run->id;
      std::fprintf(stderr, "  failed: %s (log: %s)\n", result.run->id.c_str(),
                   (dir / kRunOutputLog).string().c_str());
    }
    return kExitRunFailed;
  }
  return 0;
}

}  // namespace swarmnet
