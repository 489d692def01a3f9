// The propagation plugins: values against their formulas, bounds, chaining and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "network/propagation_chain.hpp"
#include "network_test_support.hpp"
#include "plugin/plugin_loader.hpp"

namespace swarmnet {
namespace {

using test::choose;
using test::set_param;

PluginInstance<Propagation> make_model(PluginLoader& loader, const PluginChoice& choice,
                                       std::uint64_t seed = 7) {
  PluginArgs args;
  args.params = choice.params;
  args.seed = seed;
  args.shared_seed = seed;
  return loader.create<Propagation>(choice.name, args);
}

PluginInstance<Propagation> make_model(PluginLoader& loader, const std::string& name) {
  return make_model(loader, choose(loader, name, PluginKind::propagation));
}

RadioLink link_at(double distance_m, std::uint64_t frame_uid = 1, NodeId tx = 0, NodeId rx = 1) {
  RadioLink link;
  link.transmitter = tx;
  link.receiver = rx;
  link.rx_position = Vec2(distance_m, 0.0);
  link.distance_m = distance_m;
  link.frame_uid = frame_uid;
  return link;
}

TEST(WirelessPropagation, LogDistanceHasNs3Defaults) {
  PluginLoader loader;
  const auto model = make_model(loader, "log_distance");
  EXPECT_DOUBLE_EQ(model->rx_power_dbm(16.0206, link_at(0.5)), 16.0206 - 46.6777);
  EXPECT_NEAR(model->rx_power_dbm(16.0206, link_at(100.0)), 16.0206 - 46.6777 - 60.0, 1e-9);
  // ns-3's default range with the -82 dBm detection threshold: about 51.5 m.
  const double range = std::pow(10.0, (16.0206 - 46.6777 + 82.0) / 30.0);
  EXPECT_NEAR(range, 51.5, 0.3);
  EXPECT_EQ(model->max_rx_power_dbm(10.0, 80.0), model->rx_power_dbm(10.0, link_at(80.0)));
}

TEST(WirelessPropagation, FriisFollowsTheFreeSpaceLaw) {
  PluginLoader loader;
  const auto model = make_model(loader, "friis");
  const double lambda = kSpeedOfLightMps / 5.15e9;
  const double expected = 20.0 * std::log10(4.0 * std::numbers::pi * 100.0 / lambda);
  EXPECT_NEAR(0.0 - model->rx_power_dbm(0.0, link_at(100.0)), expected, 1e-9);
  // 20 dB per decade; the log-distance default reference loss is Friis at 1 m.
  EXPECT_NEAR(model->rx_power_dbm(0.0, link_at(10.0)) - model->rx_power_dbm(0.0, link_at(100.0)),
              20.0, 1e-9);
  EXPECT_NEAR(0.0 - model->rx_power_dbm(0.0, link_at(1.0)), 46.6777, 0.01);  // ns-3: c = 3e8
}

TEST(WirelessPropagation, TwoRayGroundIsFriisBelowTheCrossoverAndD4Beyond) {
  PluginLoader loader;
  PluginChoice choice = choose(loader, "two_ray_ground", PluginKind::propagation);
  set_param(choice, "frequency_hz", 914e6);  // ns-2's default: crossover 86.1 m at 1.5 m
  const auto model = make_model(loader, choice);
  const auto friis_choice = [&] {
    PluginChoice f = choose(loader, "friis", PluginKind::propagation);
    set_param(f, "frequency_hz", 914e6);
    return f;
  }();
  const auto friis = make_model(loader, friis_choice);
  const double crossover = 4.0 * std::numbers::pi * 1.5 * 1.5 / (kSpeedOfLightMps / 914e6);
  EXPECT_NEAR(crossover, 86.2, 0.01);
  EXPECT_NEAR(model->rx_power_dbm(0.0, link_at(50.0)), friis->rx_power_dbm(0.0, link_at(50.0)),
              1e-9);
  // Continuous at the crossover; 40 dB per decade beyond it.
  EXPECT_NEAR(model->rx_power_dbm(0.0, link_at(crossover - 1e-9)),
              model->rx_power_dbm(0.0, link_at(crossover)), 1e-6);
  EXPECT_NEAR(model->rx_power_dbm(0.0, link_at(100.0)) - model->rx_power_dbm(0.0, link_at(1000.0)),
              40.0, 1e-9);
  // ns-2's 250 m range: 281.8 mW with its -81 dBm-ish (3.652e-10 W) threshold.
  EXPECT_NEAR(model->rx_power_dbm(10.0 * std::log10(281.8), link_at(250.0)),
              10.0 * std::log10(3.652e-10 * 1e3), 0.05);
}

TEST(WirelessPropagation, RangeIsAHardCutoff) {
  PluginLoader loader;
  const auto model = make_model(loader, "range");
  EXPECT_EQ(model->rx_power_dbm(5.0, link_at(250.0)), 5.0);
  EXPECT_EQ(model->rx_power_dbm(5.0, link_at(250.001)), kNoSignalDbm);
  EXPECT_EQ(model->max_rx_power_dbm(5.0, 251.0), kNoSignalDbm);
}

TEST(WirelessPropagation, NakagamiGainHasUnitMeanAndItsBoundHolds) {
  PluginLoader loader;
  const auto model = make_model(loader, "nakagami");
  for (const double distance : {50.0, 150.0, 300.0}) {
    double sum = 0.0;
    double sum_sq = 0.0;
    double strongest = -1e9;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      const double db = model->rx_power_dbm(0.0, link_at(distance, static_cast<std::uint64_t>(i)));
      const double g = std::pow(10.0, db / 10.0);
      sum += g;
      sum_sq += g * g;
      strongest = std::max(strongest, db);
    }
    const double mean = sum / n;
    const double m = distance < 80.0 ? 1.5 : 0.75;
    EXPECT_NEAR(mean, 1.0, 0.03) << distance;
    // Var(Gamma(m, 1/m)) = 1/m.
    EXPECT_NEAR(sum_sq / n - mean * mean, 1.0 / m, 0.1) << distance;
    EXPECT_LE(strongest, model->max_rx_power_dbm(0.0, distance));
  }
  // Bound never grows with distance, and is above the mean.
  EXPECT_GE(model->max_rx_power_dbm(0.0, 10.0), model->max_rx_power_dbm(0.0, 100.0));
  EXPECT_GT(model->max_rx_power_dbm(0.0, 300.0), 10.0);
  // Per link and frame, not per call.
  EXPECT_EQ(model->rx_power_dbm(0.0, link_at(100.0, 9)),
            model->rx_power_dbm(0.0, link_at(100.0, 9)));
  EXPECT_NE(model->rx_power_dbm(0.0, link_at(100.0, 9)),
            model->rx_power_dbm(0.0, link_at(100.0, 10)));
}

TEST(WirelessPropagation, ShadowingIsGaussianInDbAndBounded) {
  PluginLoader loader;
  const auto model = make_model(loader, "shadowing");
  double sum = 0.0;
  double sum_sq = 0.0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const double x = model->rx_power_dbm(0.0, link_at(10.0, static_cast<std::uint64_t>(i)));
    sum += x;
    sum_sq += x * x;
    EXPECT_LE(x, model->max_rx_power_dbm(0.0, 10.0));
  }
  EXPECT_NEAR(sum / n, 0.0, 0.1);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 4.0, 0.1);
  EXPECT_EQ(model->max_rx_power_dbm(0.0, 10.0), 20.0);

  PluginChoice per_link = choose(loader, "shadowing", PluginKind::propagation);
  set_param(per_link, "per_frame", false);
  const auto static_map = make_model(loader, per_link);
  EXPECT_EQ(static_map->rx_power_dbm(0.0, link_at(10.0, 1)),
            static_map->rx_power_dbm(0.0, link_at(10.0, 2)));
  // Per ordered pair: the two directions of a link draw apart, unless reciprocal.
  EXPECT_NE(static_map->rx_power_dbm(0.0, link_at(10.0, 1, 3, 7)),
            static_map->rx_power_dbm(0.0, link_at(10.0, 1, 7, 3)));
  set_param(per_link, "reciprocal", true);
  const auto reciprocal = make_model(loader, per_link);
  int differing = 0;
  for (NodeId a = 0; a < 20; ++a) {
    for (NodeId b = a + 1; b < 20; ++b) {
      EXPECT_EQ(reciprocal->rx_power_dbm(0.0, link_at(10.0, 1, a, b)),
                reciprocal->rx_power_dbm(0.0, link_at(10.0, 5, b, a)));
      if (reciprocal->rx_power_dbm(0.0, link_at(10.0, 1, a, b)) !=
          reciprocal->rx_power_dbm(0.0, link_at(10.0, 1, a, b + 1 < 20 ? b + 1 : 0))) {
        ++differing;
      }
    }
  }
  EXPECT_GT(differing, 150);  // still a map: pairs draw apart
}

TEST(WirelessPropagation, ChainAppliesModelsInOrderAndBoundsTheCutoff) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 2);
  settings.network.propagation = {choose(loader, "log_distance", PluginKind::propagation),
                                  choose(loader, "nakagami", PluginKind::propagation)};
  const PropagationChain chain(settings, loader);
  // The cutoff of log_distance + nakagami is farther than that of log_distance alone.
  NetworkSettings plain = settings;
  plain.network.propagation.pop_back();
  const PropagationChain plain_chain(plain, loader);
  const double threshold = -82.0;
  const double with_fading = cutoff_distance_m(chain, 16.0206, threshold);
  const double without = cutoff_distance_m(plain_chain, 16.0206, threshold);
  EXPECT_NEAR(without, 51.5, 0.3);
  EXPECT_GT(with_fading, without * 2.0);  // +13.5 dB at 30 dB/decade: x2.8
  for (std::uint64_t uid = 1; uid < 2000; ++uid) {
    EXPECT_LT(chain.rx_power_dbm(16.0206, link_at(with_fading, uid)), threshold);
  }
}

TEST(WirelessPropagation, ModelsSayWhetherTheyVaryPerFrame) {
  // The channel reuses a transmitter's links within a step only when no model in the chain
  // varies per frame; each model's answer must match what its rx_power_dbm does.
  PluginLoader loader;
  // What rx_power_dbm does: one link at 10 m, twenty frames; do their powers differ?
  const auto draws_per_frame = [](const PluginInstance<Propagation>& model) {
    const double first = model->rx_power_dbm(0.0, link_at(10.0, 1));
    for (std::uint64_t uid = 2; uid <= 20; ++uid) {
      if (model->rx_power_dbm(0.0, link_at(10.0, uid)) != first) return true;
    }
    return false;
  };
  for (const char* name : {"log_distance", "friis", "two_ray_ground", "range"}) {
    const auto model = make_model(loader, name);
    EXPECT_FALSE(model->varies_per_frame()) << name;
    EXPECT_FALSE(draws_per_frame(model)) << name;
  }
  for (const char* name : {"nakagami", "shadowing"}) {
    EXPECT_TRUE(draws_per_frame(make_model(loader, name))) << name;
  }
  EXPECT_TRUE(make_model(loader, "nakagami")->varies_per_frame());
  EXPECT_TRUE(make_model(loader, "shadowing")->varies_per_frame());
  PluginChoice per_link = choose(loader, "shadowing", PluginKind::propagation);
  set_param(per_link, "per_frame", false);
  EXPECT_FALSE(make_model(loader, per_link)->varies_per_frame());
  EXPECT_FALSE(draws_per_frame(make_model(loader, per_link)));
  EXPECT_FALSE(make_model(loader, "disk")->varies_per_frame());  // probability 1
  EXPECT_FALSE(draws_per_frame(make_model(loader, "disk")));
  PluginChoice lossy = choose(loader, "disk", PluginKind::propagation);
  set_param(lossy, "probability", 0.5);
  EXPECT_TRUE(make_model(loader, lossy)->varies_per_frame());
  EXPECT_TRUE(draws_per_frame(make_model(loader, lossy)));

  NetworkSettings settings = test::make_settings(loader, 2);
  settings.network.propagation = {choose(loader, "log_distance", PluginKind::propagation)};
  EXPECT_FALSE(PropagationChain(settings, loader).varies_per_frame());
  settings.network.propagation.push_back(choose(loader, "nakagami", PluginKind::propagation));
  EXPECT_TRUE(PropagationChain(settings, loader).varies_per_frame());
}

}  // namespace
}  // namespace swarmnet
