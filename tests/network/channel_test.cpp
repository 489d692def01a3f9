#include "network/channel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "network/network_simulator.hpp"
#include "network/propagation_chain.hpp"
#include "network_test_support.hpp"

namespace swarmnet {
namespace {

using test::choose;
using test::make_settings;
using test::set_param;

constexpr double kInf = std::numeric_limits<double>::infinity();

double scenario_cutoff(const NetworkSettings& settings, PluginLoader& loader) {
  const PropagationChain chain(settings, loader);
  return cutoff_distance_m(chain, settings.network.phy.tx_power_dbm,
                           settings.network.phy.rx_sensitivity_dbm);
}

TEST(NetworkChannel, CutoffDistanceOfDiskIsItsRange) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 2);
  for (const double range : {0.5, 1.0, 37.25, 120.0, 999.0}) {
    set_param(settings.network.propagation[0], "range_m", range);
    const double cutoff = scenario_cutoff(settings, loader);
    EXPECT_GT(cutoff, range);
    EXPECT_LE(cutoff, range + kCutoffResolutionM);
  }
}

TEST(NetworkChannel, ChainedBoundsTakeTheShortestRange) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 2);
  PluginChoice shorter = choose(loader, "disk", PluginKind::propagation);
  set_param(shorter, "range_m", 80.0);
  settings.network.propagation.push_back(shorter);
  const double cutoff = scenario_cutoff(settings, loader);
  EXPECT_GT(cutoff, 80.0);
  EXPECT_LE(cutoff, 80.0 + kCutoffResolutionM);
}

TEST(NetworkChannel, UnlimitedOrInfiniteRangeHasNoCutoff) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 2);
  set_param(settings.network.propagation[0], "unlimited", true);
  EXPECT_EQ(scenario_cutoff(settings, loader), kInf);

  settings = make_settings(loader, 2);
  set_param(settings.network.propagation[0], "range_m", kInf);
  EXPECT_EQ(scenario_cutoff(settings, loader), kInf);
  const NetworkSimulator simulator(settings, loader, nullptr);
  EXPECT_FALSE(simulator.channel().uses_grid());  // nothing to cut: every node is visited
}

TEST(NetworkChannel, NothingIsAudibleWhenTheSensitivityExceedsTheTxPower) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 2);
  settings.network.phy.rx_sensitivity_dbm = settings.network.phy.tx_power_dbm + 1.0;
  EXPECT_EQ(scenario_cutoff(settings, loader), 0.0);
}

TEST(NetworkChannel, SimulatorUsesTheGridOnlyWhenTheCutoffIsOn) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 3);
  {
    const NetworkSimulator simulator(settings, loader, nullptr);
    EXPECT_TRUE(simulator.channel().uses_grid());
    EXPECT_LE(std::abs(simulator.channel().cutoff_m() - 120.0), kCutoffResolutionM);
  }
  settings.network.channel.cutoff = false;
  const NetworkSimulator simulator(settings, loader, nullptr);
  EXPECT_FALSE(simulator.channel().uses_grid());
}

TEST(NetworkChannel, OnlyNodesWithinRangeHearAFrame) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 4, "ideal_mac", "direct");
  // Distances from node 0: 100 m, exactly 120 m (the disk is closed), 120.5 m.
  const std::vector<Vec2> positions = {{10, 50}, {110, 50}, {130, 50}, {130.5, 50}};
  const auto out =
      test::run(settings, loader,
                test::fixed_batches(settings, positions, 2, {test::message(0, 0, kBroadcast)}));
  ASSERT_EQ(out.deliveries.size(), 2U);
  EXPECT_EQ(out.deliveries[0].receiver, 1U);
  EXPECT_EQ(out.deliveries[1].receiver, 2U);
  EXPECT_EQ(out.report["packets"]["broadcast_deliveries"], 2);
}

TEST(NetworkChannel, ReceiversMillionsOfKilometresAwayHearAFrameInArrivalOrder) {
  // Delays beyond 2^32 ns do not fit the channel's packed sort keys: they must still sort.
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 5, "ideal_mac", "direct");
  set_param(settings.network.propagation[0], "unlimited", true);
  const double metres_per_ns = kSpeedOfLightMps * 1e-9;
  const std::vector<Vec2> positions = {{0, 0},
                                       {4.5e9 * metres_per_ns, 0},    // 4.5 s: past 2^32 ns
                                       {4.0e9 * metres_per_ns, 0},    // 4.0 s
                                       {10, 0},                       // 33 ns
                                       {-4.0e9 * metres_per_ns, 0}};  // 4.0 s, as node 2
  const auto out =
      test::run(settings, loader,
                test::fixed_batches(settings, positions, 50, {test::message(0, 0, kBroadcast)}));
  ASSERT_EQ(out.deliveries.size(), 4U);
  // By arrival; the two at the same distance by id.
  EXPECT_EQ(out.deliveries[0].receiver, 3U);
  EXPECT_EQ(out.deliveries[1].receiver, 2U);
  EXPECT_EQ(out.deliveries[2].receiver, 4U);
  EXPECT_EQ(out.deliveries[3].receiver, 1U);
  EXPECT_EQ(out.deliveries[1].delivered_at, out.deliveries[2].delivered_at);
  EXPECT_GT(out.deliveries[3].delivered_at - out.deliveries[1].delivered_at, from_seconds(0.49));
}

bool same_deliveries(const std::vector<Delivery>& a, const std::vector<Delivery>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].message_id != b[i].message_id || a[i].source != b[i].source ||
        a[i].destination != b[i].destination || a[i].receiver != b[i].receiver ||
        a[i].sent_at != b[i].sent_at || a[i].delivered_at != b[i].delivered_at ||
        a[i].hops != b[i].hops || a[i].payload != b[i].payload) {
      return false;
    }
  }
  return true;
}

TEST(NetworkChannel, CutoffOnAndOffGiveIdenticalResults) {
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 80);
  settings.arena.width_m = 600.0;
  settings.arena.height_m = 600.0;
  set_param(settings.network.propagation[0], "range_m", 100.0);
  set_param(settings.network.propagation[0], "probability", 0.8);
  const auto batches = test::random_batches(settings, 7, 30, 6, 0.25, 2.0);

  settings.network.channel.cutoff = true;
  const auto with_cutoff = test::run(settings, loader, batches);
  settings.network.channel.cutoff = false;
  const auto without_cutoff = test::run(settings, loader, batches);

  // The settings exercises multi-hop flooding and lossy links, not a trivial case.
  ASSERT_GT(with_cutoff.deliveries.size(), 100U);
  EXPECT_GT(with_cutoff.report["hops_mean"].get<double>(), 1.5);
  EXPECT_GT(with_cutoff.report["packets"]["undelivered"].get<int>(), 0);

  EXPECT_TRUE(same_deliveries(with_cutoff.deliveries, without_cutoff.deliveries));
  EXPECT_TRUE(with_cutoff.trace == without_cutoff.trace) << "packet traces differ";
  EXPECT_EQ(with_cutoff.report.dump(), without_cutoff.report.dump());
  EXPECT_EQ(with_cutoff.events_per_step, without_cutoff.events_per_step);
}

TEST(NetworkDisk, LossyLinkDeliversAtItsProbability) {
  // 2000 one-hop messages over a link that carries each frame with p = 0.5. The delivered count
  // is Binomial(2000, 0.5): standard deviation sqrt(2000 * 0.25) = 22.4 messages, i.e. 0.0112 in
  // rate. The seed is fixed, so the test is deterministic; the tolerance of 4 standard deviations
  // (0.0447) would be exceeded by a correct model with probability 6e-5 for a random seed.
  PluginLoader loader;
  NetworkSettings settings = make_settings(loader, 2, "ideal_mac", "direct");
  set_param(settings.network.propagation[0], "probability", 0.5);
  settings.network.arp.reset();  // the link's loss alone: no ARP frame to lose as well
  constexpr std::uint64_t kSteps = 100;
  constexpr std::uint64_t kPerStep = 20;
  auto batches = test::fixed_batches(settings, {{10, 50}, {60, 50}}, kSteps + 1, {});
  std::uint64_t id = 0;
  for (std::uint64_t s = 0; s < kSteps; ++s) {
    for (std::uint64_t k = 0; k < kPerStep; ++k) {
      batches[s].messages.push_back(test::message(id++, 0, 1, 64));
    }
  }
  const auto out = test::run(settings, loader, batches);
  const double n = static_cast<double>(kSteps * kPerStep);
  EXPECT_EQ(out.report["packets"]["sent"].get<double>(), n);
  EXPECT_EQ(out.report["packets"]["dropped"]["queue_full"], 0);
  const double rate = static_cast<double>(out.deliveries.size()) / n;
  const double tolerance = 4.0 * std::sqrt(0.5 * 0.5 / n);
  EXPECT_NEAR(rate, 0.5, tolerance);
  EXPECT_DOUBLE_EQ(out.report["pdr"].get<double>(), rate);
}

}  // namespace
}  // namespace swarmnet
