// Determinism, proven on bytes: the same scenario and seed twice give identical outputs (timing
// fields of summary.json aside); another seed gives different traces; both sync modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kScenario = std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml";
// Small enough for the default suite, busy enough to exercise flooding and collisions.
const std::string kSmall =
    " --set robots.count=30 --set duration_s=20 --set arena.width_m=300"
    " --set arena.height_m=300 --set arena.obstacles=[]";

// summary.json without the fields that measure the machine or name the transport rather than
// describe the simulation.
std::string summary_without_timing(const std::filesystem::path& dir) {
  auto summary = nlohmann::ordered_json::parse(read_file(dir / "summary.json"));
  for (const char* key : {"wall_s", "cpu_s", "realtime_factor", "transport_share", "transport"}) {
    EXPECT_TRUE(summary.contains(key)) << key;
    summary.erase(key);
  }
  return summary.dump(2);
}

void run_into(const std::filesystem::path& dir, const std::string& extra) {
  const auto result =
      run_swarmnet("run " + kScenario + kSmall + extra + " --quiet --out " + dir.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

constexpr const char* kTraces[] = {"packets.csv", "mobility.ns2", "traffic.csv",
                                   "scenario.resolved.yaml"};
// What controllers recorded per robot and sampled, what they were told (output.sensing_trace)
// and the route queries they made: compared when the first run wrote them.
constexpr const char* kControllerOutputs[] = {"robot_metrics.csv", "series.csv", "sensing.csv",
                                              "send_options.csv", "route_queries.csv"};

// What a test checks of the first of identical runs, given its directory.
using RunCheck = std::function<void(const std::filesystem::path&)>;

// Runs each variant into the same run directory (the resolved scenario names it), keeping each
// result, and expects every output identical to the first's; then calls `check_first`, if given,
// with the first run's directory.
void expect_identical_runs(const std::vector<std::string>& variants,
                           const RunCheck& check_first = {}) {
  TempDir dir;
  const auto out = dir.path() / "run";
  for (std::size_t i = 0; i < variants.size(); ++i) {
    run_into(out, variants[i]);
    std::filesystem::rename(out, dir.path() / std::to_string(i));
  }
  const auto first = dir.path() / "0";
  for (std::size_t i = 1; i < variants.size(); ++i) {
    const auto other = dir.path() / std::to_string(i);
    for (const char* file : kTraces) {
      const std::string expected = read_file(first / file);
      EXPECT_FALSE(expected.empty()) << file;
      EXPECT_TRUE(expected == read_file(other / file))
          << file << " differs between '" << variants[0] << "' and '" << variants[i] << "'";
    }
    for (const char* file : kControllerOutputs) {
      if (!std::filesystem::exists(first / file)) continue;
      EXPECT_TRUE(read_file(first / file) == read_file(other / file))
          << file << " differs between '" << variants[0] << "' and '" << variants[i] << "'";
    }
    EXPECT_EQ(summary_without_timing(first), summary_without_timing(other))
        << "between '" << variants[0] << "' and '" << variants[i] << "'";
  }
  if (check_first) check_first(first);
}

// A folder holding only the test fixture plugin `name`: the fixtures' folder also holds
// stand-ins for real plugins.
void copy_fixture(const TempDir& folder, const std::string& name) {
  const std::string file = "swarmnet_" + name + ".so";
  std::filesystem::copy_file(std::filesystem::path(SWARMNET_TEST_FIXTURE_DIR) / file,
                             folder.path() / file);
}

// `base` on every transport gives the same bytes, in each sync mode; `check_first` is called
// with the first run of each sync mode.
void expect_identical_on_every_transport(const std::string& base,
                                         const RunCheck& check_first = {}) {
  for (const char* sync : {"strict", "pipelined"}) {
    SCOPED_TRACE(std::string("sync ") + sync);
    std::vector<std::string> variants;
    for (const char* transport : {"shm", "inproc", "uds", "tcp"}) {
      variants.push_back(base + " --set sync=" + sync + " --transport " + transport);
    }
    expect_identical_runs(variants, check_first);
  }
}

const std::string kSensing = " --set output.sensing_trace=true";

// The run in `run` wrote sensing.csv with rows of `record` (neighbor, report or route), and
// `swarmnet replay` of it, the network half alone, writes the same sensing.csv and packets.csv.
RunCheck expect_sensing_replayed(const std::string& record) {
  return [record](const std::filesystem::path& run) {
    const std::string sensing = read_file(run / "sensing.csv");
    EXPECT_EQ(sensing.substr(0, sensing.find('\n')),
              "step,window_end_ns,robot,record,peer,time_ns,port,message_id,status,reason,"
              "next_hop,hops,attempts,frames,unicasts,first_attempt_acks,rssi_dbm,"
              "rssi_smoothed_dbm,sinr_db");
    EXPECT_NE(sensing.find("," + record + ","), std::string::npos) << sensing.substr(0, 500);
    const auto summary = nlohmann::json::parse(read_file(run / "summary.json"));
    EXPECT_EQ(summary["outputs"]["sensing_trace"], "sensing.csv");
    const auto replayed = run.parent_path() / "replayed";
    const auto replay = run_swarmnet("replay " + run.string() + " --out " + replayed.string());
    ASSERT_EQ(replay.exit_code, 0) << replay.output;
    EXPECT_NE(replay.output.find("sensing.csv is byte-identical to the run's"), std::string::npos)
        << replay.output;
    EXPECT_TRUE(sensing == read_file(replayed / "sensing.csv")) << "the replay's sensing.csv";
    EXPECT_TRUE(read_file(run / "packets.csv") == read_file(replayed / "packets.csv"));
    std::filesystem::remove_all(replayed);
  };
}

TEST(RunDeterminism, SameSeedGivesIdenticalBytesInStrictMode) {
  expect_identical_runs({" --seed 7", " --seed 7"});
}

TEST(RunDeterminism, SameSeedGivesIdenticalBytesInPipelinedMode) {
  expect_identical_runs({" --seed 7 --set sync=pipelined", " --seed 7 --set sync=pipelined"});
}

// Every transport carries the same records, so every transport gives the same bytes.
TEST(RunDeterminism, EveryTransportGivesIdenticalBytes) {
  expect_identical_on_every_transport(" --seed 3");
}

// Radio neighbour tables cross in the step protocol like deliveries: a controller reading them
// (the neighbor_probe fixture, beaconing in place of cbr) sees the same tables on every
// transport, in each sync mode; sensing.csv shows them, and a replay writes them alike.
TEST(RunDeterminism, EveryTransportGivesIdenticalNeighborTables) {
  TempDir plugins;
  copy_fixture(plugins, "neighbor_probe");
  const std::string probe = " --set network.neighbors.enabled=true --set plugin_paths=[" +
                            plugins.path().string() +
                            "] --set 'robots.controllers.1={plugin: neighbor_probe}'";
  expect_identical_on_every_transport(probe + kSensing + " --seed 3",
                                      expect_sensing_replayed("neighbor"));
  TempDir dir;
  run_into(dir.path() / "run", probe + " --seed 3");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "sensing.csv"))
      << "only with output.sensing_trace";
  const auto summary = nlohmann::json::parse(read_file(dir.path() / "run" / "summary.json"));
  EXPECT_FALSE(summary["outputs"].contains("sensing_trace"));
  const auto& seen = summary["controllers"]["neighbors"];
  EXPECT_GT(seen["sum"].get<double>(), 0.0) << seen.dump();
  EXPECT_GT(summary["controllers"]["neighbor_frames"]["mean"].get<double>(), 0.0);

  // Without the key the network half keeps no tables, and the controller is told which to set.
  const std::string without = probe.substr(probe.find(" --set plugin_paths"));
  const auto refused = run_swarmnet("run " + kScenario + kSmall + without + " --quiet --out " +
                                    (dir.path() / "refused").string());
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("set network.neighbors.enabled: true"), std::string::npos)
      << refused.output;
}

// Send options and reports cross in the step protocol too: a controller sending one-hop beacons
// and unicasts that ask for reports (the report_probe fixture) gets the same reports on every
// transport, in each sync mode; its beacons travel one hop; and a replay of the run, which reads
// the options from send_options.csv, gives the run's packets and (output.sensing_trace) the
// run's sensing.csv.
TEST(RunDeterminism, EveryTransportGivesIdenticalSendReports) {
  TempDir plugins;
  copy_fixture(plugins, "report_probe");
  const std::string probe = " --set plugin_paths=[" + plugins.path().string() +
                            "] --set 'network.mac={plugin: dcf80211}'"
                            " --set 'network.routing={plugin: aodv}'"
                            " --set 'robots.controllers.1={plugin: report_probe}'";
  expect_identical_on_every_transport(probe + kSensing + " --seed 3",
                                      expect_sensing_replayed("report"));
  TempDir dir;
  const auto run = dir.path() / "run";
  run_into(run, probe + " --seed 3");
  const auto summary = nlohmann::json::parse(read_file(run / "summary.json"));
  const auto& controllers = summary["controllers"];
  // AODV unicasts are acknowledged by their first hop; the beacons are sent.
  for (const char* outcome : {"report_acknowledged", "report_sent"}) {
    EXPECT_GT(controllers[outcome]["count"].get<double>(), 0.0) << outcome << controllers.dump();
  }
  EXPECT_EQ(controllers["beacon_hops"]["max"].get<double>(), 1.0) << controllers.dump();
  EXPECT_GE(controllers["report_attempts"]["min"].get<double>(), 1.0);
  EXPECT_GE(controllers["report_delay_s"]["min"].get<double>(), 0.0);
  ASSERT_TRUE(std::filesystem::exists(run / "send_options.csv"));

  const auto replay =
      run_swarmnet("replay " + run.string() + " --quiet --out " + (dir.path() / "replay").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_TRUE(read_file(run / "packets.csv") == read_file(dir.path() / "replay" / "packets.csv"));
}

// Route queries cross with the batch and their answers with the result: a controller asking
// route_to() every step (the route_probe fixture) reads the same answers on every transport, in
// each sync mode, and asking changes no byte of what the network simulates. The run records the
// queries (route_queries.csv), so a replay asks them too and writes the run's sensing.csv.
TEST(RunDeterminism, EveryTransportGivesIdenticalRouteAnswers) {
  TempDir plugins;
  copy_fixture(plugins, "route_probe");
  const std::string stack =
      " --seed 3 --set 'network.mac={plugin: dcf80211}'"
      " --set 'network.routing={plugin: aodv}'";
  const std::string probe = stack + " --set plugin_paths=[" + plugins.path().string() +
                            "] --set 'robots.controllers.1={plugin: route_probe}'";
  expect_identical_on_every_transport(probe + kSensing, expect_sensing_replayed("route"));
  TempDir dir;
  run_into(dir.path() / "asked", probe);
  const std::string queries = read_file(dir.path() / "asked" / "route_queries.csv");
  EXPECT_EQ(queries.rfind("step,robot,destination\n0,", 0), 0U) << queries.substr(0, 200);
  const auto summary = nlohmann::json::parse(read_file(dir.path() / "asked" / "summary.json"));
  const auto& controllers = summary["controllers"];
  const double robots = summary["robots"].get<double>();
  // Pending on the first step only (strict sync); then answers one window old, some valid.
  EXPECT_EQ(controllers["route_pending"]["count"].get<double>(), robots) << controllers.dump();
  EXPECT_GT(controllers["route_valid"]["count"].get<double>(), 0.0) << controllers.dump();
  EXPECT_GE(controllers["route_hops"]["min"].get<double>(), 1.0);
  EXPECT_EQ(controllers["route_age_s"]["min"].get<double>(), 0.0);  // the window just ended
  EXPECT_EQ(controllers["route_age_s"]["max"].get<double>(), 0.0);

  // Per robot, the answers add up to the pooled count; the series has a row per answer.
  const std::string per_robot = read_file(dir.path() / "asked" / "robot_metrics.csv");
  double valid = 0.0;
  std::istringstream rows(per_robot);
  std::string row;
  while (std::getline(rows, row)) {
    if (row.find(",route_valid,") != std::string::npos) {
      valid += std::stod(row.substr(row.find(",route_valid,") + 13));
    }
  }
  EXPECT_EQ(valid, controllers["route_valid"]["count"].get<double>()) << per_robot;
  const std::string series = read_file(dir.path() / "asked" / "series.csv");
  EXPECT_EQ(series.rfind("time_ns,robot,series,value\n", 0), 0U) << series.substr(0, 200);
  EXPECT_EQ(static_cast<double>(std::count(series.begin(), series.end(), '\n')) - 1.0,
            controllers["route_age_s"]["count"].get<double>());

  // The same run with a controller that sends alike and never asks: identical packets.
  run_into(dir.path() / "quiet", probe + " --set 'robots.controllers.1.params.ask=false'");
  EXPECT_TRUE(read_file(dir.path() / "asked" / "packets.csv") ==
              read_file(dir.path() / "quiet" / "packets.csv"));
  // Neither asked nor told: no file of either kind.
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "quiet" / "route_queries.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "quiet" / "sensing.csv"));
}

// The range-and-bearing device belongs to the robot half: a controller using it (the rab_probe
// fixture, beside the quickstart's two) gives the same bytes twice with noise and loss on,
// reads in every step the data each robot set in the previous one, and changes nothing the
// network half does (the same packets, motion and traffic as a run without it). Without the key
// the run stops, saying which key to set.
TEST(RunDeterminism, RangeAndBearingRunsAreIdenticalAndLeaveTheNetworkAlone) {
  TempDir plugins;
  copy_fixture(plugins, "rab_probe");
  const std::string controllers =
      " --set plugin_paths=[" + plugins.path().string() +
      "] --set 'robots.controllers=[{plugin: diffusion, params: {speed_mps: 1.0}},"
      " {plugin: cbr, params: {fraction: 0.2, rate_hz: 5, payload_bytes: 512}},"
      " {plugin: rab_probe}]'";
  const std::string probe = controllers +
                            " --set robots.range_and_bearing.enabled=true"
                            " --set robots.range_and_bearing.range_m=60"
                            " --set robots.range_and_bearing.range_noise_sd_m=0.5"
                            " --set robots.range_and_bearing.bearing_noise_sd_rad=0.05"
                            " --set robots.range_and_bearing.loss_probability=0.1 --seed 3";
  expect_identical_runs({probe, probe});

  TempDir dir;
  run_into(dir.path() / "rab", probe);
  const auto summary = nlohmann::json::parse(read_file(dir.path() / "rab" / "summary.json"));
  const auto& controllers_seen = summary["controllers"];
  EXPECT_GT(controllers_seen["rab_readings"]["sum"].get<double>(), 0.0) << controllers_seen.dump();
  for (const char* check : {"rab_stale", "rab_wrong_sender", "rab_unpadded"}) {
    EXPECT_GT(controllers_seen[check]["count"].get<double>(), 0.0) << check;
    EXPECT_EQ(controllers_seen[check]["sum"].get<double>(), 0.0) << check;
  }
  run_into(dir.path() / "plain", " --seed 3");
  for (const char* file : {"packets.csv", "mobility.ns2", "traffic.csv"}) {
    EXPECT_TRUE(read_file(dir.path() / "rab" / file) == read_file(dir.path() / "plain" / file))
        << file;
  }

  const auto refused = run_swarmnet("run " + kScenario + kSmall + controllers + " --quiet --out " +
                                    (dir.path() / "refused").string());
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("set robots.range_and_bearing.enabled: true"), std::string::npos)
      << refused.output;
}

TEST(RunDeterminism, AnotherSeedGivesDifferentTraces) {
  TempDir a;
  TempDir b;
  run_into(a.path(), " --seed 7");
  run_into(b.path(), " --seed 8");
  for (const char* file : {"packets.csv", "mobility.ns2", "traffic.csv"}) {
    EXPECT_NE(read_file(a.path() / file), read_file(b.path() / file)) << file;
  }
}

// network.seed re-draws the network half only: given as the master seed it changes nothing; another
// value keeps the robots' motion and the messages they send, and changes what the channel does.
TEST(RunDeterminism, NetworkSeedChangesTheChannelNotTheTraffic) {
  TempDir master;
  TempDir same;
  TempDir other;
  run_into(master.path(), " --seed 7");
  run_into(same.path(), " --seed 7 --set network.seed=7");
  run_into(other.path(), " --seed 7 --set network.seed=8");
  for (const char* file : {"packets.csv", "mobility.ns2", "traffic.csv"}) {
    EXPECT_TRUE(read_file(master.path() / file) == read_file(same.path() / file)) << file;
  }
  EXPECT_EQ(summary_without_timing(master.path()), summary_without_timing(same.path()));
  for (const char* file : {"mobility.ns2", "traffic.csv"}) {
    const std::string expected = read_file(master.path() / file);
    EXPECT_FALSE(expected.empty()) << file;
    EXPECT_TRUE(expected == read_file(other.path() / file)) << file;
  }
  EXPECT_NE(read_file(master.path() / "packets.csv"), read_file(other.path() / "packets.csv"));
}

// output.frame_trace writes frames.csv: one line per frame summary.json counts, the same bytes
// on every run of the same seed, named among the outputs; without it there is no such file.
TEST(RunOutputs, TheFrameTraceIsWrittenOnlyWhenAskedAndIsDeterministic) {
  TempDir a;
  TempDir b;
  TempDir none;
  run_into(a.path(), " --seed 7 --set output.frame_trace=true");
  run_into(b.path(), " --seed 7 --set output.frame_trace=true");
  run_into(none.path(), " --seed 7");
  const std::string frames = read_file(a.path() / "frames.csv");
  EXPECT_TRUE(frames == read_file(b.path() / "frames.csv"));
  EXPECT_EQ(frames.substr(0, frames.find('\n')),
            "time_ns,node,kind,retry,receiver,bytes,sequence,message_id");
  const auto s = nlohmann::json::parse(read_file(a.path() / "summary.json"));
  EXPECT_EQ(s["outputs"]["frame_trace"], "frames.csv");
  EXPECT_GT(s["mac"]["tx_frames"].get<std::size_t>(), 100U);
  EXPECT_EQ(static_cast<std::size_t>(std::count(frames.begin(), frames.end(), '\n')),
            s["mac"]["tx_frames"].get<std::size_t>() + 1);
  EXPECT_FALSE(std::filesystem::exists(none.path() / "frames.csv"));
  const auto without = nlohmann::json::parse(read_file(none.path() / "summary.json"));
  EXPECT_FALSE(without["outputs"].contains("frame_trace"));
  // The trace leaves the rest of the run as it was.
  EXPECT_TRUE(read_file(a.path() / "packets.csv") == read_file(none.path() / "packets.csv"));
  // frames.csv is the run's own: --overwrite without the trace removes it, so no earlier trace
  // is left beside the new run's other files.
  run_into(a.path(), " --seed 8 --overwrite");
  EXPECT_FALSE(std::filesystem::exists(a.path() / "frames.csv"));
}

TEST(RunOutputs, SummaryCarriesTheContractFields) {
  TempDir dir;
  run_into(dir.path(), "");
  const auto s = nlohmann::json::parse(read_file(dir.path() / "summary.json"));
  for (const char* key :
       {"scenario", "seed", "robots", "sim_time_s", "steps", "wall_s", "cpu_s", "realtime_factor",
        "packets", "pdr", "delay_s", "hops_mean", "mac", "routing", "controllers"}) {
    EXPECT_TRUE(s.contains(key)) << "summary.json lacks " << key;
  }
  for (const char* key : {"robot", "network", "transport"}) EXPECT_TRUE(s["cpu_s"].contains(key));
  for (const char* key : {"sent", "delivered", "dropped"}) EXPECT_TRUE(s["packets"].contains(key));
  for (const char* key : {"mean", "p50", "p95"}) EXPECT_TRUE(s["delay_s"].contains(key));
  for (const char* key : {"tx_frames", "collisions", "retries"})
    EXPECT_TRUE(s["mac"].contains(key));
  EXPECT_EQ(s["robots"], 30);
  EXPECT_EQ(s["steps"], 200);
  // 6 senders (20% of 30) at 5 messages/s from t = 1 s: about 6 * 5 * 19 messages.
  EXPECT_GT(s["packets"]["sent"].get<int>(), 400);
  EXPECT_LT(s["packets"]["sent"].get<int>(), 700);
  EXPECT_GT(s["packets"]["delivered"].get<int>(), 0);
  // No file of the run is left under a temporary name.
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace swarmnet::testing
