// The reference study's task allocation end to end (task_events world, task_allocation
// controller, flooding over a 120 m disk): every event is serviced, every message type is sent,
// the run ends when the task is done, and its outputs are byte-identical on a rerun, over another
// transport and in a replay of the network half.
#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kScenario =
    std::string(SWARMNET_SOURCE_DIR) + "/configs/paper/task-allocation.yaml";
// 10 robots, 2 events, the study's "p100" model; seed 1 sends all five message types.
const std::string kSmall =
    " --seed 1 --set robots.count=10 --set world.0.params.events=2"
    " --set 'network.propagation=[{plugin: disk, params: {range_m: 120, probability: 1.0}}]'"
    " --set 'network.phy={model: threshold}' --set 'network.mac={plugin: ideal_mac}'"
    " --set output.packet_trace=true --quiet";

nlohmann::json run_small(const std::filesystem::path& dir, const std::string& extra = "") {
  const auto result = run_swarmnet("run " + kScenario + kSmall + " --out " + dir.string() + extra);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return nlohmann::json::parse(read_file(dir / "summary.json"));
}

TEST(TaskAllocationRun, EveryEventIsServicedWithEveryMessageTypeAndTheRunEndsThere) {
  TempDir dir;
  const nlohmann::json summary = run_small(dir.path() / "run");
  EXPECT_EQ(summary["ended"]["by"], "task_done");
  EXPECT_EQ(summary["ended"]["world"], "task_events");
  EXPECT_EQ(summary["world"]["events_serviced"]["count"], 2);
  EXPECT_EQ(summary["world"]["events_unserviced"]["sum"], 0.0);
  EXPECT_EQ(summary["world"]["completion_time_s"]["count"], 1);
  const double done_at = summary["world"]["completion_time_s"]["max"];
  EXPECT_DOUBLE_EQ(summary["ended"]["at_s"].get<double>(), done_at);
  EXPECT_DOUBLE_EQ(summary["sim_time_s"].get<double>(), done_at);
  EXPECT_LT(done_at, summary["duration_s"].get<double>());
  const nlohmann::json& controllers = summary["controllers"];
  for (const char* type : {"S", "G", "C", "H", "A"}) {
    const std::string sent = std::string("sent.") + type;
    ASSERT_TRUE(controllers.contains(sent)) << sent;
    EXPECT_GE(controllers[sent]["count"].get<int>(), 1) << sent;
  }
  // The one A of this run is sent by a robot out of everyone's range: no one receives it.
  for (const char* type : {"S", "G", "C", "H"}) {
    const std::string received = std::string("received.") + type;
    ASSERT_TRUE(controllers.contains(received)) << received;
    EXPECT_GE(controllers[received]["count"].get<int>(), 1) << received;
  }
  EXPECT_EQ(summary["world"]["distance_m"]["count"], 10);
  // positions.bin holds exactly the steps that ran.
  const std::uint64_t steps = summary["steps"];
  EXPECT_EQ(read_file(dir.path() / "run" / "positions.bin").size(), 32 + steps * 10 * 16);
  EXPECT_NE(read_file(dir.path() / "run" / "run.log").find("ended by world task_events"),
            std::string::npos);
}

TEST(TaskAllocationRun, RerunsTransportsAndTheReplayGiveIdenticalBytes) {
  TempDir dir;
  run_small(dir.path() / "first");
  run_small(dir.path() / "second");
  run_small(dir.path() / "inproc", " --transport inproc");
  const auto first = dir.path() / "first";
  for (const char* file : {"positions.bin", "packets.csv", "traffic.csv", "mobility.ns2"}) {
    const std::string bytes = read_file(first / file);
    ASSERT_FALSE(bytes.empty()) << file;
    EXPECT_TRUE(read_file(dir.path() / "second" / file) == bytes) << file;
    EXPECT_TRUE(read_file(dir.path() / "inproc" / file) == bytes) << file;
  }
  const auto replay =
      run_swarmnet("replay " + first.string() + " --out " + (dir.path() / "replay").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_TRUE(read_file(dir.path() / "replay" / "packets.csv") == read_file(first / "packets.csv"));
  const nlohmann::json replayed =
      nlohmann::json::parse(read_file(dir.path() / "replay" / "summary.json"));
  const nlohmann::json original = nlohmann::json::parse(read_file(first / "summary.json"));
  EXPECT_EQ(replayed["steps"], original["steps"]);
  EXPECT_EQ(replayed["packets"], original["packets"]);
}

}  // namespace
}  // namespace swarmnet::testing
