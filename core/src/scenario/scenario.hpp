// A validated scenario: everything a run needs, with defaults filled and plugins resolved. The
// engines never see it: each takes its own typed settings (network_settings(), robot_settings()).
// Produced only by load_scenario() (scenario_loader.hpp); every field here has been checked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "network/network_settings.hpp"
#include "plugin/plugin_choice.hpp"
#include "robot/robot_settings.hpp"
#include "swarmnet/arena.hpp"

namespace swarmnet {

enum class SyncMode : std::uint8_t { strict, pipelined };

inline const char* to_string(SyncMode mode) {
  return mode == SyncMode::strict ? "strict" : "pipelined";
}

struct OutputConfig {
  std::filesystem::path dir;  // resolved: --out, else output.dir, else runs/<name>-seed<seed>
  bool packet_trace = true;
  bool frame_trace = false;  // every frame on the air (frames.csv): large, so off by default
  // What the network half handed the controllers each window (sensing.csv)
  bool sensing_trace = false;
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
  std::vector<PluginChoice> worlds;  // the `world` list, in order
  PluginChoice physics;
  NetworkConfig network;
  OutputConfig output;

  // The scenario as run, as YAML text: every key in a fixed order, defaults filled and overrides
  // applied (scenario.resolved.yaml).
  std::string resolved_yaml;

  [[nodiscard]] std::uint64_t step_count() const;
  // What each engine is set up with: the parts of this scenario it simulates.
  [[nodiscard]] NetworkSettings network_settings() const;
  [[nodiscard]] RobotSettings robot_settings() const;
};

}  // namespace swarmnet
