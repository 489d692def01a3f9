// A validated scenario: everything a run needs, with defaults filled and plugins resolved.
// Produced only by load_scenario() (scenario_loader.hpp); every field here has been checked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/params.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

// Where a value came from, for error messages: "file.yaml:12:5" or "--set robots.count".
struct SourceLocation {
  std::string text;
};

// One plugin chosen in the scenario, with its validated parameters.
struct PluginChoice {
  std::string name;
  PluginKind kind = PluginKind::controller;
  ParamSet params;
  SourceLocation where;
};

enum class SyncMode : std::uint8_t { strict, pipelined };

inline const char* to_string(SyncMode mode) {
  return mode == SyncMode::strict ? "strict" : "pipelined";
}

struct ProximityConfig {
  std::uint32_t rays = 24;
  double range_m = 0.3;
};

struct RobotsConfig {
  std::uint32_t count = 0;
  double radius_m = 0.085;
  double axle_m = 0.14;
  double max_speed_mps = 1.0;
  Rect placement;  // region robots start in (defaults to the whole arena)
  ProximityConfig proximity;
  std::vector<PluginChoice> controllers;  // run in this order on every step
};

enum class PhyModel : std::uint8_t { threshold, sinr };

// The radio of every node (network/phy.hpp describes both reception models). Defaults of the
// sinr model's keys are ns-3.37's YansWifiPhy defaults for 802.11a.
struct PhyConfig {
  double tx_power_dbm = 16.0206;
  double rx_sensitivity_dbm = -96.0;  // threshold model: frames weaker than this are not received
  PhyModel model = PhyModel::threshold;
  double tx_gain_db = 0.0;
  double rx_gain_db = 0.0;
  double bandwidth_hz = 20.0e6;
  double noise_figure_db = 7.0;
  double energy_detection_dbm = -62.0;   // CCA-ED: total energy that makes the medium busy
  double cca_threshold_dbm = -82.0;      // weakest frame whose preamble is detected (and sensed)
  double preamble_snr_db = 4.0;          // SINR a preamble needs to be detected
  double interference_floor_db = -10.0;  // signals below noise floor + this are ignored
  // Signals below cca_threshold + this are quiet (not carrier-sensed); the default makes none.
  double sensing_floor_db = -100.0;
};

struct ChannelConfig {
  bool cutoff = true;  // visit only nodes that can possibly hear a frame (DESIGN.md section 7)
};

struct NetworkConfig {
  std::vector<PluginChoice> propagation;  // applied in order
  PhyConfig phy;
  ChannelConfig channel;
  PluginChoice mac;
  PluginChoice routing;
};

struct OutputConfig {
  std::filesystem::path dir;  // resolved: --out, else output.dir, else runs/<name>-seed<seed>
  bool packet_trace = true;
  bool mobility_trace = true;
  double mobility_interval_s = 0.0;  // 0: every step
  bool traffic_schedule = true;
};

struct Scenario {
  std::string name;
  std::filesystem::path source;  // the file it was read from
  std::uint64_t seed = 1;
  double duration_s = 0.0;
  double step_s = 0.1;
  SyncMode sync = SyncMode::strict;
  std::vector<std::filesystem::path> plugin_paths;  // searched before anything else
  Arena arena;
  RobotsConfig robots;
  PluginChoice physics;
  NetworkConfig network;
  OutputConfig output;

  // The scenario as run, as YAML text: every key in a fixed order, defaults filled and overrides
  // applied (scenario.resolved.yaml).
  std::string resolved_yaml;

  [[nodiscard]] std::uint64_t step_count() const;
};

}  // namespace swarmnet
