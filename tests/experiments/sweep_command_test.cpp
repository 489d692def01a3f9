// `swarmnet sweep` and `swarmnet stats` end to end: runs in parallel, results.csv, resuming,
// a failed run that does not stop the others, and a typo caught before anything runs.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kQuickstart = std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml";

std::filesystem::path write_sweep(const TempDir& dir, const std::string& grid) {
  auto path = dir.path() / "s.yaml";
  std::ofstream(path) << "base: " << kQuickstart << "\n"
                      << "set:\n  duration_s: 2\n  arena.width_m: 120\n  arena.height_m: 120\n"
                      << "  arena.obstacles: []\n"
                      << "grid:\n"
                      << grid << "seeds: [1, 2]\n";
  return path;
}

std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(SweepCommand, RunsEveryCombinationResumesAndFeedsStats) {
  TempDir dir;
  const auto sweep = write_sweep(dir, "  robots.count: [5, 8]\n");
  const auto out = dir.path() / "out";
  const std::string command = "sweep " + sweep.string() + " -j 2 --out " + out.string();
  auto result = run_swarmnet(command);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("[4/4] ok"), std::string::npos) << result.output;
  for (const char* id : {"count-5_seed-1", "count-5_seed-2", "count-8_seed-1", "count-8_seed-2"}) {
    const auto summary = nlohmann::json::parse(read_file(out / "runs" / id / "summary.json"));
    EXPECT_EQ(summary["robots"], std::string(id).starts_with("count-5") ? 5 : 8) << id;
  }
  const std::string csv = read_file(out / "results.csv");
  EXPECT_EQ(count_lines(csv), 5U) << csv;
  EXPECT_TRUE(csv.starts_with("run_id,seed,status,robots.count,scenario,")) << csv;
  EXPECT_NE(csv.find(",delay_s.p95,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ncount-8_seed-2,2,ok,8,"), std::string::npos) << csv;

  // Finished runs are skipped; a run without summary.json (interrupted) is redone.
  std::filesystem::remove(out / "runs" / "count-8_seed-1" / "summary.json");
  const auto kept = std::filesystem::last_write_time(out / "runs/count-5_seed-1/summary.json");
  result = run_swarmnet(command);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("3 finished before, 1 to run"), std::string::npos) << result.output;
  EXPECT_EQ(kept, std::filesystem::last_write_time(out / "runs/count-5_seed-1/summary.json"));
  EXPECT_TRUE(std::filesystem::exists(out / "runs" / "count-8_seed-1" / "summary.json"));
  EXPECT_EQ(count_lines(read_file(out / "results.csv")), 5U);

  result = run_swarmnet("stats " + (out / "results.csv").string() +
                        " --by robots.count --metric pdr --metric packets.sent --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  const auto& groups = json["metrics"]["packets.sent"]["groups"];
  ASSERT_EQ(groups.size(), 2U);
  EXPECT_EQ(groups[0]["group"]["robots.count"], "5");
  EXPECT_EQ(groups[0]["n"], 2);
  EXPECT_EQ(json["metrics"]["pdr"]["welch"].size(), 1U);

  result =
      run_swarmnet("stats " + (out / "results.csv").string() + " --by robots.count --metric pdr");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("95% CI low"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("Welch's t-test of pdr"), std::string::npos) << result.output;
  result = run_swarmnet("stats " + (out / "results.csv").string() + " --by robot --metric pdr");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("no column 'robot' (--by)"), std::string::npos) << result.output;
}

TEST(SweepCommand, AFailedRunIsReportedAndTheOthersFinish) {
  TempDir dir;
  const auto sweep = write_sweep(dir, "  robots.count: [5]\n");
  const auto out = dir.path() / "out";
  // A directory where the run's log must go makes that run (and only it) fail at its end.
  std::filesystem::create_directories(out / "runs" / "count-5_seed-2" / "run.log" / "blocker");
  const auto result = run_swarmnet("sweep " + sweep.string() + " -j 2 --out " + out.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("FAILED count-5_seed-2"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("failed: count-5_seed-2 (log: "), std::string::npos)
      << result.output;
  EXPECT_TRUE(std::filesystem::exists(out / "runs" / "count-5_seed-1" / "summary.json"));
  const std::string csv = read_file(out / "results.csv");
  EXPECT_NE(csv.find("\ncount-5_seed-1,1,ok,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ncount-5_seed-2,2,failed,"), std::string::npos) << csv;
}

TEST(SweepCommand, ATypoFailsBeforeAnythingRuns) {
  TempDir dir;
  const auto sweep = write_sweep(dir, "  robots.cuont: [5, 8]\n");
  const auto out = dir.path() / "out";
  const auto result = run_swarmnet("sweep " + sweep.string() + " --out " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  // The value's place in the sweep file, then the scenario module's own message.
  EXPECT_NE(result.output.find(sweep.string() + ":8:18: grid robots.cuont=5: --set robots.cuont"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "runs"));
}

// A linked axis: the robot count and the arena's side change together, as one axis.
TEST(SweepCommand, ALinkedAxisSetsItsKeysTogether) {
  TempDir dir;
  auto sweep = dir.path() / "linked.yaml";
  std::ofstream(sweep) << "base: " << kQuickstart << "\n"
                       << "set:\n  duration_s: 2\n  arena.obstacles: []\n"
                       << "grid:\n  size:\n"
                       << "    robots.count: [5, 8]\n"
                       << "    arena.width_m: [100, 130]\n"
                       << "    arena.height_m: [90, 120]\n"
                       << "seeds: [1]\n";
  const auto out = dir.path() / "out";
  const auto result = run_swarmnet("sweep " + sweep.string() + " -j 2 --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto summary =
      nlohmann::json::parse(read_file(out / "runs" / "size-8_seed-1" / "summary.json"));
  EXPECT_EQ(summary["robots"], 8);
  const std::string resolved = read_file(out / "runs" / "size-8_seed-1" / "scenario.resolved.yaml");
  EXPECT_NE(resolved.find("width_m: 130\n"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("height_m: 120\n"), std::string::npos) << resolved;
  const std::string csv = read_file(out / "results.csv");
  EXPECT_TRUE(csv.starts_with("run_id,seed,status,robots.count,arena.width_m,arena.height_m,"))
      << csv;
  EXPECT_NE(csv.find("\nsize-5_seed-1,1,ok,5,100,90,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nsize-8_seed-1,1,ok,8,130,120,"), std::string::npos) << csv;
  EXPECT_EQ(count_lines(csv), 3U) << csv;
}

TEST(SweepCommand, ATypoInALinkedKeyIsLocatedAtItsValue) {
  TempDir dir;
  auto sweep = dir.path() / "linked.yaml";
  std::ofstream(sweep) << "base: " << kQuickstart << "\n"
                       << "grid:\n  size:\n"
                       << "    robots.count: [5, 8]\n"
                       << "    arena.widht_m: [100, 130]\n";
  const auto out = dir.path() / "out";
  const auto result = run_swarmnet("sweep " + sweep.string() + " --out " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(sweep.string() +
                               ":5:21: grid size: arena.widht_m=100: --set arena.widht_m"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "runs"));
}

// Ctrl-C: no new run starts, the running one stops, finished work and results.csv stay, and the
// same command later finishes the rest.
TEST(SweepCommand, SigintStopsTheChildrenAndKeepsWhatFinished) {
  TempDir dir;
  auto path = dir.path() / "long.yaml";
  std::ofstream(path) << "base: " << kQuickstart << "\n"
                      << "set:\n  duration_s: 900\n  arena.obstacles: []\n"
                      << "grid:\n  robots.count: [60]\nseeds: [1, 2]\n";
  const auto out = dir.path() / "out";
  std::vector<std::string> args = {swarmnet_binary(), "sweep",     path.string(), "-j", "1",
                                   "--out",           out.string()};
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);
  const auto first = out / "runs" / "count-60_seed-1" / "scenario.resolved.yaml";
  for (int i = 0; i < 200 && !std::filesystem::exists(first); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(std::filesystem::exists(first)) << "the first run did not start";
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  EXPECT_FALSE(std::filesystem::exists(out / "runs" / "count-60_seed-1" / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(out / "runs" / "count-60_seed-2"));  // never started
  const std::string csv = read_file(out / "results.csv");
  EXPECT_NE(csv.find("\ncount-60_seed-1,1,not run,"), std::string::npos) << csv;
  EXPECT_NE(read_file(out / "runs" / "count-60_seed-1" / "run.log").find("interrupted"),
            std::string::npos);
}

// A grid too large to expand is refused with its size, before anything is built.
TEST(SweepCommand, AHugeGridIsRefusedWithItsCount) {
  TempDir dir;
  std::string values = "[";
  for (int i = 1; i <= 100; ++i) values += std::to_string(i) + (i < 100 ? ", " : "]");
  auto path = dir.path() / "huge.yaml";
  std::ofstream(path) << "base: " << kQuickstart << "\n"
                      << "grid:\n  robots.count: " << values << "\n  duration_s: " << values
                      << "\n  step_s: [0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]"
                      << "\n  seed: " << values << "\nseeds: " << values << "\n";
  const auto result = run_swarmnet("sweep " + path.string() + " --check");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("expands into 1000000000 runs; at most 1000000"), std::string::npos)
      << result.output;
}

// A sweep holds its directory: a second one into it is refused while the first runs, and a
// killed sweep takes its runs with it.
TEST(SweepCommand, OneSweepAtATimeAndItsRunsDieWithIt) {
  TempDir dir;
  auto path = dir.path() / "long.yaml";
  std::ofstream(path) << "base: " << kQuickstart << "\n"
                      << "set:\n  duration_s: 900\n  arena.obstacles: []\n"
                      << "grid:\n  robots.count: [60]\nseeds: [1]\n";
  const auto out = dir.path() / "out";
  const pid_t sweep = spawn_swarmnet({"sweep", path.string(), "-j", "1", "--out", out.string()},
                                     dir.path() / "sweep.log");
  const auto run_dir = out / "runs" / "count-60_seed-1";
  for (int i = 0; i < 200 && !std::filesystem::exists(run_dir / "scenario.resolved.yaml"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(std::filesystem::exists(run_dir / "scenario.resolved.yaml"));
  const auto second = run_swarmnet("sweep " + path.string() + " -j 1 --out " + out.string());
  EXPECT_EQ(second.exit_code, 1) << second.output;
  EXPECT_NE(second.output.find("another sweep (pid " + std::to_string(sweep) + ") is running"),
            std::string::npos)
      << second.output;

  // The run's pid, from the kernel's list of the sweep's children.
  pid_t run = 0;
  std::ifstream(std::string("/proc/") + std::to_string(sweep) + "/task/" + std::to_string(sweep) +
                "/children") >>
      run;
  ASSERT_GT(run, 0);
  ASSERT_EQ(::kill(sweep, SIGKILL), 0);
  ASSERT_EQ(::waitpid(sweep, nullptr, 0), sweep);
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = ::kill(run, 0) != 0;
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  EXPECT_TRUE(gone) << "the run outlived its killed sweep";
}

}  // namespace
}  // namespace swarmnet::testing
