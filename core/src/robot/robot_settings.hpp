// What the robot half is set up with: typed settings, no YAML. The scenario loader fills them
// from a validated scenario (Scenario::robot_settings); tests build them by hand.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <vector>

#include "plugin/plugin_choice.hpp"
#include "swarmnet/arena.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

struct ProximityConfig {
  std::uint32_t rays = 24;
  double range_m = 0.3;
};

// robots.range_and_bearing (swarmnet/range_and_bearing.hpp); defaults as the scenario's.
struct RangeAndBearingConfig {
  bool enabled = false;
  double range_m = 3.0;  // a foot-bot's
  double range_noise_sd_m = 0.0;
  double bearing_noise_sd_rad = 0.0;
  double loss_probability = 0.0;
  std::uint32_t data_bytes = 10;  // a foot-bot's

  bool operator==(const RangeAndBearingConfig&) const = default;
};

struct RobotsConfig {
  std::uint32_t count = 0;
  double radius_m = 0.085;
  double axle_m = 0.14;
  double max_speed_mps = 1.0;
  Rect placement;  // region robots start in (defaults to the whole arena)
  ProximityConfig proximity;
  RangeAndBearingConfig range_and_bearing;
  std::vector<PluginChoice> controllers;  // run in this order on every step
  // controllers[c]'s port (swarmnet/controller.hpp); an entry without one here has port c.
  std::vector<std::uint16_t> controller_ports;

  [[nodiscard]] std::uint16_t port_of(std::size_t entry) const {
    return entry < controller_ports.size() ? controller_ports[entry]
                                           : static_cast<std::uint16_t>(entry);
  }
};

struct RobotSettings {
  std::uint64_t seed = 1;  // master seed: every stream is derived from it (swarmnet/random.hpp)
  double step_s = 0.1;     // must be positive
  Arena arena;
  RobotsConfig robots;
  PluginChoice physics;
  std::vector<PluginChoice> worlds;  // world plugins, run in this order (swarmnet/world.hpp)
  bool neighbor_tables = false;      // network.neighbors.enabled: neighbors() answers
  // Opens series.csv, at the first sample() (robot/metric_series.hpp); without it sample()
  // throws std::logic_error.
  std::function<std::ostream&()> open_series;
};

}  // namespace swarmnet
