// The command as a user meets it: the default run, and bad input answered with a clear message
// and a non-zero exit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "command_runner.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet::testing {
namespace {

TEST(CommandLine, DefaultRunPrintsItsSummary) {
  TempDir dir;
  const auto result = run_swarmnet("run --set duration_s=10 --out " + dir.path().string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* text :
       {"robots        50", "simulated", "real time", "delivered", "delivery ratio", "outputs"}) {
    EXPECT_NE(result.output.find(text), std::string::npos) << "missing '" << text << "' in\n"
                                                           << result.output;
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "summary.json"));
}

// The argument parser quotes a refused value; a 100 KB one is cut, its length said.
TEST(CommandLine, AHugeRefusedArgumentIsEchoedCut) {
  const std::string huge(100000, 'x');
  const auto result = run_swarmnet("run --transport " + huge);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_LT(result.output.size(), 1000U) << result.output.substr(0, 2000);
  EXPECT_NE(result.output.find("bytes)"), std::string::npos) << result.output.substr(0, 2000);
}

// --max-memory takes sizes with binary units (CLI11's AsSizeValue); nonsense and 0 are refused.
TEST(CommandLine, AMemoryBudgetIsASizeWithAUnit) {
  const auto unknown = run_swarmnet("net --listen 127.0.0.1:0 --max-memory lots");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("unit not recognized"), std::string::npos) << unknown.output;
  const auto zero = run_swarmnet("net --listen 127.0.0.1:0 --max-memory 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("not in range 1 to"), std::string::npos) << zero.output;
}

TEST(CommandLine, HelpNamesTheCommand) {
  for (const char* arguments : {"help", "--help"}) {
    const auto result = run_swarmnet(arguments);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("Usage: swarmnet [OPTIONS] SUBCOMMAND"), std::string::npos)
        << arguments << ":\n"
        << result.output;
  }
  const auto run_help = run_swarmnet("run --help");
  EXPECT_NE(run_help.output.find("Usage: swarmnet run"), std::string::npos) << run_help.output;
}

TEST(CommandLine, VersionShowsThePluginAbi) {
  const auto result = run_swarmnet("--version");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("swarmnet " SWARMNET_TEST_VERSION " (plugin ABI version " +
                               std::to_string(kAbiVersion) + ")"),
            std::string::npos)
      << result.output;
}

TEST(CommandLine, MissingScenarioFileIsRefused) {
  const auto result = run_swarmnet("run /nonexistent/scenario.yaml");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("/nonexistent/scenario.yaml"), std::string::npos) << result.output;
}

TEST(CommandLine, BadOverrideNamesTheKey) {
  const auto result = run_swarmnet("validate " + std::string(SWARMNET_SOURCE_DIR) +
                                   "/configs/quickstart.yaml --set robots.cuont=3");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("robots.cuont"), std::string::npos) << result.output;
}

TEST(CommandLine, ValidateAcceptsTheQuickstart) {
  const auto result =
      run_swarmnet("validate " + std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("valid scenario 'quickstart'"), std::string::npos) << result.output;
}

TEST(CommandLine, PluginsListsEveryKind) {
  const auto result = run_swarmnet("plugins");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* name :
       {"kinematic2d", "diffusion", "cbr", "disk", "ideal_mac", "direct", "flooding"}) {
    EXPECT_NE(result.output.find(name), std::string::npos) << name << " not listed";
  }
  const auto one = run_swarmnet("plugins flooding");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_NE(one.output.find("ttl"), std::string::npos) << one.output;
  const auto missing = run_swarmnet("plugins no_such_plugin");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("no_such_plugin"), std::string::npos);
}

TEST(CommandLine, UnwritableOutputDirectoryIsReported) {
  const auto result = run_swarmnet("run --set duration_s=1 --out /proc/swarmnet-cannot-write");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("/proc/swarmnet-cannot-write"), std::string::npos) << result.output;
}

TEST(CommandLine, ANegativeOrHugeSeedIsRefusedAsWritten) {
  for (const char* seed : {"-1", "18446744073709551615", "12x"}) {
    const auto result = run_swarmnet("validate " + std::string(SWARMNET_SOURCE_DIR) +
                                     "/configs/quickstart.yaml --seed " + seed);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(std::string("'") + seed + "' is not a seed"), std::string::npos)
        << result.output;
  }
}

TEST(CommandLine, ADeviceOrAHugeFileIsNotReadAsAScenario) {
  const auto result = run_swarmnet("validate /dev/zero");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("/dev/zero: is not a regular file"), std::string::npos)
      << result.output;
  TempDir dir;
  const auto huge = dir.path() / "huge.yaml";
  std::ofstream(huge) << "name: x\n";
  std::filesystem::resize_file(huge, std::uintmax_t{65} << 20U);  // sparse: no disk used
  const auto too_big = run_swarmnet("validate " + huge.string());
  EXPECT_EQ(too_big.exit_code, 2);
  EXPECT_NE(too_big.output.find("at most 64 MiB"), std::string::npos) << too_big.output;
}

TEST(CommandLine, AnEmptyScenarioIsRefusedAtItsFirstLine) {
  TempDir dir;
  const auto file = dir.path() / "empty.yaml";
  std::ofstream(file) << "# nothing but a comment\n";
  const auto result = run_swarmnet("validate " + file.string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find(file.string() + ":1:1: duration_s: missing required key"),
            std::string::npos)
      << result.output;
}

TEST(CommandLine, ARunDirectoryHoldingAnEarlierRunIsReplacedOnlyWhenAsked) {
  TempDir dir;
  const std::string run = "run --set duration_s=1 -q --out " + dir.path().string();
  ASSERT_EQ(run_swarmnet(run).exit_code, 0);
  const auto again = run_swarmnet(run);
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.output.find("holds an earlier run"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("--overwrite"), std::string::npos) << again.output;
  std::ofstream(dir.path() / "notes.txt") << "mine\n";
  // An output this run does not write (nothing samples) goes with the earlier run's.
  std::ofstream(dir.path() / "series.csv") << "time_ns,robot,series,value\n0,0,stale,1\n";
  const auto replaced = run_swarmnet(run + " --overwrite");
  EXPECT_EQ(replaced.exit_code, 0) << replaced.output;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "summary.json"));
  EXPECT_EQ(read_file(dir.path() / "notes.txt"), "mine\n");  // never removed
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "series.csv"));
  EXPECT_NE(read_file(dir.path() / "run.log").find("--overwrite: removed the earlier run's"),
            std::string::npos);
}

// A disk that fills up at summary.json: the run fails, and run.log (its room reserved at the
// start) says why instead of ending like a finished run's. Every other point the disk can fill at
// is in disk_full_test.cpp.
TEST(CommandLine, ADiskFullAtTheSummaryLeavesNoLogSayingFinished) {
  TempDir dir;
  const auto mount_point = dir.path() / "tiny";
  std::filesystem::create_directories(mount_point);
  // 17 pages: run.log's reserved room takes 16, the resolved scenario one, none is left for
  // summary.json.
  if (std::system(
          ("mount -t tmpfs -o size=68k tmpfs " + mount_point.string() + " 2>/dev/null").c_str()) !=
      0) {
    GTEST_SKIP() << "cannot mount a small tmpfs here (needs root): the disk-full case is untested";
  }
  const auto result = run_swarmnet(
      "run --set duration_s=1 --set output.packet_trace=false --set output.mobility_trace=false "
      "--set output.traffic_schedule=false -q --out " +
      (mount_point / "run").string());
  const bool has_summary = std::filesystem::exists(mount_point / "run" / "summary.json");
  const std::string log = read_file(mount_point / "run" / "run.log");
  std::system(("umount " + mount_point.string()).c_str());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("No space left on device"), std::string::npos) << result.output;
  EXPECT_FALSE(has_summary);
  EXPECT_EQ(log.find("finished:"), std::string::npos) << log;
  EXPECT_TRUE(log.ends_with("run failed: cannot write " +
                            (mount_point / "run" / "summary.json").string() +
                            ": No space left on device\n"))
      << log;
}

}  // namespace
}  // namespace swarmnet::testing
