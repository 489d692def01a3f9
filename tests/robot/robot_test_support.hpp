// Helpers for the robot-half tests: hand-built settings and plugin instances. (A fake
// RobotContext for driving a controller without a world is in the SDK test kit.)
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "plugin/default_plugin_choice.hpp"
#include "plugin/plugin_loader.hpp"
#include "robot/robot_settings.hpp"
#include "swarmnet/controller.hpp"
#include "swarmnet/physics.hpp"

namespace swarmnet::test {

using Overrides = std::map<std::string, ParamValue>;

inline PluginChoice make_choice(PluginLoader& loader, const std::string& name, PluginKind kind,
                                const Overrides& overrides = {}) {
  PluginChoice choice = default_plugin_choice(loader, name, kind);
  for (const auto& [key, value] : overrides) {
    if (!choice.params.contains(key)) throw std::logic_error("test sets undeclared " + key);
    choice.params.set(key, value);
  }
  choice.where = SourceLocation{"test"};
  return choice;
}

// Robot settings with `count` robots over the whole `width_m` x `height_m` arena, kinematic2d
// physics and no controllers.
inline RobotSettings make_settings(PluginLoader& loader, std::uint32_t count, double width_m,
                                   double height_m, std::uint64_t seed = 1) {
  RobotSettings settings;
  settings.seed = seed;
  settings.step_s = 0.1;
  settings.arena.width_m = width_m;
  settings.arena.height_m = height_m;
  settings.robots.count = count;
  settings.robots.placement = Rect{0.0, 0.0, width_m, height_m};
  settings.robots.proximity = ProximityConfig{24, 1.0};
  settings.physics = make_choice(loader, "kinematic2d", PluginKind::physics);
  return settings;
}

inline PluginInstance<Physics> make_physics(PluginLoader& loader, const Overrides& overrides = {}) {
  PluginArgs args;
  args.params = make_choice(loader, "kinematic2d", PluginKind::physics, overrides).params;
  return loader.create<Physics>("kinematic2d", args);
}

inline RobotBody make_body(double x, double y, double heading_rad, double radius_m = 0.085) {
  RobotBody body;
  body.position = Vec2(x, y);
  body.heading_rad = heading_rad;
  body.radius_m = radius_m;
  body.axle_m = 0.14;
  body.max_speed_mps = 10.0;
  return body;
}

}  // namespace swarmnet::test
