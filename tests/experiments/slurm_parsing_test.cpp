// The Slurm side of a sweep without a cluster: the job-array script, squeue/sacct/scontrol
// output as Slurm 22.05 prints it, and an sbatch that is not there. The real cluster is in
// slurm_sweep_test.cpp.
#include <gtest/gtest.h>

#include <fstream>

#include "command_runner.hpp"
#include "experiments/captured_command.hpp"
#include "experiments/slurm_status.hpp"
#include "experiments/slurm_submission.hpp"

namespace swarmnet::testing {
namespace {

using namespace std::string_literals;

TEST(SlurmScript, MapsTheArrayIndexToARunAndRunsItAsALocalSweepWould) {
  SlurmJobSettings settings;
  settings.swarmnet = "/opt/swarmnet/bin/swarmnet";
  settings.partition = "short";
  settings.time_limit = "00:30:00";
  settings.cpus_per_run = 2;
  settings.max_parallel = 50;
  settings.sbatch_args = {"--account=robots"};
  const std::string script =
      job_array_script("/shared/study/sweep", "swarmnet-routing", 3, 1500, settings);
  for (const char* line :
       {"#!/bin/bash\n", "#SBATCH --job-name=swarmnet-routing\n", "#SBATCH --array=0-1499%50\n",
        "#SBATCH --cpus-per-task=2\n",
        "#SBATCH --output=/shared/study/sweep/slurm/logs/%A_%a.log\n",
        "#SBATCH --chdir=/shared/study/sweep\n", "#SBATCH --partition=short\n",
        "#SBATCH --time=00:30:00\n", "#SBATCH --account=robots\n",
        "sweep_dir='/shared/study/sweep'\n", "swarmnet='/opt/swarmnet/bin/swarmnet'\n",
        "\"$sweep_dir/slurm/submit-3.tasks\"",
        "mapfile -d '' -t args < \"$sweep_dir/slurm/args/$id\"",
        "exec \"$swarmnet\" \"${args[@]}\" </dev/null >\"$run_dir/output.log\" 2>&1\n"}) {
    EXPECT_NE(script.find(line), std::string::npos) << line << " not in:\n" << script;
  }
  settings.max_parallel = 0;
  settings.partition.clear();
  settings.time_limit.clear();
  const std::string plain = job_array_script("/shared/it's here", "n", 1, 1, settings);
  EXPECT_NE(plain.find("#SBATCH --array=0-0\n"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("--partition"), std::string::npos) << plain;
  EXPECT_NE(plain.find("sweep_dir='/shared/it'\\''s here'\n"), std::string::npos) << plain;

  // Paths relative to the submitting shell, or a line break, cannot go into a job script.
  EXPECT_THROW((void)job_array_script("runs/sweep", "n", 1, 1, settings), std::invalid_argument);
  settings.sbatch_args = {"--comment=a\nb"};
  EXPECT_THROW((void)job_array_script("/shared/sweep", "n", 1, 1, settings), std::invalid_argument);
}

// The script itself, run by bash as a Slurm task would be, with a stand-in for swarmnet that
// prints its arguments: index 1 runs the second run with its arguments, NUL-separated on disk.
TEST(SlurmScript, TheTaskRunsTheRunOfItsIndexWithItsArguments) {
  TempDir dir;
  const auto sweep_dir = dir.path() / "sweep";
  std::filesystem::create_directories(sweep_dir / "slurm" / "args");
  std::ofstream(sweep_dir / "slurm" / "submit-1.tasks") << "a_seed-1\nb_seed-1\n";
  std::ofstream(sweep_dir / "slurm" / "args" / "b_seed-1", std::ios::binary)
      << "run\0/base.yaml\0--set\0routing={plugin: aodv, params: {x: 'a b'}}\0"s;
  const auto fake = dir.path() / "fake-swarmnet";
  std::ofstream(fake) << "#!/bin/bash\nfor a in \"$@\"; do echo \"[$a]\"; done\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  SlurmJobSettings settings;
  settings.swarmnet = fake;
  const auto script = dir.path() / "job.sh";
  std::ofstream(script) << job_array_script(sweep_dir, "n", 1, 2, settings);
  const CapturedCommand result =
      run_captured({"env", "SLURM_ARRAY_TASK_ID=1", "bash", script.string()});
  ASSERT_EQ(result.exit_code, 0) << result.output << result.errors;
  EXPECT_EQ(read_file(sweep_dir / "runs" / "b_seed-1" / "output.log"),
            "[run]\n[/base.yaml]\n[--set]\n[routing={plugin: aodv, params: {x: 'a b'}}]\n");

  const CapturedCommand missing =
      run_captured({"env", "SLURM_ARRAY_TASK_ID=7", "bash", script.string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.errors.find("no run for array index 7"), std::string::npos) << missing.errors;

  // A swarmnet path the node does not have: said in the task's Slurm log, before anything runs.
  settings.swarmnet = dir.path() / "not-installed" / "swarmnet";
  std::ofstream(script) << job_array_script(sweep_dir, "n", 1, 2, settings);
  const CapturedCommand absent =
      run_captured({"env", "SLURM_ARRAY_TASK_ID=0", "bash", script.string()});
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_NE(absent.errors.find(settings.swarmnet.string() + " is not an executable on "),
            std::string::npos)
      << absent.errors;
  EXPECT_FALSE(std::filesystem::exists(sweep_dir / "runs" / "a_seed-1"));
}

TEST(SlurmStatus, ReadsSqueueSacctAndScontrol) {
  // squeue -h -r -o %F|%K|%T: pending tasks one per line; a plain job has no index.
  const auto queued = parse_squeue("41|0|RUNNING\n41|3|PENDING\n40|N/A|RUNNING\n");
  ASSERT_EQ(queued.size(), 2U);
  EXPECT_EQ(queued.at({"41", 0}).state, "RUNNING");
  EXPECT_EQ(queued.at({"41", 3}).state, "PENDING");

  const auto accounted = parse_sacct(
      "41_0|COMPLETED|0:0\n41_1|FAILED|1:0\n41_2|CANCELLED by 0|0:15\n41_[4-9%2]|PENDING|0:0\n"
      "39|COMPLETED|0:0\n");
  ASSERT_EQ(accounted.size(), 3U);
  EXPECT_EQ(accounted.at({"41", 1}).state, "FAILED");
  EXPECT_EQ(accounted.at({"41", 1}).exit_code, "1:0");
  EXPECT_EQ(accounted.at({"41", 2}).state, "CANCELLED");

  const auto shown = parse_scontrol(
      "JobId=44 ArrayJobId=41 ArrayTaskId=3 ArrayTaskThrottle=2 JobName=swarmnet-s "
      "JobState=FAILED Reason=NonZeroExitCode ExitCode=1:0\n"
      "JobId=41 ArrayJobId=41 ArrayTaskId=4-9%2 JobState=PENDING ExitCode=0:0\n");
  ASSERT_EQ(shown.size(), 1U);
  EXPECT_EQ(shown.at({"41", 3}).state, "FAILED");
  EXPECT_EQ(shown.at({"41", 3}).exit_code, "1:0");

  EXPECT_TRUE(slurm_state_is_active("PENDING"));
  EXPECT_TRUE(slurm_state_is_active("COMPLETING"));
  EXPECT_FALSE(slurm_state_is_active("TIMEOUT"));
  EXPECT_TRUE(slurm_state_is_pending("REQUEUED"));
  EXPECT_FALSE(slurm_state_is_pending("RUNNING"));
}

TEST(CapturedCommand, KeepsOutputAndErrorsApartAndSaysWhatFailed) {
  const CapturedCommand ok = run_captured({"sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_TRUE(ok.started);
  EXPECT_EQ(ok.exit_code, 3);
  EXPECT_EQ(ok.output, "out\n");
  EXPECT_EQ(ok.errors, "err\n");
  EXPECT_EQ(describe_failure({"sh"}, ok), "sh: exit 3: err");
  const CapturedCommand missing = run_captured({"no-such-program-anywhere"});
  EXPECT_FALSE(missing.started);
  EXPECT_EQ(describe_failure({"no-such-program-anywhere"}, missing),
            "cannot run no-such-program-anywhere: No such file or directory");
}

// Without sbatch (a machine that is not a cluster's login node): the command and why.
TEST(SlurmSubmit, WithoutSbatchSaysSoAndSubmitsNothing) {
  TempDir dir;
  const auto sweep = dir.path() / "s.yaml";
  std::ofstream(sweep) << "base: " << SWARMNET_SOURCE_DIR << "/configs/quickstart.yaml\n"
                       << "grid:\n  robots.count: [5]\n";
  const auto out = dir.path() / "out";
  const auto result = run_swarmnet("sweep " + sweep.string() + " --out " + out.string() +
                                       " --slurm --swarmnet /opt/swarmnet/bin/swarmnet",
                                   "PATH=" + dir.path().string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("sbatch did not accept the job array " +
                               (out / "slurm" / "submit-1.sh").string() +
                               " (cannot run sbatch: No such file or directory)"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "slurm" / "jobs"));
  EXPECT_NE(read_file(out / "slurm" / "submit-1.sh").find("swarmnet='/opt/swarmnet/bin/swarmnet'"),
            std::string::npos);

  // --status of a sweep never submitted asks Slurm nothing.
  const auto status =
      run_swarmnet("sweep " + sweep.string() + " --out " + out.string() + " --status",
                   "PATH=" + dir.path().string());
  EXPECT_EQ(status.exit_code, 0) << status.output;
  EXPECT_NE(status.output.find(": 1 runs: 0 done, 0 running, 0 pending, 0 failed, 1 not submitted"),
            std::string::npos)
      << status.output;
}

}  // namespace
}  // namespace swarmnet::testing
