// `swarmnet sweep --slurm / --status / --collect` against a real Slurm: a one-node cluster
// started from Debian's packages (slurm_cluster.hpp). A 6-run sweep with one run made to fail is
// submitted, watched, collected, fixed and resubmitted (only that run), and its results.csv is
// compared byte for byte, timing columns aside, with the same sweep run locally. Skipped, with
// the reason, only where the daemons cannot start.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "command_runner.hpp"
#include "slurm_cluster.hpp"

namespace swarmnet::testing {
namespace {

const std::string kQuickstart = std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml";

// The run whose task is made to fail: a directory where its run.log must go.
const std::string kBroken = "count-8_seed-2";

class SlurmSweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cluster_ = new SlurmCluster();
    // At most 4 tasks per array: the 6-run sweep becomes two arrays, as a 1500-run study would
    // on a cluster with Slurm's default of 1001.
    cluster_->set_max_array_size(4);
    why_not_ = cluster_->start();
  }
  static void TearDownTestSuite() {
    const auto directory = cluster_->directory();
    delete cluster_;  // cancels every job, stops the daemons, removes their directory
    cluster_ = nullptr;
    if (directory.empty()) return;
    EXPECT_EQ(SlurmCluster::processes_using(directory), "") << "left running";
    EXPECT_FALSE(std::filesystem::exists(directory));
  }
  void SetUp() override {
    if (!why_not_.empty()) GTEST_SKIP() << "no Slurm cluster on this machine: " << why_not_;
  }

  static SlurmCluster* cluster_;
  static std::string why_not_;
};

SlurmCluster* SlurmSweep::cluster_ = nullptr;
std::string SlurmSweep::why_not_;

std::filesystem::path write_sweep(const TempDir& dir) {
  auto path = dir.path() / "tiny.yaml";
  std::ofstream(path) << "base: " << kQuickstart << "\n"
                      << "set:\n  duration_s: 2\n  arena.width_m: 120\n  arena.height_m: 120\n"
                      << "  arena.obstacles: []\n"
                      << "grid:\n  robots.count: [5, 8, 10]\n"
                      << "seeds: [1, 2]\n";
  return path;
}

// Polls --status until no run is running or pending; returns the last status output.
std::string wait_for_sweep(const std::string& status_command, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::string output;
  while (std::chrono::steady_clock::now() < deadline) {
    output = run_swarmnet(status_command).output;
    if (output.find(" 0 running, 0 pending,") != std::string::npos) return output;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  ADD_FAILURE() << "the sweep did not finish within " << timeout.count() << " s:\n" << output;
  return output;
}

// results.csv as rows of cells (no cell of these sweeps is quoted), without timing columns.
std::vector<std::vector<std::string>> without_timing(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  std::vector<bool> keep;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (line.ends_with(",")) cells.emplace_back();
    if (keep.empty()) {
      for (const auto& name : cells) {
        keep.push_back(name != "wall_s" && name != "realtime_factor" && name != "transport_share" &&
                       !name.starts_with("cpu_s."));
      }
    }
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < cells.size() && i < keep.size(); ++i) {
      if (keep[i]) kept.push_back(cells[i]);
    }
    rows.push_back(std::move(kept));
  }
  return rows;
}

TEST_F(SlurmSweep, SubmitsStatusCollectsAndResubmitsOnlyTheFailedRun) {
  TempDir dir;
  const auto sweep = write_sweep(dir);
  const auto out = dir.path() / "cluster";
  const std::string on_slurm = "sweep " + sweep.string() + " --out " + out.string();

  // The same sweep run here, for the comparison.
  const auto local =
      run_swarmnet("sweep " + sweep.string() + " -j 2 --out " + (dir.path() / "local").string());
  ASSERT_EQ(local.exit_code, 0) << local.output;

  // A job sbatch refuses: the command and Slurm's reason, nothing recorded as submitted.
  auto refused = run_swarmnet(on_slurm + " --slurm --partition no-such-partition");
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("sbatch did not accept the job array"), std::string::npos)
      << refused.output;
  EXPECT_NE(refused.output.find("Invalid partition name specified"), std::string::npos)
      << refused.output;
  EXPECT_FALSE(std::filesystem::exists(out / "slurm" / "jobs"));

  std::filesystem::create_directories(out / "runs" / kBroken / "run.log" / "blocker");
  auto submitted = run_swarmnet(on_slurm + " --slurm --max-parallel 2");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(submitted.output, match, std::regex("(?:^|\\n)([0-9]+)\\n")))
      << submitted.output;
  const std::string first_job = match[1];
  const std::string rest = match.suffix();
  ASSERT_TRUE(std::regex_search(rest, match, std::regex("^([0-9]+)\\n"))) << submitted.output;
  const std::string second_job = match[1];
  EXPECT_NE(submitted.output.find("6 submitted (0 failed before) as Slurm job arrays " + first_job +
                                  " (4 runs), " + second_job +
                                  " (2 runs) (this cluster's MaxArraySize is 4; at most 2 at a "
                                  "time in each)"),
            std::string::npos)
      << submitted.output;

  // The script: one array, throttled, and no path outside the sweep directory and swarmnet's.
  const std::string script = read_file(out / "slurm" / "submit-1.sh");
  EXPECT_NE(script.find("#SBATCH --array=0-3%2\n"), std::string::npos) << script;
  const std::filesystem::path bin = std::filesystem::canonical(swarmnet_binary());
  std::smatch path;
  for (auto it = script.cbegin();
       std::regex_search(it, script.cend(), path, std::regex("(^|[ ='\"])(/[^ '\"\\n]*)"));
       it = path[0].second) {
    const std::string p = path[2];
    EXPECT_TRUE(p.starts_with(out.string()) || p == bin.string() || p == "/bin/bash" ||
                p == "/dev/null")
        << "the job script names " << p << ":\n"
        << script;
  }
  EXPECT_EQ(read_file(out / "slurm" / "submit-1.tasks"),
            "count-5_seed-1\ncount-5_seed-2\ncount-8_seed-1\ncount-8_seed-2\n");
  EXPECT_EQ(read_file(out / "slurm" / "submit-2.tasks"), "count-10_seed-1\ncount-10_seed-2\n");
  EXPECT_NE(read_file(out / "slurm" / "submit-2.sh").find("#SBATCH --array=0-1%2\n"),
            std::string::npos);

  const std::string status_command = on_slurm + " --status";
  std::string status = wait_for_sweep(status_command, std::chrono::seconds(120));
  EXPECT_NE(status.find("6 runs: 5 done, 0 running, 0 pending, 1 failed, 0 not submitted"),
            std::string::npos)
      << status;
  // Which run, its Slurm task and state, and where to look.
  EXPECT_NE(
      status.find("failed: " + kBroken + " (Slurm task " + first_job + "_3: FAILED, exit 1:0;"),
      std::string::npos)
      << status;
  EXPECT_NE(
      status.find("Slurm log: " + (out / "slurm" / "logs").string() + "/" + first_job + "_3.log"),
      std::string::npos)
      << status;
  EXPECT_NE(status.find("output: " + (out / "runs" / kBroken / "output.log").string()),
            std::string::npos)
      << status;
  // This cluster keeps no accounting: said so, and scontrol used instead.
  EXPECT_NE(status.find("sacct is unavailable"), std::string::npos) << status;
  EXPECT_TRUE(std::filesystem::exists(out / "slurm" / "logs" / (first_job + "_3.log")));

  auto collected = run_swarmnet(on_slurm + " --collect");
  EXPECT_EQ(collected.exit_code, 1) << collected.output;
  EXPECT_NE(read_file(out / "results.csv").find("\n" + kBroken + ",2,failed,8,"),
            std::string::npos);

  // Fixed, then submitted again: that run alone, the others untouched.
  const auto kept = std::filesystem::last_write_time(out / "runs/count-5_seed-1/summary.json");
  std::filesystem::remove_all(out / "runs" / kBroken / "run.log");
  submitted = run_swarmnet(on_slurm + " --slurm --max-parallel 2");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.output;
  ASSERT_TRUE(std::regex_search(submitted.output, match, std::regex("(?:^|\\n)([0-9]+)\\n")))
      << submitted.output;
  const std::string third_job = match[1];
  EXPECT_NE(submitted.output.find("5 done, 0 queued or running before, 1 submitted (1 failed "
                                  "before) as Slurm job array " +
                                  third_job + " (submission 3, at most 2 at a time)"),
            std::string::npos)
      << submitted.output;
  EXPECT_EQ(read_file(out / "slurm" / "submit-3.tasks"), kBroken + "\n");
  EXPECT_NE(read_file(out / "slurm" / "submit-3.sh").find("#SBATCH --array=0-0%2\n"),
            std::string::npos);

  status = wait_for_sweep(status_command, std::chrono::seconds(120));
  EXPECT_NE(status.find("6 runs: 6 done, 0 running, 0 pending, 0 failed, 0 not submitted"),
            std::string::npos)
      << status;
  EXPECT_EQ(kept, std::filesystem::last_write_time(out / "runs/count-5_seed-1/summary.json"));
  collected = run_swarmnet(on_slurm + " --collect");
  EXPECT_EQ(collected.exit_code, 0) << collected.output;

  const std::string cluster_csv = read_file(out / "results.csv");
  const std::string local_csv = read_file(dir.path() / "local" / "results.csv");
  const auto cluster_rows = without_timing(cluster_csv);
  const auto local_rows = without_timing(local_csv);
  ASSERT_EQ(cluster_rows.size(), 7U) << cluster_csv;
  EXPECT_EQ(cluster_rows, local_rows) << "on Slurm:\n" << cluster_csv << "\nhere:\n" << local_csv;
  // Only the timing columns were left out, and they are there.
  EXPECT_NE(cluster_csv.find(",wall_s,"), std::string::npos);
  EXPECT_EQ(cluster_csv.substr(0, cluster_csv.find('\n')),
            local_csv.substr(0, local_csv.find('\n')));

  // Nothing left to do.
  submitted = run_swarmnet(on_slurm + " --slurm");
  EXPECT_EQ(submitted.exit_code, 0) << submitted.output;
  EXPECT_NE(submitted.output.find("nothing to submit"), std::string::npos) << submitted.output;
}

}  // namespace
}  // namespace swarmnet::testing
