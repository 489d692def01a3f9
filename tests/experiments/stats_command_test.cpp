// `swarmnet stats` on results files written in the test: short labels for grid values that are
// YAML mappings, comparisons against a baseline or within one factor, Holm's correction, and
// intervals that stay inside [0, 1] for ratios.
#include "experiments/stats_command.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command_runner.hpp"
#include "experiments/group_labels.hpp"

namespace swarmnet {
namespace {

using testing::TempDir;

TEST(GroupLabels, AMappingIsNamedByItsPluginAndWhatDiffers) {
  EXPECT_EQ(short_labels({"{plugin: flooding, params: {ttl: 32, jitter_max_s: 0.005}}",
                          "{plugin: flooding, params: {ttl: 16, jitter_max_s: 0.005}}",
                          "{plugin: aodv}", "{plugin: direct, params: {x: 1}}"}),
            (std::vector<std::string>{"flooding ttl=32", "flooding ttl=16", "aodv", "direct"}));
  // Without a plugin: what differs, or everything when nothing does.
  EXPECT_EQ(short_labels({"{width_m: 100, height_m: 50}", "{width_m: 200, height_m: 50}"}),
            (std::vector<std::string>{"width_m=100", "width_m=200"}));
  EXPECT_EQ(short_labels({"{width_m: 100, height_m: 50}"}),
            (std::vector<std::string>{"width_m=100 height_m=50"}));
  // Plain values are their own names; equal values get equal names.
  EXPECT_EQ(short_labels({"10", "20", "10"}), (std::vector<std::string>{"10", "20", "10"}));
  EXPECT_EQ(short_labels({"{not yaml", "plain"}), (std::vector<std::string>{"{not yaml", "plain"}));
}

// 8 groups: two swarm sizes x four routing settings, three seeds each.
std::filesystem::path write_results(const TempDir& dir) {
  const std::filesystem::path path = dir.path() / "results.csv";
  std::ofstream out(path);
  out << "run_id,seed,status,robots.count,network.routing,pdr,delay_s.mean\n";
  const char* routing[] = {"\"{plugin: flooding, params: {ttl: 32, jitter_max_s: 0.005}}\"",
                           "\"{plugin: flooding, params: {ttl: 16, jitter_max_s: 0.005}}\"",
                           "\"{plugin: aodv}\"", "\"{plugin: direct}\""};
  for (int n : {10, 20}) {
    for (int r = 0; r < 4; ++r) {
      for (int seed = 1; seed <= 3; ++seed) {
        const double pdr = r == 2 ? 0.97 + 0.01 * seed : 0.5 + 0.1 * r + 0.02 * seed;
        out << "r," << seed << ",ok," << n << ',' << routing[r] << ',' << pdr << ','
            << 0.01 * (r + seed) << '\n';
      }
    }
  }
  return path;
}

std::string stats_output(const StatsOptions& options, int* code = nullptr) {
  std::ostringstream out;
  const int exit_code = stats_command(options, out);
  if (code != nullptr) *code = exit_code;
  return out.str();
}

StatsOptions options_for(const std::filesystem::path& file) {
  StatsOptions options;
  options.file = file;
  options.by = {"robots.count", "network.routing"};
  options.metrics = {"pdr"};
  return options;
}

TEST(StatsCommand, LabelsGroupsShortlyAndSaysThatAllPairsAreUncorrected) {
  TempDir dir;
  const std::string text = stats_output(options_for(write_results(dir)));
  EXPECT_NE(text.find("flooding ttl=32"), std::string::npos) << text;
  EXPECT_EQ(text.find("{plugin"), std::string::npos) << "whole mappings as labels:\n" << text;
  EXPECT_NE(text.find("28 comparisons; p not corrected for multiple comparisons"),
            std::string::npos)
      << text;
}

TEST(StatsCommand, WithinOneFactorAgainstABaselineWithHolm) {
  TempDir dir;
  StatsOptions options = options_for(write_results(dir));
  options.within = "network.routing";
  options.baseline = "aodv";
  options.holm = true;
  options.json = true;
  int code = -1;
  const auto json = nlohmann::json::parse(stats_output(options, &code));
  ASSERT_EQ(code, 0);
  const auto& tests = json["metrics"]["pdr"]["welch"];
  ASSERT_EQ(tests.size(), 6U) << "3 comparisons with aodv in each of 2 swarm sizes";
  for (const auto& test : tests) {
    const std::string a = test["a"];
    const std::string b = test["b"];
    EXPECT_TRUE(a == "10,aodv" || a == "20,aodv") << a;
    EXPECT_EQ(a.substr(0, 3), b.substr(0, 3)) << "the same swarm size on both sides";
    EXPECT_GE(test["p_holm"].get<double>(), test["p"].get<double>());
  }
  // A baseline that names no value of the column is refused, naming the values there are.
  options.baseline = "olsr";
  stats_output(options, &code);
  EXPECT_EQ(code, 2);
  options.baseline = "aodv";
  options.within = "seed";
  stats_output(options, &code);
  EXPECT_EQ(code, 2) << "--within must be a --by column";
}

TEST(StatsCommand, ARatiosIntervalStaysInsideZeroToOne) {
  TempDir dir;
  StatsOptions options = options_for(write_results(dir));
  options.metrics = {"pdr", "delay_s.mean"};
  options.json = true;
  const auto json = nlohmann::json::parse(stats_output(options));
  EXPECT_EQ(json["metrics"]["pdr"]["interval"], "wilson_effective_n");
  EXPECT_EQ(json["metrics"]["delay_s.mean"]["interval"], "student_t");
  for (const auto& group : json["metrics"]["pdr"]["groups"]) {
    EXPECT_LE(group["ci_high"].get<double>(), 1.0) << group.dump();
    EXPECT_GE(group["ci_low"].get<double>(), 0.0) << group.dump();
  }
  // --bounded on a metric that leaves [0, 1] is refused.
  options.metrics = {"robots.count"};
  options.bounded = true;
  int code = -1;
  stats_output(options, &code);
  EXPECT_EQ(code, 2);
}

}  // namespace
}  // namespace swarmnet
