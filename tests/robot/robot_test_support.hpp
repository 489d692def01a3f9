// Helpers for the robot-half tests: hand-built scenarios, plugin instances and a fake
// RobotContext for driving a controller without a world.
#pragma once

#include <cstdint>
#include <map>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "plugin/plugin_loader.hpp"
#include "robot/controller_metrics.hpp"
#include "scenario/default_plugin_choice.hpp"
#include "scenario/scenario.hpp"
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

// A scenario with `count` robots over the whole `width_m` x `height_m` arena, kinematic2d physics
// and no controllers.
inline Scenario make_scenario(PluginLoader& loader, std::uint32_t count, double width_m,
                              double height_m, std::uint64_t seed = 1) {
  Scenario scenario;
  scenario.name = "robot-test";
  scenario.seed = seed;
  scenario.step_s = 0.1;
  scenario.duration_s = 10.0;
  scenario.arena.width_m = width_m;
  scenario.arena.height_m = height_m;
  scenario.robots.count = count;
  scenario.robots.placement = Rect{0.0, 0.0, width_m, height_m};
  scenario.robots.proximity = ProximityConfig{24, 1.0};
  scenario.physics = make_choice(loader, "kinematic2d", PluginKind::physics);
  return scenario;
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

// A RobotContext whose sensors the test sets and whose actuators it reads.
class FakeRobotContext final : public RobotContext {
 public:
  struct Sent {
    RobotId destination;
    std::vector<std::byte> payload;
    SimTime at;
  };

  RobotId robot_id = 0;
  std::size_t robots = 1;
  SimTime time{};
  double step_length_s = 0.1;
  Vec2 pose_position = Vec2::Zero();
  double pose_heading_rad = 0.0;
  double max_speed = 1.0;
  double range_m = 1.0;
  std::vector<double> rays = std::vector<double>(24, 1.0);
  std::vector<ReceivedMessage> received;
  double left_mps = 0.0;
  double right_mps = 0.0;
  std::vector<Sent> sent;
  ControllerMetrics metrics;

  [[nodiscard]] RobotId id() const override { return robot_id; }
  [[nodiscard]] std::size_t robot_count() const override { return robots; }
  [[nodiscard]] SimTime now() const override { return time; }
  [[nodiscard]] double step_s() const override { return step_length_s; }
  [[nodiscard]] Vec2 position() const override { return pose_position; }
  [[nodiscard]] double heading_rad() const override { return pose_heading_rad; }
  [[nodiscard]] double max_speed_mps() const override { return max_speed; }
  [[nodiscard]] std::span<const double> proximity() const override { return rays; }
  [[nodiscard]] double proximity_range_m() const override { return range_m; }
  [[nodiscard]] std::span<const ReceivedMessage> inbox() const override { return received; }
  void set_wheel_speeds(double left, double right) override {
    left_mps = left;
    right_mps = right;
  }
  std::uint64_t send(RobotId destination, std::span<const std::byte> payload) override {
    sent.push_back({destination, {payload.begin(), payload.end()}, time});
    return sent.size() - 1;
  }
  void record(std::string_view metric, double value) override {
    record_metric(metrics, metric, value);
  }

  void clear_rays() { std::fill(rays.begin(), rays.end(), range_m); }
  // Turns the wheels into a heading change over one step, as a differential drive would.
  void advance(double axle_m = 0.14) {
    pose_heading_rad = std::remainder(
        pose_heading_rad + (right_mps - left_mps) / axle_m * step_length_s, 2.0 * std::numbers::pi);
    time += from_seconds(step_length_s);
  }
};

}  // namespace swarmnet::test
