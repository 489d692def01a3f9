#include "scenario/scenario.hpp"

#include <cmath>

namespace swarmnet {

std::uint64_t Scenario::step_count() const {
  // load_scenario() guarantees duration_s is a whole number of steps, within 1e-9 relative.
  if (step_s <= 0.0) return 0;
  return static_cast<std::uint64_t>(std::llround(duration_s / step_s));
}

NetworkSettings Scenario::network_settings() const {
  NetworkSettings settings;
  settings.seed = network.seed.value_or(seed);
  settings.traffic_seed = seed;
  settings.step_s = step_s;
  settings.nodes = robots.count;
  settings.arena = arena;
  settings.network = network;
  return settings;
}

RobotSettings Scenario::robot_settings() const {
  RobotSettings settings;
  settings.seed = seed;
  settings.step_s = step_s;
  settings.arena = arena;
  settings.robots = robots;
  settings.physics = physics;
  settings.worlds = worlds;
  settings.neighbor_tables = network.neighbors.enabled;
  return settings;
}

}  // namespace swarmnet
