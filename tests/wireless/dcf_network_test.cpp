// Whole networks over log_distance + the sinr PHY + dcf80211: the sensitivity edge, hidden
// terminals with and without RTS/CTS, Bianchi's saturation throughput, and the channel cutoff.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "network/network_simulator.hpp"
#include "network/radio_thresholds.hpp"
#include "network_test_support.hpp"
#include "outputs/run_summary.hpp"
#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet {
namespace {

using test::choose;
using test::set_param;

// log_distance defaults (ns-3): the received power at 120 m equals the -82 dBm detection
// threshold with this transmit power.
const double kTxPower120mDbm = -82.0 + 46.6777 + 30.0 * std::log10(120.0);

NetworkSettings wireless_scenario(PluginLoader& loader, std::uint32_t robots,
                                  const std::string& routing = "direct") {
  NetworkSettings settings = test::make_settings(loader, robots, "dcf80211", routing);
  settings.network.propagation = {choose(loader, "log_distance", PluginKind::propagation)};
  settings.network.phy.model = PhyModel::sinr;
  settings.network.phy.tx_power_dbm = kTxPower120mDbm;
  // Static ARP: these tests pin DCF's timing, retries and contention frame by frame; ARP over
  // DCF has tests of its own (arp_network_test.cpp).
  settings.network.arp.reset();
  return settings;
}

struct Outcome {
  std::vector<Delivery> deliveries;
  nlohmann::ordered_json report;
};

Outcome simulate(const NetworkSettings& settings, PluginLoader& loader,
                 const std::vector<StepBatch>& batches) {
  Outcome outcome;
  NetworkSimulator simulator(settings, loader, nullptr);
  StepResult result;
  for (const StepBatch& batch : batches) {
    simulator.run_step(batch, result);
    for (auto& d : result.deliveries) outcome.deliveries.push_back(std::move(d));
  }
  outcome.report = network_report_json(simulator.report());
  return outcome;
}

std::size_t delivered_to(const Outcome& outcome, RobotId receiver) {
  std::size_t n = 0;
  for (const Delivery& d : outcome.deliveries) n += d.receiver == receiver ? 1 : 0;
  return n;
}

TEST(WirelessNetwork, NodesEitherSideOfTheSensitivityEdge) {
  PluginLoader loader;
  const NetworkSettings settings = wireless_scenario(loader, 3);
  // Node 1 at 119 m (-81.9 dBm) hears node 0, node 2 at 121 m (-82.1 dBm) does not.
  const std::vector<Vec2> positions = {{10, 50}, {129, 50}, {10, 171}};
  std::vector<AppMessage> messages;
  for (std::uint64_t i = 0; i < 20; ++i) messages.push_back(test::message(i, 0, kBroadcast, 200));
  const Outcome outcome =
      simulate(settings, loader, test::fixed_batches(settings, positions, 3, std::move(messages)));
  EXPECT_EQ(delivered_to(outcome, 1), 20U);
  EXPECT_EQ(delivered_to(outcome, 2), 0U);
  EXPECT_EQ(outcome.report["mac"]["tx_frames"], 20);
}

TEST(WirelessNetwork, UnicastIsAcknowledgedAndRetriedUntilTheLimit) {
  PluginLoader loader;
  NetworkSettings settings = wireless_scenario(loader, 2);
  // Out of range: every attempt times out; 7 attempts, then a retry_limit drop.
  const std::vector<Vec2> positions = {{10, 50}, {200, 50}};
  Outcome outcome = simulate(settings, loader,
                             test::fixed_batches(settings, positions, 3, {test::message(1, 0, 1)}));
  EXPECT_EQ(outcome.report["mac"]["tx_frames"], 7);
  EXPECT_EQ(outcome.report["mac"]["ack_timeouts"], 7);
  EXPECT_EQ(outcome.report["mac"]["retries"], 6);
  EXPECT_EQ(outcome.report["packets"]["dropped"]["retry_limit"], 1);
  // In range: one data frame, one ACK.
  const std::vector<Vec2> near = {{10, 50}, {60, 50}};
  outcome =
      simulate(settings, loader, test::fixed_batches(settings, near, 3, {test::message(1, 0, 1)}));
  EXPECT_EQ(outcome.report["packets"]["delivered"], 1);
  EXPECT_EQ(outcome.report["mac"]["tx_frames"], 2);
  EXPECT_EQ(outcome.report["mac"]["acks"], 1);
}

// frames.csv of one unicast from node 0 to node 1 at `positions` (output.frame_trace).
std::vector<std::string> frame_lines(const std::vector<Vec2>& positions) {
  PluginLoader loader;
  const NetworkSettings settings = wireless_scenario(loader, 2);
  std::ostringstream frames;
  NetworkSimulator simulator(settings, loader, nullptr, &frames);
  StepResult result;
  for (const StepBatch& batch :
       test::fixed_batches(settings, positions, 3, {test::message(9, 0, 1)})) {
    simulator.run_step(batch, result);
  }
  simulator.finish();
  const std::string text = frames.str();
  EXPECT_EQ(network_report_json(simulator.report())["mac"]["tx_frames"].get<std::size_t>() + 1,
            static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')))
      << "one line per frame the report counts, after the header";
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line.substr(line.find(',') + 1));
  return lines;  // without their times, which the tests above pin
}

TEST(WirelessNetwork, TheFrameTraceShowsEveryAttemptAndEveryAck) {
  // Out of range: seven attempts of one MPDU, the Retry bit on all but the first, no ACK.
  const std::vector<std::string> far = frame_lines({{10, 50}, {200, 50}});
  ASSERT_EQ(far.size(), 8U);
  EXPECT_EQ(far[0], "node,kind,retry,receiver,bytes,sequence,message_id");
  EXPECT_EQ(far[1], "0,data,0,1,164,0,9");
  for (std::size_t i = 2; i < far.size(); ++i) EXPECT_EQ(far[i], "0,data,1,1,164,0,9") << i;
  // In range: the frame and its ACK, addressed back to the sender.
  const std::vector<std::string> near = frame_lines({{10, 50}, {60, 50}});
  EXPECT_EQ(near, (std::vector<std::string>{"node,kind,retry,receiver,bytes,sequence,message_id",
                                            "0,data,0,1,164,0,9", "1,ack,0,0,14,-1,-1"}));
}

TEST(WirelessNetwork, PacketAtAnIdleStationWaitsDifsFromItsArrival) {
  // ns-3.37 (ChannelAccessManager::NeedBackoffUponAccess): backoff 0 and the medium idle when
  // the packet arrives: no backoff, but the medium must stay idle for DIFS from the arrival.
  PluginLoader loader;
  const NetworkSettings settings = wireless_scenario(loader, 2);
  const std::vector<Vec2> near = {{10, 50}, {60, 50}};
  std::vector<StepBatch> batches = test::fixed_batches(settings, near, 6, {});
  batches[3].messages.push_back(test::message(7, 0, 1));  // long after the post-backoff ended
  const Outcome outcome = simulate(settings, loader, batches);
  ASSERT_EQ(outcome.deliveries.size(), 1U);
  const Delivery& d = outcome.deliveries[0];
  const SimTime difs = from_seconds(34e-6);
  const SimTime airtime = ofdm::frame_duration(100 + 28 + 36, ofdm::kModes[0]);
  const SimTime propagation = from_seconds(50.0 / 299792458.0);
  EXPECT_NEAR(static_cast<double>((d.delivered_at - d.sent_at).count()),
              static_cast<double>((difs + airtime + propagation).count()), 2.0);
}

// A and C (200 m apart: -88.7 dBm, below carrier sense) both send to B in the middle.
Outcome hidden_terminals(bool rts_cts) {
  PluginLoader loader;
  NetworkSettings settings = wireless_scenario(loader, 3);
  set_param(settings.network.mac, "rts_threshold_bytes", std::int64_t{rts_cts ? 0 : 65535});
  const std::vector<Vec2> positions = {{10, 50}, {110, 50}, {210, 50}};
  std::vector<AppMessage> messages;
  for (std::uint64_t i = 0; i < 300; ++i) {
    messages.push_back(test::message(2 * i, 0, 1, 1000));
    messages.push_back(test::message(2 * i + 1, 2, 1, 1000));
  }
  return simulate(settings, loader,
                  test::fixed_batches(settings, positions, 20, std::move(messages)));
}

TEST(WirelessNetwork, HiddenTerminalsCollideWithoutRtsCtsAndMuchLessWithIt) {
  const Outcome plain = hidden_terminals(false);
  const Outcome protected_ = hidden_terminals(true);
  const auto collisions = [](const Outcome& o) { return o.report["mac"]["collisions"].get<int>(); };
  const auto delivered = [](const Outcome& o) {
    return o.report["packets"]["delivered"].get<int>();
  };
  const auto dropped = [](const Outcome& o) {
    return o.report["packets"]["dropped"]["retry_limit"].get<int>();
  };
  // Without RTS/CTS, B loses many data frames and the senders give packets up.
  EXPECT_GT(collisions(plain), 100);
  EXPECT_GT(dropped(plain), 10);
  // With it, only short RTS frames collide; the data is protected by the CTS's NAV.
  EXPECT_LT(collisions(protected_) * 3, collisions(plain));
  EXPECT_GT(delivered(protected_), delivered(plain) * 3 / 2);
  EXPECT_GT(protected_.report["mac"]["cts"].get<int>(), 300);
  EXPECT_LT(dropped(protected_) * 10, dropped(plain));
}

// Bianchi's model (IEEE JSAC 18(3), 2000) with a finite retry limit: stage i has window
// W_i = min(2^i W, 2^m W) slots; tau = sum p^i / sum p^i (W_i + 1) / 2 over the K attempt stages;
// p = 1 - (1 - tau)^(n - 1). Returns successful frames per second.
double bianchi_frames_per_s(int n, double slot_s, double ts_s, double tc_s) {
  const int k_stages = 7;
  const auto window = [](int i) { return std::min(16.0 * std::pow(2.0, i), 1024.0); };
  double tau = 0.1;
  for (int iteration = 0; iteration < 10000; ++iteration) {
    const double p = 1.0 - std::pow(1.0 - tau, n - 1);
    double attempts = 0.0;
    double slots = 0.0;
    for (int i = 0; i < k_stages; ++i) {
      attempts += std::pow(p, i);
      slots += std::pow(p, i) * (window(i) + 1.0) / 2.0;
    }
    tau = 0.5 * tau + 0.5 * attempts / slots;
  }
  const double p_tr = 1.0 - std::pow(1.0 - tau, n);
  const double p_s = n * tau * std::pow(1.0 - tau, n - 1) / p_tr;
  const double mean_slot = (1.0 - p_tr) * slot_s + p_tr * p_s * ts_s + p_tr * (1.0 - p_s) * tc_s;
  return p_tr * p_s / mean_slot;
}

double simulated_frames_per_s(int n, double run_s, std::uint64_t seed) {
  PluginLoader loader;
  NetworkSettings settings = wireless_scenario(loader, static_cast<std::uint32_t>(n + 1));
  settings.seed = seed;
  settings.network.phy.tx_power_dbm = 16.0206;
  set_param(settings.network.mac, "queue_limit", std::int64_t{1000000});
  set_param(settings.network.mac, "queue_max_delay_s", 1.0e6);
  // Station i on a circle of 0.4 m around the sink (node n): every pair is within the 1 m
  // reference distance, so all powers are equal and every collision destroys all frames.
  std::vector<Vec2> positions;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    positions.emplace_back(500.0 + 0.4 * std::cos(a), 500.0 + 0.4 * std::sin(a));
  }
  positions.emplace_back(500.0, 500.0);
  const auto steps = static_cast<std::uint64_t>(std::llround(run_s / settings.step_s));
  // Saturated: more packets than the cell can carry, all queued at the start.
  const int per_station = static_cast<int>(run_s * 800.0 / n) + 50;
  std::vector<AppMessage> messages;
  std::uint64_t id = 0;
  for (int k = 0; k < per_station; ++k) {
    for (int i = 0; i < n; ++i) {
      messages.push_back(
          test::message(id++, static_cast<RobotId>(i), static_cast<RobotId>(n), 1000));
    }
  }
  const Outcome outcome = simulate(
      settings, loader, test::fixed_batches(settings, positions, steps, std::move(messages)));
  // Count deliveries after a warm-up of 0.5 s (all queues filled during the first step).
  const SimTime warm_up = from_seconds(0.5);
  std::size_t frames = 0;
  for (const Delivery& d : outcome.deliveries) frames += d.delivered_at >= warm_up ? 1 : 0;
  return static_cast<double>(frames) / (run_s - 0.5);
}

TEST(WirelessNetwork, SaturationThroughputMatchesBianchi) {
  // 1000-byte payloads: MPDU = 36 + 28 + 1000 bytes.
  const SimTime data = ofdm::frame_duration(1064, ofdm::kModes[0]);
  const SimTime ack = ofdm::frame_duration(14, ofdm::kModes[0]);
  const double slot = 9e-6;
  const double sifs = 16e-6;
  const double difs = sifs + 2 * slot;
  // Success: DATA + SIFS + ACK + DIFS. Collision: no station decodes a preamble (equal powers),
  // so the others wait DIFS after the busy medium, as in Bianchi's T_c = DATA + DIFS.
  const double ts = to_seconds(data) + sifs + to_seconds(ack) + difs;
  const double tc = to_seconds(data) + difs;
  for (const int n : {5, 10, 20, 50}) {
    const double expected = bianchi_frames_per_s(n, slot, ts, tc);
    // Averaged over four seeds: one run of a few thousand frames varies by a few percent.
    double measured = 0.0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      measured += simulated_frames_per_s(n, n >= 50 ? 6.0 : 8.0, seed) / 4.0;
    }
    std::printf("n = %d: simulated %.1f frames/s, Bianchi %.1f\n", n, measured, expected);
    EXPECT_NEAR(measured / expected, 1.0, 0.05)
        << "n = " << n << ": simulated " << measured << " frames/s, Bianchi " << expected;
  }
}

// 80 nodes flooding over 1.5 km with `floor_db` as the interference floor.
NetworkSettings flooding_field(PluginLoader& loader, double floor_db) {
  NetworkSettings settings = wireless_scenario(loader, 80, "flooding");
  settings.arena.width_m = 1500.0;
  settings.arena.height_m = 1500.0;
  settings.network.phy.interference_floor_db = floor_db;
  set_param(settings.network.routing, "ttl", std::int64_t{3});
  return settings;
}

// Runs `batches` with the cutoff on and off, expects the same bytes and a cutoff of about
// `cutoff_m`, and returns the run with the cutoff.
test::RunOutput expect_cutoff_exact(NetworkSettings settings, PluginLoader& loader,
                                    const std::vector<StepBatch>& batches, double cutoff_m) {
  settings.network.channel.cutoff = true;
  test::RunOutput with_cutoff = test::run(settings, loader, batches);
  settings.network.channel.cutoff = false;
  const test::RunOutput without = test::run(settings, loader, batches);
  {
    const NetworkSimulator probe(settings, loader, nullptr);
    EXPECT_NEAR(probe.channel().cutoff_m(), cutoff_m, 2.0);
  }
  EXPECT_EQ(with_cutoff.trace, without.trace);
  EXPECT_EQ(with_cutoff.report.dump(), without.report.dump());
  EXPECT_GT(with_cutoff.report["packets"]["broadcast_deliveries"].get<int>(), 50);
  EXPECT_GT(with_cutoff.report["mac"]["tx_frames"].get<int>(), 100);
  return with_cutoff;
}

TEST(WirelessNetwork, CutoffGivesIdenticalResultsWhereItIsExact) {
  // log_distance (deterministic) + sinr: nodes beyond the cutoff receive less than the
  // interference floor, which the PHY ignores anyway, so visiting them changes nothing.
  PluginLoader loader;
  const NetworkSettings settings = flooding_field(loader, PhyConfig{}.interference_floor_db);
  const auto batches = test::random_batches(settings, 11, 20, 6, 0.3, 2.0);
  const test::RunOutput run = expect_cutoff_exact(settings, loader, batches, 648.0);
  EXPECT_GT(run.report["packets"]["delivered"].get<int>(), 0);
}

TEST(WirelessNetwork, AFloorAtTheDetectionThresholdIgnoresWhatCannotBeDetectedAndStaysExact) {
  // interference_floor_db above 0 puts the floor above the noise; at cca_threshold_dbm minus the
  // noise floor nothing weaker than a detectable frame reaches a PHY, so the cutoff shrinks to
  // the 120 m detection range, and cutting there must still change nothing.
  PluginLoader loader;
  const PhyConfig defaults;
  const double floor_db = defaults.cca_threshold_dbm - noise_floor_dbm(defaults);
  EXPECT_NEAR(floor_db, 11.99, 0.01);
  const NetworkSettings settings = flooding_field(loader, floor_db);
  // The weakest signal any PHY is handed is then the detection threshold: no far signal exists.
  EXPECT_NEAR(audibility_threshold_dbm(settings.network.phy), defaults.cca_threshold_dbm, 1e-9);
  EXPECT_EQ(event_threshold_dbm(settings.network.phy),
            audibility_threshold_dbm(settings.network.phy));
  const auto batches = test::random_batches(settings, 11, 20, 6, 0.3, 2.0);
  const test::RunOutput run = expect_cutoff_exact(settings, loader, batches, 120.0);
  // Against the default floor the same traffic meets less interference: the runs differ.
  const test::RunOutput default_floor =
      test::run(flooding_field(loader, defaults.interference_floor_db), loader, batches);
  EXPECT_NE(run.trace, default_floor.trace);
}

}  // namespace
}  // namespace swarmnet
