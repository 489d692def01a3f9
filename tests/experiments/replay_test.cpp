// `swarmnet replay`: the network half alone, fed from a run's positions.bin and traffic.csv,
// writes a packet trace byte-identical to the integrated run's, for every routing protocol over
// the ideal MAC and over 802.11 DCF with SINR reception, in both sync modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kConfigs = std::string(SWARMNET_SOURCE_DIR) + "/configs/";
const std::string kSmall =
    " --set robots.count=30 --set duration_s=10 --set arena.width_m=300 --set arena.height_m=300"
    " --set arena.obstacles=[] --quiet";

struct Stack {
  const char* name;
  const char* base;  // ideal_mac over a disk (aodv.yaml), dcf80211 with the sinr PHY (wireless)
};

void expect_replay_identical(const std::string& routing, const Stack& stack, const char* sync) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  const auto run = run_swarmnet("run " + kConfigs + stack.base + kSmall +
                                " --set \"network.routing={plugin: " + routing + "}\"" +
                                " --set sync=" + sync + " --seed 5 --out " + run_dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto replay_dir = dir.path() / "replay";
  const auto replay = run_swarmnet("replay " + run_dir.string() + " --out " + replay_dir.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_NE(replay.output.find("byte-identical"), std::string::npos) << replay.output;

  const std::string original = read_file(run_dir / "packets.csv");
  EXPECT_GT(std::count(original.begin(), original.end(), '\n'), 50) << "too little traffic";
  EXPECT_TRUE(original == read_file(replay_dir / "packets.csv"))
      << routing << " over " << stack.name << ", " << sync << ": packet traces differ";
  const auto a = nlohmann::json::parse(read_file(run_dir / "summary.json"));
  const auto b = nlohmann::json::parse(read_file(replay_dir / "summary.json"));
  EXPECT_EQ(a["packets"], b["packets"]);
  EXPECT_EQ(a["mac"], b["mac"]);
  EXPECT_EQ(a["routing"], b["routing"]);
  EXPECT_GE(b["cpu_s"]["network"].get<double>(), 0.0);
}

// Runs configs/`config`, small, with `extra` into `run_dir`; fails the test if the run failed
// (call it inside ASSERT_NO_FATAL_FAILURE).
void run_small(const std::filesystem::path& run_dir, const std::string& config,
               const std::string& extra = "") {
  const auto run =
      run_swarmnet("run " + kConfigs + config + kSmall + extra + " --out " + run_dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
}

TEST(Replay, PacketTraceIsByteIdenticalForEveryRoutingMacAndSyncMode) {
  for (const Stack stack :
       {Stack{"ideal_mac", "aodv.yaml"}, Stack{"dcf80211+sinr", "wireless.yaml"}}) {
    for (const char* routing : {"direct", "flooding", "aodv"}) {
      for (const char* sync : {"strict", "pipelined"}) {
        SCOPED_TRACE(std::string(routing) + " over " + stack.name + ", " + sync);
        expect_replay_identical(routing, stack, sync);
      }
    }
  }
}

// A run that wrote its frame trace (output.frame_trace) is replayed with it: the replay's
// frames.csv is the run's, byte for byte, and named among the replay's outputs.
TEST(Replay, FrameTraceIsByteIdenticalToTheRunsOver80211) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  const auto run = run_swarmnet(
      "run " + kConfigs + "wireless.yaml" + kSmall + " --set \"network.routing={plugin: aodv}\"" +
      " --set output.frame_trace=true --seed 5 --out " + run_dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto replay_dir = dir.path() / "replay";
  const auto replay = run_swarmnet("replay " + run_dir.string() + " --out " + replay_dir.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  const std::string original = read_file(run_dir / "frames.csv");
  EXPECT_GT(std::count(original.begin(), original.end(), '\n'), 100) << "too few frames";
  EXPECT_TRUE(original == read_file(replay_dir / "frames.csv")) << "frame traces differ";
  const auto summary = nlohmann::json::parse(read_file(replay_dir / "summary.json"));
  EXPECT_EQ(summary["outputs"]["frame_trace"], "frames.csv");
}

TEST(Replay, PositionsRecordHoldsExactPositionsEveryStep) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  ASSERT_NO_FATAL_FAILURE(run_small(run_dir, "quickstart.yaml"));
  const std::string bytes = read_file(run_dir / "positions.bin");
  ASSERT_GE(bytes.size(), 32U);
  EXPECT_EQ(bytes.substr(0, 8), std::string("SNPOS\0\0\0", 8));
  std::uint32_t version = 0;
  std::uint32_t robots = 0;
  std::uint64_t steps = 0;
  std::int64_t step_ns = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  std::memcpy(&robots, bytes.data() + 12, 4);
  std::memcpy(&steps, bytes.data() + 16, 8);
  std::memcpy(&step_ns, bytes.data() + 24, 8);
  EXPECT_EQ(version, 1U);
  EXPECT_EQ(robots, 30U);
  EXPECT_EQ(steps, 100U);
  EXPECT_EQ(step_ns, 100000000);
  ASSERT_EQ(bytes.size(), 32 + 16 * std::uint64_t{robots} * steps);
  // Robot 0's first x, to the ns-2 trace's six decimals.
  double x0 = 0.0;
  std::memcpy(&x0, bytes.data() + 32, 8);
  char expected[64];
  std::snprintf(expected, sizeof expected, "$node_(0) set X_ %.6f\n", x0);
  EXPECT_TRUE(read_file(run_dir / "mobility.ns2").starts_with(expected));
  const auto summary = nlohmann::json::parse(read_file(run_dir / "summary.json"));
  EXPECT_EQ(summary["outputs"]["positions"], "positions.bin");
}

TEST(Replay, RefusesARunWithoutItsRecordsClearly) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  ASSERT_NO_FATAL_FAILURE(
      run_small(run_dir, "quickstart.yaml", " --set output.mobility_trace=false"));
  const auto replay = run_swarmnet("replay " + run_dir.string());
  EXPECT_EQ(replay.exit_code, 2);
  EXPECT_NE(replay.output.find("positions.bin"), std::string::npos) << replay.output;
}

// route_queries.csv beside traffic.csv is what the run's controllers asked route_to(): a replay
// asks the same at the same windows (its sensing.csv shows the answers), and refuses a file no
// run writes, naming the file and the line.
TEST(Replay, AsksTheRecordedRouteQueriesAndRefusesAMalformedFileByLine) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  ASSERT_NO_FATAL_FAILURE(run_small(run_dir, "aodv.yaml", " --set output.sensing_trace=true"));
  EXPECT_FALSE(std::filesystem::exists(run_dir / "route_queries.csv")) << "no controller asked";
  const auto queries = run_dir / "route_queries.csv";
  std::ofstream(queries) << "step,robot,destination\n3,0,2\n3,0,7\n3,4,1\n99,29,0\n";
  const auto replay_dir = dir.path() / "replay";
  const auto replay =
      run_swarmnet("replay " + run_dir.string() + " --quiet --out " + replay_dir.string());
  // The run's sensing.csv holds no answers, the replay's does: the check says so.
  EXPECT_EQ(replay.exit_code, 1) << replay.output;
  EXPECT_NE(replay.output.find("the replayed sensing trace differs"), std::string::npos)
      << replay.output;
  EXPECT_TRUE(read_file(run_dir / "packets.csv") == read_file(replay_dir / "packets.csv"))
      << "asking changes nothing the network simulates";
  const std::string sensing = read_file(replay_dir / "sensing.csv");
  for (const char* row : {"\n3,400000000,0,route,2,400000000,,,", "\n3,400000000,0,route,7,",
                          "\n3,400000000,4,route,1,", "\n99,10000000000,29,route,0,"}) {
    EXPECT_NE(sensing.find(row), std::string::npos) << row << " in\n" << sensing;
  }
  EXPECT_EQ(std::count(sensing.begin(), sensing.end(), '\n'), 5) << sensing;

  struct Malformed {
    const char* text;
    const char* where;
    const char* message;
  };
  const Malformed malformed[] = {
      {"step,robot,dest\n", ":1:", "not a SwarmNet route queries file"},
      {"step,robot,destination\n1,0,2\n1,0\n", ":3:", "expected 3 fields"},
      {"step,robot,destination\n1,x,2\n", ":2:", "'x' is not a non-negative integer"},
      {"step,robot,destination\n1,0,30\n", ":2:", "is not a robot asking about another"},
      {"step,robot,destination\n1,4,4\n", ":2:", "is not a robot asking about another"},
      {"step,robot,destination\n2,0,1\n1,0,1\n", ":3:", "steps are not in ascending order"},
      {"step,robot,destination\n2,3,1\n2,0,1\n", ":3:", "not ascending by robot"},
      {"step,robot,destination\n2,3,1\n2,3,1\n", ":3:", "not ascending by robot"},
      {"step,robot,destination\n100,0,1\n", ": route queries", "after the last step (100)"},
  };
  for (const Malformed& bad : malformed) {
    SCOPED_TRACE(bad.text);
    std::ofstream(queries, std::ios::trunc) << bad.text;
    const auto refused = run_swarmnet("replay " + run_dir.string() + " --quiet --out " +
                                      (dir.path() / "refused").string());
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_NE(refused.output.find("route_queries.csv" + std::string(bad.where)), std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find(bad.message), std::string::npos) << refused.output;
  }
}

// Only a world plugin ends a run early: without one, a positions.bin shorter than the scenario
// is refused (a run of another duration), not replayed as if it were whole.
TEST(Replay, RefusesAShorterTraceWhenNoWorldCouldHaveEndedTheRun) {
  TempDir dir;
  const auto run_dir = dir.path() / "run";
  ASSERT_NO_FATAL_FAILURE(run_small(run_dir, "quickstart.yaml"));
  const auto scenario = run_dir / "scenario.resolved.yaml";
  std::string text = read_file(scenario);
  const std::size_t at = text.find("duration_s: 10");
  ASSERT_NE(at, std::string::npos) << text.substr(0, 300);
  text.replace(at, std::strlen("duration_s: 10"), "duration_s: 20");
  std::ofstream(scenario) << text;
  const auto replay = run_swarmnet("replay " + run_dir.string());
  EXPECT_NE(replay.exit_code, 0) << replay.output;
  EXPECT_NE(replay.output.find("does not match"), std::string::npos) << replay.output;
}

}  // namespace
}  // namespace swarmnet::testing
