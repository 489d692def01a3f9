#include "experiments/sweep_command.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "coupling/process_spawn.hpp"
#include "coupling/stop_signal.hpp"
#include "experiments/sweep_file.hpp"
#include "experiments/sweep_results.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "outputs/run_error.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario_loader.hpp"
#include "session/exit_codes.hpp"

namespace swarmnet {

namespace {

constexpr const char* kChildLog = "output.log";  // the run's stdout and stderr

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

// Checks every expanded scenario as `swarmnet validate` would; each problem once, located in the
// sweep file where a swept or fixed value caused it.
std::vector<std::string> validate_runs(const SweepSpec& spec, const std::vector<SweepRun>& runs) {
  std::map<std::string, std::string> origin;  // "--set KEY" -> sweep file location and value
  for (const auto& fixed : spec.fixed) {
    origin["--set " + fixed.key] = fixed.location + ": set " + fixed.key + "=" + fixed.text;
  }
  std::vector<std::string> problems;
  std::set<std::string> seen;
  PluginLoader loader;
  for (const auto& run : runs) {
    ScenarioOverrides overrides;
    overrides.set = run.set;
    overrides.seed = run.seed;
    overrides.out_dir = "unused";
    try {
      (void)load_scenario(spec.base, overrides, loader);
    } catch (const ScenarioError& error) {
      for (const auto& line : error.problems()) {
        std::string where = "run " + run.id;
        for (std::size_t a = 0; a < spec.axes.size(); ++a) {
          const SweepAxis& axis = spec.axes[a];
          for (std::size_t k = 0; k < axis.keys.size(); ++k) {
            const auto& value = axis.points[run.point[a]].values[k];
            if (line.starts_with("--set " + axis.keys[k] + ":") ||
                line.starts_with("--set " + axis.keys[k] + " ")) {
              where = value.location + ": grid " + (axis.linked ? axis.name + ": " : "") +
                      axis.keys[k] + "=" + value.text;
            }
          }
        }
        for (const auto& [option, place] : origin) {
          if (line.starts_with(option + ":")) where = place;
        }
        if (seen.insert(line).second) problems.push_back(where.append(": ").append(line));
        if (problems.size() >= 20) return problems;
      }
    } catch (const std::exception& error) {
      if (seen.insert(error.what()).second)
        problems.push_back("run " + run.id + ": " + error.what());
    }
  }
  return problems;
}

std::filesystem::path self_executable() {
  std::error_code ec;
  auto path = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path("swarmnet") : path;
}

struct Child {
  pid_t pid = 0;
  std::size_t run = 0;
  std::chrono::steady_clock::time_point start;
};

// Starts `swarmnet run` for one run, its output into the run directory's output.log.
pid_t spawn_run(const std::filesystem::path& exe, const SweepSpec& spec, const SweepRun& run,
                const std::filesystem::path& dir) {
  std::vector<std::string> args = {exe.string(), "run", spec.base.string()};
  for (const auto& set : run.set) {
    args.emplace_back("--set");
    args.push_back(set);
  }
  // A run redone (failed or interrupted before) replaces what it left.
  args.insert(args.end(), {"--seed", std::to_string(run.seed), "--out", dir.string(), "--quiet",
                           "--overwrite"});
  SpawnRequest request;
  request.executable = exe;
  request.arguments = std::move(args);
  request.output_file = dir / kChildLog;
  // The run dies with the sweep (SIGTERM, so it still cleans up): no orphans after a kill.
  request.extra_environment = {std::string(kParentVariable) + "=" + std::to_string(::getpid())};
  std::string error;
  return spawn_process(request, error);
}

// Holds an exclusive lock on the sweep directory for this process's life: a second sweep into
// the same directory (an immediate resume while the first still runs) is refused, not run into
// the same run directories at the same time.
class SweepLock {
 public:
  explicit SweepLock(const std::filesystem::path& out) {
    const std::filesystem::path path = out / ".sweep.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd_ < 0) throw RunError("cannot open " + path.string() + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      char holder[32] = {};
      const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
      ::close(fd_);
      throw RunError("another sweep" +
                     (n > 0 ? " (pid " + std::string(holder, static_cast<std::size_t>(n)) + ")"
                            : std::string()) +
                     " is running into " + out.string() + "; wait for it or stop it first");
    }
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
      // The lock holds without the pid; the pid only makes the refusal message clearer.
    }
  }
  ~SweepLock() { ::close(fd_); }
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  int fd_ = -1;
};

std::string last_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::string last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
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
  if (const auto problems = validate_runs(spec, runs); !problems.empty()) {
    std::fprintf(stderr, "swarmnet: error: the sweep %s gives invalid scenarios:\n",
                 options.file.string().c_str());
    for (const auto& line : problems) std::fprintf(stderr, "%s\n", line.c_str());
    return kExitBadInput;
  }
  const std::filesystem::path out =
      !options.out.empty() ? options.out
      : !spec.out.empty()  ? spec.out
                           : std::filesystem::path("runs/sweeps") / options.file.stem();
  if (options.validate_only) {
    std::printf("%s: valid sweep: %zu runs (%zu combinations x %zu seeds) of %s into %s\n",
                options.file.string().c_str(), runs.size(), runs.size() / spec.seeds.size(),
                spec.seeds.size(), spec.base.string().c_str(), out.string().c_str());
    return 0;
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

  std::vector<SweepRunResult> results(runs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    results[i].run = &runs[i];
    results[i].summary = runs_dir / runs[i].id / kSummaryFile;
    if (std::filesystem::exists(results[i].summary)) {
      results[i].status = "ok";
    } else {
      results[i].status = "not run";
      pending.push_back(i);
    }
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
    const auto log = std::filesystem::exists(dir / kLogFile) ? dir / kLogFile : dir / kChildLog;
    progress.finished(runs[child.run].id, ok, seconds,
                      last_line(dir / kChildLog) + " (log: " + log.string() + ")");
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
                   (dir / kChildLog).string().c_str());
    }
    return kExitRunFailed;
  }
  return 0;
}

}  // namespace swarmnet
