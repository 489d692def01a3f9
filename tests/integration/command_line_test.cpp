// The command as a user meets it: the default run, and bad input answered with a clear message
// and a non-zero exit.
#include <gtest/gtest.h>

#include "command_runner.hpp"

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

}  // namespace
}  // namespace swarmnet::testing
