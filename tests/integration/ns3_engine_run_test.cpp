// The ns-3 engine as a user runs it (`network.engine: ns3`, configs/ns3.yaml): small runs deliver
// with every routing ns-3 maps, the same seed gives the same bytes on every transport, replay
// works, and every scenario the engine cannot run as asked is refused before the run starts,
// with the place in the file and the reason.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

const std::string kScenario = std::string(SWARMNET_SOURCE_DIR) + "/configs/ns3.yaml";
// Ten robots in a 200 m square for a few seconds: multi-hop sometimes, quick always.
const std::string kSmall =
    " --set robots.count=10 --set duration_s=4 --set arena.width_m=200"
    " --set arena.height_m=200 --set arena.obstacles=[]";

nlohmann::json run_summary(const std::filesystem::path& dir, const std::string& extra) {
  const auto result =
      run_swarmnet("run " + kScenario + kSmall + extra + " --quiet --out " + dir.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  if (result.exit_code != 0) return {};
  return nlohmann::json::parse(read_file(dir / "summary.json"));
}

std::string summary_without_timing(const std::filesystem::path& dir) {
  auto summary = nlohmann::ordered_json::parse(read_file(dir / "summary.json"));
  for (const char* key : {"wall_s", "cpu_s", "realtime_factor", "transport_share", "transport"}) {
    summary.erase(key);
  }
  return summary.dump(2);
}

TEST(Ns3Engine, AodvDeliversAndTheSummarySaysWhichEngineRan) {
  TempDir dir;
  const auto summary = run_summary(dir.path() / "run", "");
  ASSERT_FALSE(summary.empty());
  EXPECT_EQ(summary["engine"], "ns3");
  EXPECT_GT(summary["packets"]["sent"].get<int>(), 0);
  EXPECT_GT(summary["packets"]["delivered"].get<int>(), 0);
  EXPECT_GT(summary["mac"]["tx_frames"].get<int>(), 0);
  EXPECT_GT(summary["routing"]["control_packets"].get<int>(), 0);  // AODV's own messages
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "packets.csv"));
}

TEST(Ns3Engine, DirectAndFloodingDeliver) {
  for (const char* routing : {"direct", "flooding"}) {
    TempDir dir;
    const auto summary = run_summary(
        dir.path() / "run", std::string(" --set 'network.routing={plugin: ") + routing + "}'");
    ASSERT_FALSE(summary.empty()) << routing;
    EXPECT_GT(summary["packets"]["delivered"].get<int>(), 0) << routing;
  }
}

TEST(Ns3Engine, OlsrAndDsdvRouteUnderDirect) {
  for (const char* ip : {"olsr", "dsdv"}) {
    TempDir dir;
    const auto summary =
        run_summary(dir.path() / "run", std::string(" --set 'network.routing={plugin: direct}'") +
                                            " --set network.ns3.ip_routing=" + ip);
    ASSERT_FALSE(summary.empty()) << ip;
    EXPECT_GT(summary["packets"]["delivered"].get<int>(), 0) << ip;
  }
}

TEST(Ns3Engine, StaticArpSendsNoArpFrameAndDynamicArpDoes) {
  TempDir dir;
  const auto dynamic = run_summary(dir.path() / "dynamic", "");
  const auto aligned = run_summary(dir.path() / "static", " --set network.arp=static");
  ASSERT_FALSE(dynamic.empty());
  ASSERT_FALSE(aligned.empty());
  EXPECT_GT(dynamic["arp"]["requests_sent"].get<int>(), 0);
  EXPECT_EQ(aligned["arp"]["requests_sent"].get<int>(), 0);
  EXPECT_EQ(aligned["arp"]["replies_sent"].get<int>(), 0);
  EXPECT_GT(aligned["packets"]["delivered"].get<int>(), 0);
}

TEST(Ns3Engine, OtherErrorModelsStandardsManagersAndTheAlignedSetupRun) {
  for (const char* extra :
       {" --set network.ns3.error_rate_model=table", " --set network.ns3.error_rate_model=yans",
        " --set network.ns3.standard=80211n --set network.ns3.data_mode=HtMcs3"
        " --set network.ns3.control_mode=OfdmRate6Mbps",
        " --set network.ns3.rate_manager=minstrel"}) {
    TempDir dir;
    const auto summary = run_summary(dir.path() / "run", extra);
    ASSERT_FALSE(summary.empty()) << extra;
    EXPECT_GT(summary["packets"]["delivered"].get<int>(), 0) << extra;
  }
}

TEST(Ns3Engine, SameSeedGivesIdenticalBytesOnEveryTransportAndSyncMode) {
  TempDir dir;
  std::vector<std::string> variants;
  for (const char* transport : {"shm", "inproc", "uds", "tcp"}) {
    variants.push_back(std::string(" --transport ") + transport);
  }
  variants.push_back(" --set sync=pipelined");
  variants.push_back(" --set sync=pipelined --transport inproc");
  for (std::size_t i = 0; i < variants.size(); ++i) {
    ASSERT_FALSE(run_summary(dir.path() / "run", variants[i]).empty()) << variants[i];
    std::filesystem::rename(dir.path() / "run", dir.path() / std::to_string(i));
  }
  // Strict and pipelined read deliveries at different steps: each compares with its own kind.
  for (std::size_t i = 1; i < variants.size(); ++i) {
    const auto first = dir.path() / (i < 4 ? "0" : "4");
    const auto other = dir.path() / std::to_string(i);
    if (first == other) continue;
    for (const char* file : {"mobility.ns2", "traffic.csv", "scenario.resolved.yaml"}) {
      EXPECT_TRUE(read_file(first / file) == read_file(other / file))
          << file << " differs for '" << variants[i] << "'";
    }
    EXPECT_EQ(summary_without_timing(first), summary_without_timing(other)) << variants[i];
  }
}

TEST(Ns3Engine, ReplayRerunsTheNetworkHalfOnTheRecordedTraces) {
  TempDir dir;
  const auto run = dir.path() / "run";
  const auto summary = run_summary(run, "");
  ASSERT_FALSE(summary.empty());
  const auto replay =
      run_swarmnet("replay " + run.string() + " --quiet --out " + (dir.path() / "replay").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  const auto replayed = nlohmann::json::parse(read_file(dir.path() / "replay" / "summary.json"));
  EXPECT_EQ(replayed["engine"], "ns3");
  // The robots move the same and send the same messages; ns-3 decides the same.
  EXPECT_EQ(replayed["packets"], summary["packets"]);
  EXPECT_EQ(replayed["mac"], summary["mac"]);
}

struct Refusal {
  std::string set;       // the --set overrides that make the scenario unmappable (shell words)
  std::string location;  // where the refusal points
  std::string message;   // a fragment of what it says
};

// Send options come from a controller during the run, so the engine can refuse them only when
// the first arrives: the run fails naming the robot, the message and what it asked for.
TEST(Ns3Engine, AMessageWithSendOptionsFailsTheRunByName) {
  TempDir plugins;
  std::filesystem::copy_file(
      std::filesystem::path(SWARMNET_TEST_FIXTURE_DIR) / "swarmnet_report_probe.so",
      plugins.path() / "swarmnet_report_probe.so");
  TempDir dir;
  const auto result =
      run_swarmnet("run " + kScenario + kSmall + " --set plugin_paths=[" + plugins.path().string() +
                   "] --set 'robots.controllers.1={plugin: report_probe}'"
                   " --quiet --out " +
                   (dir.path() / "run").string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("robot 0's message 0 asks for a send report (SendOptions); "
                               "network.engine: ns3 gives neither"),
            std::string::npos)
      << result.output;
}

TEST(Ns3Engine, ARouteQueryFailsTheRunByName) {
  TempDir plugins;
  std::filesystem::copy_file(
      std::filesystem::path(SWARMNET_TEST_FIXTURE_DIR) / "swarmnet_route_probe.so",
      plugins.path() / "swarmnet_route_probe.so");
  TempDir dir;
  const auto result =
      run_swarmnet("run " + kScenario + kSmall + " --set plugin_paths=[" + plugins.path().string() +
                   "] --set 'robots.controllers.1={plugin: route_probe}'"
                   " --quiet --out " +
                   (dir.path() / "run").string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("robot 0 asks route_to(1) in step 0; network.engine: ns3 answers "
                               "no route queries"),
            std::string::npos)
      << result.output;
}

TEST(Ns3Engine, WhatNs3CannotRunIsRefusedBeforeTheRunWithWhereAndWhy) {
  const std::vector<Refusal> refusals = {
      {"'network.mac={plugin: ideal_mac}'", "--set network.mac",
       "the MAC plugin 'ideal_mac' has no ns-3 counterpart"},
      {"'network.propagation=[{plugin: disk}]'", "--set network.propagation",
       "the propagation plugin 'disk' has no ns-3 counterpart (network.engine: ns3); expected one "
       "of log_distance, friis, two_ray_ground, range, nakagami"},
      {"'network.propagation=[{plugin: shadowing}]'", "--set network.propagation",
       "the propagation plugin 'shadowing' has no ns-3 counterpart"},
      {"network.phy.model=threshold", "--set network.phy.model",
       "the threshold model has no ns-3 counterpart"},
      {"network.phy.sensing_floor_db=-20", "--set network.phy.sensing_floor_db",
       "has no ns-3 counterpart"},
      {"network.phy.header_failure_cca=ns3", "--set network.phy.header_failure_cca",
       "has no ns-3 counterpart"},
      {"network.channel.cutoff=false", "--set network.channel.cutoff", "has no ns-3 counterpart"},
      {"network.channel.far_signals=events", "--set network.channel.far_signals",
       "has no ns-3 counterpart"},
      {"network.neighbors.enabled=true", "--set network.neighbors.enabled",
       "is not given by the ns-3 engine yet"},
      {"network.routing.params.link_layer_feedback=false",
       "--set network.routing.params.link_layer_feedback",
       "ns-3's AODV takes layer-2 feedback whenever ARP resolved the neighbour"},
      {"network.routing.params.enable_local_repair=true",
       "--set network.routing.params.enable_local_repair",
       "'aodv' parameter enable_local_repair is true, but ns-3.37's AODV has no local repair"},
      {"network.routing.params.increment_seqno_on_break=true",
       "--set network.routing.params.increment_seqno_on_break",
       "expected increment_seqno_on_break: false in network.routing.params"},
      {"network.routing.params.rrep_ip_ttl=false", "--set network.routing.params.rrep_ip_ttl",
       "'aodv' parameter rrep_ip_ttl is false, but ns-3.37's AODV sends a RREP with an IP TTL"},
      {"network.routing.params.queue_released_by_rrep_only=false",
       "--set network.routing.params.queue_released_by_rrep_only",
       "ns-3.37's AODV sends buffered packets only on a RREP or when the discovery timer fires"},
      {"network.routing.params.control_via_route_to_neighbor=false",
       "--set network.routing.params.control_via_route_to_neighbor",
       "sends a unicast message to a neighbour as an IP datagram along the route to it"},
      {"network.routing.params.neighbor_route_forgets_seqno=false",
       "--set network.routing.params.neighbor_route_forgets_seqno",
       "gives a neighbour's route that an AODV message makes one hop sequence number 0"},
      {"network.mac.params.header_bytes=40", "--set network.mac.params.header_bytes",
       "'dcf80211' parameter header_bytes is 40, but ns-3 sends real headers"},
      {"network.mac.params.data_rate_bps=7e6", "--set network.mac.params.data_rate_bps",
       "802.11a has no constant mode of 7000000 bit/s"},
      {"network.ns3.standard=80211n", "--set network.ns3.standard",
       "802.11n has no constant mode of 6000000 bit/s"},
      {"network.ns3.data_mode=HtMcs7", "--set network.ns3.data_mode",
       "'HtMcs7' is no WifiMode of 802.11a"},
      // A standard the schema does not know is refused once, without the checks that name it
      // (which used to read past its end: found by fuzzing).
      {"network.ns3.standard=80", "--set network.ns3.standard", "80211a"},
      {"network.ns3.standard=802", "--set network.ns3.standard", "80211a"},
      {"network.ns3.rate_manager=minstrel --set network.ns3.data_mode=OfdmRate54Mbps",
       "--set network.ns3.data_mode", "applies only to the constant rate manager"},
      {"network.ns3.ip_routing=olsr", "--set network.ns3.ip_routing",
       "only the `direct` plugin sends"},
      {"output.packet_trace=true", "--set output.packet_trace",
       "the ns-3 engine writes no packet trace"},
      {"output.frame_trace=true", "--set output.frame_trace",
       "the ns-3 engine writes no frame trace"},
      {"output.sensing_trace=true", "--set output.sensing_trace",
       "the ns-3 engine writes no sensing trace"},
      {"network.engine=native --set network.ns3.standard=80211g", "--set network.ns3.standard",
       "applies only to the ns-3 engine"},
      {"network.ns3.standard=80211g --set network.mac.params.cw_min=31",
       "--set network.mac.params.cw_min", "802.11g in ns-3 has its own cw_min"},
      {"network.ns3.standard=80211g --set network.phy.bandwidth_hz=40e6",
       "--set network.phy.bandwidth_hz", "802.11g channels are 20 MHz wide"},
  };
  for (const auto& refusal : refusals) {
    const auto result = run_swarmnet("validate " + kScenario + " --set " + refusal.set);
    EXPECT_NE(result.exit_code, 0) << refusal.set;
    EXPECT_NE(result.output.find(refusal.location), std::string::npos) << refusal.set << ":\n"
                                                                       << result.output;
    EXPECT_NE(result.output.find(refusal.message), std::string::npos) << refusal.set << ":\n"
                                                                      << result.output;
  }
  // A plugin's default that is not what ns-3 does is refused too, pointing at the engine.
  const auto paper = run_swarmnet("validate " + std::string(SWARMNET_SOURCE_DIR) +
                                  "/configs/paper/evaluation.yaml --set network.engine=ns3");
  EXPECT_NE(paper.exit_code, 0);
  EXPECT_NE(paper.output.find("--set network.engine: network.engine: 'aodv' parameter "
                              "increment_seqno_on_break is true (its default), but ns-3.37's "
                              "AODV does not increment"),
            std::string::npos)
      << paper.output;
  // In the file itself, the refusal names the file, line and column.
  TempDir dir;
  const auto scenario = dir.path() / "ideal.yaml";
  std::string text = read_file(kScenario);
  text.replace(text.find("plugin: dcf80211"), 16, "plugin: ideal_mac");
  text.replace(text.find("data_rate_bps: 6.0e6"), 20, "bitrate_bps: 6.0e6");
  std::ofstream(scenario) << text;
  const auto result = run_swarmnet("validate " + scenario.string());
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find(scenario.string() + ":52:13: network.mac.plugin: the MAC plugin "
                                                   "'ideal_mac' has no ns-3 counterpart"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace swarmnet::testing
