// Failure of one half during a run: the other half stops within the design bound of 2 s (the
// tests allow 5 s on a loaded machine) with a message naming the half and how it ended, a
// non-zero exit, no child process and no shared-memory segment left behind.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kStopBound = std::chrono::seconds(5);

// A `swarmnet run` started in the background, its output going to a file.
class BackgroundRun {
 public:
  BackgroundRun(const TempDir& dir, const std::vector<std::string>& extra,
                const std::string& scenario = "quickstart.yaml")
      : log_(dir.path() / "out.txt") {
    std::vector<std::string> args = {"run",
                                     std::string(SWARMNET_SOURCE_DIR) + "/configs/" + scenario,
                                     "--quiet",
                                     "--set",
                                     "duration_s=100000",
                                     "--out",
                                     (dir.path() / "run").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    pid_ = spawn_swarmnet(args, log_);
  }
  ~BackgroundRun() {
    if (!reaped_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  BackgroundRun(const BackgroundRun&) = delete;
  BackgroundRun& operator=(const BackgroundRun&) = delete;

  [[nodiscard]] pid_t pid() const { return pid_; }

  // The network half's pid, once the run has started it and stepped a while.
  pid_t network_half() const {
    const auto deadline = Clock::now() + std::chrono::seconds(20);
    while (Clock::now() < deadline) {
      std::ifstream children("/proc/" + std::to_string(pid_) + "/task/" + std::to_string(pid_) +
                             "/children");
      pid_t child = 0;
      if (children >> child && child > 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));  // let it step a while
        return child;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return 0;
  }

  // Waits for the run to exit; returns its wait status, or -1 if it did not exit in `bound`.
  int wait_exit(std::chrono::steady_clock::duration bound) {
    const auto deadline = Clock::now() + bound;
    int status = 0;
    while (Clock::now() < deadline) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        reaped_ = true;
        return status;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return -1;
  }
  [[nodiscard]] std::string output() const { return read_file(log_); }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  bool reaped_ = false;
};

bool process_gone(pid_t pid) {
  // A zombie still answers kill(); its state in /proc says it is dead.
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string word;
  std::string state;
  if (!(stat >> word >> word >> state)) return true;
  return state == "Z" || state == "X";
}

bool wait_gone(pid_t pid, std::chrono::steady_clock::duration bound) {
  const auto deadline = Clock::now() + bound;
  while (Clock::now() < deadline) {
    if (process_gone(pid)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return process_gone(pid);
}

std::vector<std::string> segments_of(pid_t pid) {
  std::vector<std::string> found;
  const std::string prefix = "swarmnet-" + std::to_string(pid) + "-";
  for (const auto& entry : std::filesystem::directory_iterator("/dev/shm")) {
    if (entry.path().filename().string().starts_with(prefix)) found.push_back(entry.path());
  }
  return found;
}

void expect_nothing_left(const TempDir& dir, pid_t run) {
  EXPECT_TRUE(segments_of(run).empty());
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "summary.json"));
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "run")) {
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
  }
}

// True once process `pid` has `library` mapped (within 20 s).
bool wait_mapped(pid_t pid, const std::string& library) {
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (Clock::now() < deadline) {
    if (read_file("/proc/" + std::to_string(pid) + "/maps").find(library) != std::string::npos) {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// `engine_library`: a library the network half must have loaded before it is killed.
void expect_killed_network_half_reported(const std::string& scenario,
                                         const std::string& engine_library = "") {
  TempDir dir;
  BackgroundRun run(dir, {}, scenario);
  const pid_t network = run.network_half();
  ASSERT_GT(network, 0) << run.output();
  if (!engine_library.empty()) ASSERT_TRUE(wait_mapped(network, engine_library));
  ASSERT_EQ(::kill(network, SIGKILL), 0);
  const int status = run.wait_exit(kStopBound);
  ASSERT_NE(status, -1) << "the robot half did not stop";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
  const std::string out = run.output();
  EXPECT_NE(
      out.find("the network half (pid " + std::to_string(network) + ") was killed by signal 9"),
      std::string::npos)
      << out;
  expect_nothing_left(dir, run.pid());
  // The robot half's log says it too: the reason stays with the run directory.
  const std::string log = read_file(dir.path() / "run" / "run.log");
  EXPECT_NE(log.find("\nrun failed: "), std::string::npos) << log;
  EXPECT_NE(
      log.find("the network half (pid " + std::to_string(network) + ") was killed by signal 9"),
      std::string::npos)
      << log;
}

TEST(PeerFailure, KilledNetworkHalfEndsTheRunWithItsCause) {
  expect_killed_network_half_reported("quickstart.yaml");
}

#ifdef SWARMNET_HAVE_NS3
// The ns-3 engine's half is the same `swarmnet net` process with ns-3 loaded in it.
TEST(PeerFailure, KilledNs3NetworkHalfEndsTheRunWithItsCause) {
  expect_killed_network_half_reported("ns3.yaml", "libswarmnet_ns3_engine.so");
}
#endif

TEST(PeerFailure, KilledRobotHalfTakesTheNetworkHalfDown) {
  TempDir dir;
  BackgroundRun run(dir, {});
  const pid_t network = run.network_half();
  ASSERT_GT(network, 0) << run.output();
  ASSERT_EQ(::kill(run.pid(), SIGKILL), 0);
  ASSERT_NE(run.wait_exit(kStopBound), -1);
  EXPECT_TRUE(wait_gone(network, kStopBound)) << "the network half outlived the robot half";
  EXPECT_TRUE(segments_of(run.pid()).empty());
}

// A robot half killed outright cannot end its log, but what it wrote as it went is on disk:
// run.log.partial-PID names the scenario, the seed and the transport, and how far the run got.
TEST(PeerFailure, KilledRobotHalfLeavesALogOfHowFarItGot) {
  TempDir dir;
  BackgroundRun run(dir, {});
  ASSERT_GT(run.network_half(), 0) << run.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // the first progress line: 1 s
  ASSERT_EQ(::kill(run.pid(), SIGKILL), 0);
  ASSERT_NE(run.wait_exit(kStopBound), -1);
  const auto partial = dir.path() / "run" / ("run.log.partial-" + std::to_string(run.pid()));
  ASSERT_TRUE(std::filesystem::exists(partial)) << run.output();
  const std::string log = read_file(partial);
  EXPECT_TRUE(log.starts_with("SwarmNet run of scenario 'quickstart' from ")) << log;
  EXPECT_NE(log.find("\nseed "), std::string::npos) << log;
  EXPECT_NE(log.find("\ntransport: shared-memory rings"), std::string::npos) << log;
  EXPECT_NE(log.find("\nat step "), std::string::npos) << log;
  EXPECT_EQ(log.find('\0'), std::string::npos) << "the reserved room shows as zeros";
  EXPECT_TRUE(log.ends_with("\n")) << log;
}

TEST(PeerFailure, HungNetworkHalfIsDetectedByTheStepTimeout) {
  TempDir dir;
  BackgroundRun run(dir, {"--step-timeout", "0.5"});
  const pid_t network = run.network_half();
  ASSERT_GT(network, 0) << run.output();
  ASSERT_EQ(::kill(network, SIGSTOP), 0);  // alive, but never answers again
  const int status = run.wait_exit(kStopBound);
  ASSERT_NE(status, -1) << "the robot half waited forever";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
  EXPECT_NE(run.output().find("no answer within the step timeout; it hangs"), std::string::npos)
      << run.output();
  EXPECT_TRUE(wait_gone(network, kStopBound)) << "the hung network half was left running";
  expect_nothing_left(dir, run.pid());
}

// The quickstart scenario for 0.5 simulated s under `step_timeout_s`, with the test fixtures on
// the plugin path and one more `--set` (a fixture standing in for a slow or stuck half).
CommandResult run_with_fixture(const TempDir& dir, const std::string& transport,
                               const std::string& step_timeout_s, const std::string& fixture_set) {
  return run_swarmnet("run " SWARMNET_SOURCE_DIR "/configs/quickstart.yaml --quiet --transport " +
                      transport + " --step-timeout " + step_timeout_s +
                      " --set duration_s=0.5 --set 'plugin_paths=[\"" SWARMNET_TEST_FIXTURE_DIR
                      "\"]' --set '" +
                      fixture_set + "' --out " + (dir.path() / "run").string());
}

// A network half that computes for longer than the step timeout is slow, not hung: the robot
// half keeps waiting while the child (or, in process, the network thread) uses the CPU. The
// fixture's node 0 computes for 0.4 s of CPU every 0.1 simulated s; the step timeout is 0.15 s.
TEST(PeerFailure, ANetworkHalfComputingPastTheStepTimeoutIsWaitedFor) {
  for (const std::string transport : {"shm", "uds", "inproc"}) {
    TempDir dir;
    const CommandResult result =
        run_with_fixture(dir, transport, "0.15",
                         R"(network.routing={"plugin": "busy_routing", )"
                         R"("params": {"period_s": 0.1, "busy_ms": 400}})");
    EXPECT_EQ(result.exit_code, 0) << transport << ": " << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "run" / "summary.json")) << transport;
  }
}

// Likewise the other way: a robot half that computes for longer than the step timeout is slow,
// not hung, for the network half that waits for its next step (the child reads its parent's CPU
// time; in process, the network thread reads the robot thread's CPU clock). The fixture's robot 0
// computes for 0.4 s of CPU at every 0.1 s step; the step timeout is 0.15 s.
TEST(PeerFailure, ARobotHalfComputingPastTheStepTimeoutIsWaitedFor) {
  for (const std::string transport : {"shm", "inproc"}) {
    TempDir dir;
    const CommandResult result = run_with_fixture(
        dir, transport, "0.15",
        R"(robots.controllers=[{"plugin": "busy_controller", "params": {"busy_ms": 400}}])");
    EXPECT_EQ(result.exit_code, 0) << transport << ": " << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "run" / "summary.json")) << transport;
  }
}

// In process, a network thread that stops computing is still found hung: the fixture's node 0
// sleeps 3 s without computing under a 0.2 s step timeout. The robot half gives up within two
// timeouts of the wait's start, and the run ends once the thread wakes and sees the link closed.
TEST(PeerFailure, AnInProcessNetworkHalfThatStopsComputingIsFoundHung) {
  TempDir dir;
  const CommandResult result =
      run_with_fixture(dir, "inproc", "0.2",
                       R"(network.routing={"plugin": "busy_routing", )"
                       R"("params": {"period_s": 0.1, "busy_ms": 0, "sleep_ms": 3000}})");
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("no answer within the step timeout; it hangs"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "summary.json"));
}

TEST(PeerFailure, TerminationSignalStopsBothHalvesCleanly) {
  for (const char* transport : {"shm", "uds"}) {
    TempDir dir;
    BackgroundRun run(dir, {"--transport", transport});
    const pid_t network = run.network_half();
    ASSERT_GT(network, 0) << run.output();
    ASSERT_EQ(::kill(run.pid(), SIGTERM), 0);
    const int status = run.wait_exit(kStopBound);
    ASSERT_NE(status, -1) << transport;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
    EXPECT_NE(run.output().find("interrupted by SIGTERM"), std::string::npos) << run.output();
    EXPECT_TRUE(wait_gone(network, kStopBound)) << transport;
    expect_nothing_left(dir, run.pid());
    // The log of an interrupted run is kept, and says so.
    EXPECT_NE(read_file(dir.path() / "run" / "run.log").find("run failed: interrupted by SIGTERM"),
              std::string::npos);
  }
}

// A robot half stopped (Ctrl-Z) longer than the step timeout: the network half gives up, and when
// the robot half resumes it reports the network half's reason, not only its exit status, on
// every transport.
TEST(PeerFailure, TheNetworkHalfsReasonReachesTheRobotHalfOnEveryTransport) {
  for (const char* transport : {"shm", "uds", "tcp"}) {
    TempDir dir;
    BackgroundRun run(dir, {"--transport", transport, "--step-timeout", "1"});
    ASSERT_GT(run.network_half(), 0) << run.output();
    ASSERT_EQ(::kill(run.pid(), SIGSTOP), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    ASSERT_EQ(::kill(run.pid(), SIGCONT), 0);
    const int status = run.wait_exit(kStopBound);
    ASSERT_NE(status, -1) << transport;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
    EXPECT_NE(run.output().find("the network half failed: lost the robot half: no answer within "
                                "the step timeout"),
              std::string::npos)
        << transport << ": " << run.output();
  }
}

// A closed terminal (SIGHUP) stops a run as Ctrl-C does: both halves, no temporary files, a log
// that says why.
TEST(PeerFailure, HangupStopsBothHalvesCleanly) {
  TempDir dir;
  BackgroundRun run(dir, {});
  const pid_t network = run.network_half();
  ASSERT_GT(network, 0) << run.output();
  ASSERT_EQ(::kill(run.pid(), SIGHUP), 0);
  const int status = run.wait_exit(kStopBound);
  ASSERT_NE(status, -1);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGHUP) << status;
  EXPECT_NE(run.output().find("interrupted by SIGHUP"), std::string::npos) << run.output();
  EXPECT_TRUE(wait_gone(network, kStopBound));
  expect_nothing_left(dir, run.pid());
  EXPECT_NE(read_file(dir.path() / "run" / "run.log").find("run failed: interrupted by SIGHUP"),
            std::string::npos);
}

// A robot half killed outright cannot clean up; `swarmnet clean` removes what it left, and says so.
TEST(PeerFailure, CleanRemovesWhatAKilledRunLeft) {
  TempDir dir;
  BackgroundRun run(dir, {});
  ASSERT_GT(run.network_half(), 0) << run.output();
  ASSERT_EQ(::kill(run.pid(), SIGKILL), 0);
  ASSERT_NE(run.wait_exit(kStopBound), -1);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the network half dies with it
  std::size_t leftovers = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "run")) {
    leftovers += entry.path().filename().string().find(".partial-") != std::string::npos;
  }
  ASSERT_GT(leftovers, 0U) << "a killed run should have left temporary files to clean";
  const CommandResult cleaned = run_swarmnet("clean " + (dir.path() / "run").string());
  EXPECT_EQ(cleaned.exit_code, 0) << cleaned.output;
  EXPECT_NE(cleaned.output.find("removed " + std::to_string(leftovers) + " temporary file(s)"),
            std::string::npos)
      << cleaned.output;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "run")) {
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace swarmnet::testing
