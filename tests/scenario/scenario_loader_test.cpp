// Valid scenarios: every field filled, defaults, overrides, the output directory rule and the
// resolved scenario.
#include "scenario/scenario_loader.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <string>

#include "scenario_test_support.hpp"

namespace swarmnet {
namespace {

namespace fs = std::filesystem;
using test::Contains;

const fs::path kMinimal = test::kScenarioDir / "good" / "minimal.yaml";
const fs::path kFull = test::kScenarioDir / "good" / "full.yaml";

Scenario load(const fs::path& file, const ScenarioOverrides& overrides = {}) {
  PluginLoader loader({test::kFixtures});
  return load_scenario(file, overrides, loader);
}

Scenario load_with(const fs::path& file, std::vector<std::string> set) {
  ScenarioOverrides overrides;
  overrides.set = std::move(set);
  return load(file, overrides);
}

bool same_rect(const Rect& a, const Rect& b) {
  return a.x_min_m == b.x_min_m && a.y_min_m == b.y_min_m && a.x_max_m == b.x_max_m &&
         a.y_max_m == b.y_max_m;
}

TEST(ScenarioLoader, FullScenarioFillsEveryField) {
  const Scenario s = load(kFull);
  EXPECT_EQ(s.name, "full-scenario");
  EXPECT_EQ(s.source, kFull);
  EXPECT_EQ(s.seed, 42u);
  EXPECT_EQ(s.duration_s, 12.5);
  EXPECT_EQ(s.step_s, 0.05);
  EXPECT_EQ(s.step_count(), 250u);
  EXPECT_EQ(s.sync, SyncMode::pipelined);
  EXPECT_TRUE(s.plugin_paths.empty());

  EXPECT_EQ(s.arena.width_m, 200.0);
  EXPECT_EQ(s.arena.height_m, 100.0);
  ASSERT_EQ(s.arena.obstacles.size(), 2u);
  EXPECT_TRUE(same_rect(s.arena.obstacles[0], Rect{10, 10, 20, 30}));
  EXPECT_TRUE(same_rect(s.arena.obstacles[1], Rect{150, 0, 200, 5.5}));

  EXPECT_EQ(s.robots.count, 25u);
  EXPECT_EQ(s.robots.radius_m, 0.1);
  EXPECT_EQ(s.robots.axle_m, 0.12);
  EXPECT_EQ(s.robots.max_speed_mps, 0.5);
  EXPECT_TRUE(same_rect(s.robots.placement, Rect{50, 20, 100, 80}));
  EXPECT_EQ(s.robots.proximity.rays, 8u);
  EXPECT_EQ(s.robots.proximity.range_m, 1.5);

  ASSERT_EQ(s.robots.controllers.size(), 2u);
  const PluginChoice& first = s.robots.controllers[0];
  EXPECT_EQ(first.name, "test_controller");
  EXPECT_EQ(first.kind, PluginKind::controller);
  EXPECT_EQ(first.where.text, kFull.string() + ":27:15");
  EXPECT_EQ(first.params.real("speed_mps"), 2.0);  // an integer accepted for a real
  EXPECT_EQ(first.params.text("mode"), "straight");
  EXPECT_EQ(first.params.text("label"), "left wall");
  EXPECT_EQ(first.params.real("rate_hz"), 1.0);  // defaults from the plugin's schema
  EXPECT_EQ(first.params.integer("count"), 3);
  EXPECT_TRUE(first.params.boolean("enabled"));
  const PluginChoice& second = s.robots.controllers[1];
  EXPECT_EQ(second.params.real("rate_hz"), 5.0);
  EXPECT_EQ(second.params.integer("count"), 7);
  EXPECT_FALSE(second.params.boolean("enabled"));
  EXPECT_EQ(second.params.real("speed_mps"), 1.0);

  EXPECT_EQ(s.physics.name, "kinematic2d");
  EXPECT_EQ(s.physics.kind, PluginKind::physics);
  EXPECT_TRUE(s.physics.params.values().empty());

  ASSERT_EQ(s.network.propagation.size(), 2u);
  EXPECT_EQ(s.network.propagation[0].params.real("range_m"), 120.0);
  EXPECT_EQ(s.network.propagation[0].params.real("probability"), 1.0);
  EXPECT_EQ(s.network.propagation[1].params.real("range_m"), 100.0);
  EXPECT_EQ(s.network.propagation[1].params.real("probability"), 0.5);
  EXPECT_EQ(s.network.phy.tx_power_dbm, 20.0);
  EXPECT_EQ(s.network.phy.rx_sensitivity_dbm, -90.5);
  EXPECT_FALSE(s.network.channel.cutoff);
  EXPECT_EQ(s.network.mac.name, "ideal_mac");
  EXPECT_EQ(s.network.mac.kind, PluginKind::mac);
  EXPECT_EQ(s.network.mac.params.real("bitrate_bps"), 1.1e7);
  EXPECT_EQ(s.network.routing.name, "test_routing");
  EXPECT_EQ(s.network.routing.kind, PluginKind::routing);
  EXPECT_EQ(s.network.routing.params.integer("ttl"), 8);
  EXPECT_EQ(s.network.routing.params.real("jitter_max_s"), 0.005);
  EXPECT_EQ(s.network.routing.where.text, kFull.string() + ":59:13");

  EXPECT_EQ(s.output.dir, fs::path("results/full"));
  EXPECT_FALSE(s.output.packet_trace);
  EXPECT_TRUE(s.output.mobility_trace);
  EXPECT_EQ(s.output.mobility_interval_s, 0.5);
  EXPECT_FALSE(s.output.traffic_schedule);
}

TEST(ScenarioLoader, OptionalKeysTakeTheirDocumentedDefaults) {
  const Scenario s = load(kMinimal);
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.step_s, 0.1);
  EXPECT_EQ(s.step_count(), 100u);
  EXPECT_EQ(s.sync, SyncMode::strict);
  EXPECT_TRUE(s.arena.obstacles.empty());
  EXPECT_EQ(s.robots.radius_m, 0.085);
  EXPECT_EQ(s.robots.axle_m, 0.14);
  EXPECT_EQ(s.robots.max_speed_mps, 1.0);
  EXPECT_TRUE(same_rect(s.robots.placement, Rect{0, 0, 100, 50})) << "the whole arena";
  EXPECT_EQ(s.robots.proximity.rays, 24u);
  EXPECT_EQ(s.robots.proximity.range_m, 0.3);
  const RangeAndBearingConfig& rab = s.robots.range_and_bearing;
  EXPECT_FALSE(rab.enabled);
  EXPECT_EQ(rab.range_m, 3.0);
  EXPECT_EQ(rab.range_noise_sd_m, 0.0);
  EXPECT_EQ(rab.bearing_noise_sd_rad, 0.0);
  EXPECT_EQ(rab.loss_probability, 0.0);
  EXPECT_EQ(rab.data_bytes, 10u);
  EXPECT_FALSE(s.robot_settings().robots.range_and_bearing.enabled);
  ASSERT_EQ(s.robots.controllers.size(), 1u);
  EXPECT_EQ(s.robots.controllers[0].params.values().size(), 6u);
  EXPECT_EQ(s.robots.controllers[0].params.text("mode"), "random");
  EXPECT_EQ(s.physics.name, "kinematic2d");
  EXPECT_EQ(s.physics.where.text, kMinimal.string() + " (physics: default physics plugin)");
  EXPECT_EQ(s.network.phy.tx_power_dbm, 16.0206);
  EXPECT_EQ(s.network.phy.rx_sensitivity_dbm, -96.0);
  EXPECT_TRUE(s.network.channel.cutoff);
  EXPECT_TRUE(s.network.channel.lazy_far_signals);
  EXPECT_EQ(s.network.phy.header_failure_cca, HeaderFailureCca::sensed);
  EXPECT_EQ(s.network.mac.name, "ideal_mac");
  EXPECT_EQ(s.network.mac.params.real("bitrate_bps"), 6.0e6);
  EXPECT_EQ(s.network.routing.params.integer("ttl"), 32);
  EXPECT_EQ(s.output.dir, fs::path("runs/minimal-seed1"));
  EXPECT_TRUE(s.output.packet_trace);
  EXPECT_FALSE(s.output.frame_trace) << "off unless asked for: it is large";
  EXPECT_FALSE(s.output.sensing_trace) << "off unless asked for: runs without it stay as they were";
  EXPECT_TRUE(s.output.mobility_trace);
  EXPECT_EQ(s.output.mobility_interval_s, 0.0);
  EXPECT_TRUE(s.output.traffic_schedule);
}

TEST(ScenarioLoader, HeaderFailureCcaIsReadAndCheckedAgainstItsChoices) {
  EXPECT_EQ(load_with(kFull, {"network.phy.header_failure_cca=ns3"}).network.phy.header_failure_cca,
            HeaderFailureCca::ns3);
  try {
    (void)load_with(kFull, {"network.phy.header_failure_cca=ns-3"});
    FAIL() << "an unknown choice was accepted";
  } catch (const ScenarioError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("network.phy.header_failure_cca"), std::string::npos) << text;
    EXPECT_NE(text.find("ns3"), std::string::npos) << text;
  }
}

TEST(ScenarioLoader, InterferenceFloorMayLieAboveTheNoise) {
  // Above 0 dB the floor is above the noise (11.99 ignores every undetectable signal); past
  // 100 dB it is refused with its range.
  EXPECT_EQ(load_with(kFull, {"network.phy.interference_floor_db=11.99"})
                .network.phy.interference_floor_db,
            11.99);
  try {
    (void)load_with(kFull, {"network.phy.interference_floor_db=150"});
    FAIL() << "a floor of 150 dB was accepted";
  } catch (const ScenarioError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("network.phy.interference_floor_db: 150 is out of range; expected real "
                        "-100..100 (dB)"),
              std::string::npos)
        << text;
  }
}

// network.seed seeds the network half alone; absent, the master seed does, and a negative one is
// refused with its key named.
TEST(ScenarioLoader, NetworkSeedSeedsTheNetworkHalfAndKeepsTheTrafficOnTheMasterSeed) {
  const Scenario absent = load_with(kFull, {"seed=5"});
  EXPECT_FALSE(absent.network.seed.has_value());
  EXPECT_EQ(absent.network_settings().seed, 5u);
  EXPECT_EQ(absent.network_settings().traffic_seed, 5u);
  const Scenario given = load_with(kFull, {"seed=5", "network.seed=9"});
  EXPECT_EQ(given.network_settings().seed, 9u);
  EXPECT_EQ(given.network_settings().traffic_seed, 5u);
  EXPECT_EQ(given.robot_settings().seed, 5u);
  try {
    (void)load_with(kFull, {"network.seed=-1"});
    FAIL() << "a negative network seed was accepted";
  } catch (const ScenarioError& error) {
    EXPECT_NE(std::string(error.what()).find("network.seed"), std::string::npos) << error.what();
  }
}

// A controller entry's port (swarmnet/controller.hpp) is its index unless the scenario gives one;
// the resolved scenario states every port.
TEST(ScenarioLoader, ControllerPortsDefaultToTheirIndexAndAreChecked) {
  const Scenario s = load(kFull);
  EXPECT_EQ(s.robots.controller_ports, (std::vector<std::uint16_t>{0, 1}));
  EXPECT_NE(s.resolved_yaml.find("port: 1"), std::string::npos) << s.resolved_yaml;
  const Scenario shared = load_with(kFull, {"robots.controllers.1.port=0"});
  EXPECT_EQ(shared.robots.controller_ports, (std::vector<std::uint16_t>{0, 0}));
  try {
    (void)load_with(kFull, {"robots.controllers.0.port=70000"});
    FAIL() << "port 70000 accepted";
  } catch (const ScenarioError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("--set robots.controllers.0.port: robots.controllers.0.port: 70000 is out "
                        "of range; expected integer 0..65535"),
              std::string::npos)
        << error.what();
  }
}

TEST(ScenarioLoader, SetOverridesNestedValuesAndListElements) {
  const Scenario s = load_with(
      kFull, {"robots.count=30", "robots.controllers.1.params.rate_hz=2",
              "arena.obstacles.0.x_max_m=25", "network.phy.tx_power_dbm=0", "sync=strict"});
  EXPECT_EQ(s.robots.count, 30u);
  EXPECT_EQ(s.robots.controllers[1].params.real("rate_hz"), 2.0);
  EXPECT_EQ(s.robots.controllers[1].params.integer("count"), 7) << "siblings untouched";
  EXPECT_EQ(s.robots.controllers[0].params.real("rate_hz"), 1.0) << "other elements untouched";
  EXPECT_EQ(s.arena.obstacles[0].x_max_m, 25.0);
  EXPECT_EQ(s.arena.obstacles[0].x_min_m, 10.0);
  EXPECT_EQ(s.network.phy.tx_power_dbm, 0.0);
  EXPECT_EQ(s.sync, SyncMode::strict);
  // An overridden plugin is located at its override.
  const Scenario t = load_with(kMinimal, {"network.routing.plugin=test_routing"});
  EXPECT_EQ(t.network.routing.where.text, "--set network.routing.plugin");
}

TEST(ScenarioLoader, RangeAndBearingKeysReachTheRobotSettings) {
  const Scenario s = load_with(
      kMinimal,
      {"robots.range_and_bearing.enabled=true", "robots.range_and_bearing.range_m=0.8",
       "robots.range_and_bearing.range_noise_sd_m=0.02",
       "robots.range_and_bearing.bearing_noise_sd_rad=0.05",
       "robots.range_and_bearing.loss_probability=0.25", "robots.range_and_bearing.data_bytes=4"});
  const RangeAndBearingConfig expected{true, 0.8, 0.02, 0.05, 0.25, 4};
  EXPECT_TRUE(s.robot_settings().robots.range_and_bearing == expected);
}

TEST(ScenarioLoader, SetCreatesMissingKeysAndReplacesWholeValues) {
  const std::string controllers =
      "robots.controllers=[{plugin: test_controller}, "
      "{plugin: test_controller, params: {mode: straight}}]";
  const Scenario s = load_with(
      kMinimal, {"robots.placement.region={x_min_m: 10, y_min_m: 5, x_max_m: 20, y_max_m: 15}",
                 "network.mac.params.bitrate_bps=1e6", controllers,
                 "arena.obstacles=[{x_min_m: 1, y_min_m: 1, x_max_m: 2, y_max_m: 2}]",
                 "output.dir=elsewhere"});
  EXPECT_TRUE(same_rect(s.robots.placement, Rect{10, 5, 20, 15}));
  EXPECT_EQ(s.network.mac.params.real("bitrate_bps"), 1e6);
  ASSERT_EQ(s.robots.controllers.size(), 2u);
  EXPECT_EQ(s.robots.controllers[1].params.text("mode"), "straight");
  ASSERT_EQ(s.arena.obstacles.size(), 1u);
  EXPECT_EQ(s.output.dir, fs::path("elsewhere"));
}

// arena.objects: shapes, poses and masses as written, unstated keys at their defaults.
TEST(ScenarioLoader, ReadsMovableObjects) {
  const Scenario s = load_with(
      kMinimal,
      {"arena.objects=[{shape: box, x_m: 5, y_m: 6, size_x_m: 0.4, size_y_m: 0.2, "
       "heading_rad: 0.5, mass_kg: 2}, {shape: cylinder, x_m: 8, y_m: 9, radius_m: 0.1}]"});
  ASSERT_EQ(s.arena.objects.size(), 2u);
  const ArenaObject& box = s.arena.objects[0];
  EXPECT_EQ(box.shape, ArenaObject::Shape::box);
  EXPECT_EQ(box.position, Vec2(5, 6));
  EXPECT_EQ(box.size_x_m, 0.4);
  EXPECT_EQ(box.size_y_m, 0.2);
  EXPECT_EQ(box.heading_rad, 0.5);
  EXPECT_EQ(box.mass_kg, 2.0);
  const ArenaObject& cylinder = s.arena.objects[1];
  EXPECT_EQ(cylinder.shape, ArenaObject::Shape::cylinder);
  EXPECT_EQ(cylinder.position, Vec2(8, 9));
  EXPECT_EQ(cylinder.radius_m, 0.1);
  EXPECT_EQ(cylinder.heading_rad, 0.0);
  EXPECT_EQ(cylinder.mass_kg, 0.5);
  EXPECT_TRUE(load_with(kMinimal, {}).arena.objects.empty());
}

TEST(ScenarioLoader, LaterOverridesWin) {
  const Scenario s = load_with(kMinimal, {"robots.count=5", "robots.count=7"});
  EXPECT_EQ(s.robots.count, 7u);
}

TEST(ScenarioLoader, SeedAndOutputDirectoryOverrides) {
  ScenarioOverrides seed_only;
  seed_only.seed = 7;
  const Scenario a = load(kMinimal, seed_only);
  EXPECT_EQ(a.seed, 7u);
  EXPECT_EQ(a.output.dir, fs::path("runs/minimal-seed7")) << "the default follows the seed";
  EXPECT_EQ(YAML::Load(a.resolved_yaml)["seed"].as<std::string>(), "7");

  ScenarioOverrides both;
  both.seed = 9;
  both.set = {"seed=3", "output.dir=from-set"};
  both.out_dir = "from/out";
  const Scenario b = load(kMinimal, both);
  EXPECT_EQ(b.seed, 9u) << "--seed wins over --set seed";
  EXPECT_EQ(b.output.dir, fs::path("from/out")) << "--out wins over output.dir";
  EXPECT_EQ(YAML::Load(b.resolved_yaml)["output"]["dir"].as<std::string>(), "from/out");

  const Scenario c = load(kFull);
  EXPECT_EQ(c.output.dir, fs::path("results/full")) << "output.dir from the file, as written";
}

TEST(ScenarioLoader, PluginPathsAreRelativeToTheScenarioFile) {
  test::TempDir dir("plugin-paths");
  // A relative path from the scenario's directory to the fixtures; the loader itself knows no
  // directory of fixtures.
  const fs::path relative = fs::relative(test::kFixtures, dir.path() / "sub");
  std::string text = test::read_text(kMinimal);
  text += "plugin_paths:\n  - " + relative.string() + "\n";
  const fs::path file = dir.write("sub/scenario.yaml", text);

  PluginLoader loader;
  const Scenario s = load_scenario(file, {}, loader);
  ASSERT_EQ(s.plugin_paths.size(), 1u);
  EXPECT_EQ(s.plugin_paths[0], test::kFixtures);
  EXPECT_EQ(loader.search_path().front(), test::kFixtures) << "searched before anything else";
  EXPECT_EQ(YAML::Load(s.resolved_yaml)["plugin_paths"][0].as<std::string>(),
            test::kFixtures.string());

  // Without plugin_paths the same loader search path (fresh) finds nothing.
  PluginLoader bare;
  try {
    load_scenario(kMinimal, {}, bare);
    FAIL() << "loaded without the fixture directory";
  } catch (const ScenarioError& error) {
    EXPECT_TRUE(Contains(error.what(), "plugin 'test_controller' not found"));
  }
}

// A server reads a peer's scenario with its own plugin search path: the text's plugin_paths,
// however spelt, is neither looked up (no "is not a directory" about the server's folders) nor
// searched; given twice, it is refused at the second.
TEST(ScenarioLoader, APeersScenarioKeepsTheServersPluginPathsWhateverItSays) {
  const std::string text = test::read_text(kMinimal);
  const std::vector<fs::path> host = {test::kFixtures};
  for (const std::string key : {"plugin_paths", "\"plugin_paths\"", "!!str plugin_paths"}) {
    PluginLoader loader(host);
    const auto before = loader.search_path();
    const Scenario s = load_peer_scenario_text(
        text + key + ": [/no/such/dir, " + test::kScenarioDir.string() + "]\n", "peer", loader,
        host);
    EXPECT_EQ(s.plugin_paths, host) << key;
    EXPECT_EQ(loader.search_path(), before) << key;
  }
  PluginLoader loader(host);
  try {
    load_peer_scenario_text("plugin_paths: []\n" + text + "plugin_paths: [/peer]\n", "peer", loader,
                            host);
    FAIL() << "a repeated plugin_paths was accepted";
  } catch (const ScenarioError& error) {
    EXPECT_TRUE(Contains(error.what(), "plugin_paths: is given twice (first at line 1:1)"));
    EXPECT_FALSE(Contains(error.what(), "/peer"));
  }
}

TEST(ScenarioLoader, ResolvedScenarioHasEveryKeyInAFixedOrder) {
  const Scenario s = load(kMinimal);
  const YAML::Node r = YAML::Load(s.resolved_yaml);
  std::vector<std::string> top;
  for (const auto& entry : r) top.push_back(entry.first.as<std::string>());
  EXPECT_EQ(
      top, (std::vector<std::string>{"name", "seed", "duration_s", "step_s", "sync", "plugin_paths",
                                     "arena", "robots", "world", "physics", "network", "output"}));
  EXPECT_EQ(r["step_s"].as<std::string>(), "0.1");
  EXPECT_EQ(r["robots"]["radius_m"].as<std::string>(), "0.085");
  EXPECT_EQ(r["robots"]["placement"]["region"]["x_max_m"].as<std::string>(), "100");
  EXPECT_EQ(r["robots"]["proximity"]["rays"].as<std::string>(), "24");
  EXPECT_EQ(r["robots"]["controllers"][0]["params"].size(), 6u);
  EXPECT_EQ(r["physics"]["plugin"].as<std::string>(), "kinematic2d");
  EXPECT_EQ(r["network"]["mac"]["params"]["bitrate_bps"].as<std::string>(), "6000000");
  EXPECT_EQ(r["network"]["phy"]["tx_power_dbm"].as<std::string>(), "16.0206");
  EXPECT_EQ(r["output"]["dir"].as<std::string>(), "runs/minimal-seed1");
  std::vector<std::string> output;
  for (const auto& entry : r["output"]) output.push_back(entry.first.as<std::string>());
  EXPECT_EQ(output,
            (std::vector<std::string>{"dir", "packet_trace", "frame_trace", "sensing_trace",
                                      "mobility_trace", "mobility_interval_s", "traffic_schedule"}))
      << "a derived key takes its schema place, not the end";
}

TEST(ScenarioLoader, ResolvedYamlIsDeterministicAndReloadsToTheSameBytes) {
  const std::string once = resolved_yaml(load(kFull));
  EXPECT_EQ(resolved_yaml(load(kFull)), once) << "two loads, same bytes";
  // The same scenario written differently (keys reordered, defaults spelt out) resolves the same.
  test::TempDir dir("resolved");
  const fs::path copy = dir.write("resolved.yaml", once);
  const std::string again = resolved_yaml(load(copy));
  EXPECT_EQ(again, once);

  const std::string minimal = resolved_yaml(load(kMinimal));
  const fs::path minimal_copy = dir.write("minimal.resolved.yaml", minimal);
  EXPECT_EQ(resolved_yaml(load(minimal_copy)), minimal);
  EXPECT_TRUE(Contains(minimal,
                       "name: minimal\nseed: 1\nduration_s: 10\nstep_s: 0.1\n"
                       "sync: strict\nplugin_paths: []\n"));
  EXPECT_TRUE(
      Contains(minimal, "    region: {x_min_m: 0, y_min_m: 0, x_max_m: 100, y_max_m: 50}\n"));
  EXPECT_TRUE(
      Contains(once, "  obstacles:\n    - {x_min_m: 10, y_min_m: 10, x_max_m: 20, y_max_m: 30}\n"));
  EXPECT_TRUE(Contains(once, "      label: left wall\n"));
  EXPECT_TRUE(Contains(minimal, "      label: \"\"\n")) << "empty text stays text";
}

TEST(ScenarioLoader, LoadsResolvedTextAsTheNetworkHalfReceivesIt) {
  const Scenario sent = load(kFull);
  const std::string text = resolved_yaml(sent);
  PluginLoader loader({test::kFixtures});
  const Scenario received = load_scenario_text(text, "the robot half's scenario", loader);
  EXPECT_EQ(resolved_yaml(received), text);
  EXPECT_EQ(received.source, fs::path("the robot half's scenario"));
  // The routing plugin's line in the resolved text (every key written, network.phy's included),
  // found in the text rather than counted, so that a new key elsewhere does not move it.
  const std::size_t routing = text.find("\n  routing:\n");
  ASSERT_NE(routing, std::string::npos) << text;
  const auto plugin_line = std::count(text.begin(), text.begin() + routing + 1, '\n') + 2;
  EXPECT_EQ(received.network.routing.where.text,
            "the robot half's scenario:" + std::to_string(plugin_line) + ":13");

  try {
    load_scenario_text("name: x\nduration_s: -1\n", "the robot half's scenario", loader);
    FAIL() << "loaded";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(
        error.problems().front(),
        "the robot half's scenario:2:13: duration_s: -1 is out of range; expected real > 0 (s)");
  }
}

TEST(ScenarioLoader, IntegerValuedRealsAndExponentsAreAccepted) {
  const Scenario s = load_with(kMinimal, {"duration_s=1e2", "step_s=+0.5", "arena.width_m=1.5e2"});
  EXPECT_EQ(s.duration_s, 100.0);
  EXPECT_EQ(s.step_s, 0.5);
  EXPECT_EQ(s.step_count(), 200u);
  EXPECT_EQ(s.arena.width_m, 150.0);
}

TEST(ScenarioLoader, StepCountToleratesBinaryFractions) {
  // 0.3 / 0.1 is 2.9999999999999996 in binary floating point: still three steps.
  const Scenario s = load_with(kMinimal, {"duration_s=0.3", "step_s=0.1"});
  EXPECT_EQ(s.step_count(), 3u);
  const Scenario t = load_with(kMinimal, {"duration_s=120", "step_s=0.1"});
  EXPECT_EQ(t.step_count(), 1200u);
}

TEST(ScenarioLoader, QuickstartValidatesWhenTheRealPluginsAreBuilt) {
  const fs::path quickstart = fs::path(SWARMNET_SOURCE_DIR) / "configs" / "quickstart.yaml";
  PluginLoader loader;
  try {
    const Scenario s = load_scenario(quickstart, {}, loader);
    EXPECT_EQ(s.name, "quickstart");
    EXPECT_EQ(s.robots.count, 50u);
    EXPECT_EQ(s.step_count(), 1200u);
  } catch (const ScenarioError& error) {
    // Only missing plugins may stop it here (they are built by other targets).
    for (const auto& line : error.problems()) {
      if (line.find("not found; searched:") == std::string::npos) ADD_FAILURE() << line;
    }
    GTEST_SKIP() << "the real plugins are not built in this tree";
  }
}

}  // namespace
}  // namespace swarmnet

namespace swarmnet {
namespace {

// Loading is linear in list length (issue 12): 100,000 obstacles load, where 4000 took minutes
// when the resolved scenario was built by copying nodes.
TEST(ScenarioLoader, AHundredThousandObstaclesLoad) {
  std::string text =
      "name: many-obstacles\nduration_s: 1\narena:\n  width_m: 1000\n  height_m: 1000\n"
      "  obstacles:\n";
  constexpr int kObstacles = 100000;
  for (int i = 0; i < kObstacles; ++i) {
    const double x = 1.0 + (i % 400) * 2.0;
    const double y = 200.0 + (i / 400) * 2.0;  // rows 200 m to 700 m; robots start below
    text += "    - {x_min_m: " + std::to_string(x) + ", y_min_m: " + std::to_string(y) +
            ", x_max_m: " + std::to_string(x + 1.0) + ", y_max_m: " + std::to_string(y + 1.0) +
            "}\n";
  }
  text +=
      "robots:\n  count: 10\n  placement:\n    region: {x_min_m: 0, y_min_m: 0, x_max_m: 100, "
      "y_max_m: 100}\n  controllers:\n    - plugin: test_controller\nnetwork:\n  propagation:\n"
      "    - plugin: test_propagation\n  routing:\n    plugin: test_routing\n";
  const test::TempDir dir("many-obstacles");
  const Scenario s = load(dir.write("many.yaml", text));
  ASSERT_EQ(s.arena.obstacles.size(), static_cast<std::size_t>(kObstacles));
  EXPECT_TRUE(same_rect(s.arena.obstacles.back(), Rect{799, 698, 800, 699}));
  EXPECT_NE(s.resolved_yaml.find("x_min_m: 799"), std::string::npos);
}

}  // namespace
}  // namespace swarmnet
