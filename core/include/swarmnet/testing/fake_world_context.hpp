// SDK test kit: a WorldContext whose robots the test places and whose effects it reads, for
// driving a world plugin without a simulation.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "swarmnet/testing/metric_log.hpp"
#include "swarmnet/world.hpp"

namespace swarmnet::testing {

class FakeWorldContext final : public WorldContext {
 public:
  explicit FakeWorldContext(std::size_t robots, Arena arena = Arena{100.0, 100.0, {}})
      : world(std::move(arena)),
        positions(robots, Vec2::Zero()),
        headings(robots, 0.0),
        max_speeds(robots, 1.0),
        off(robots, false) {}

  // The world: set by the test.
  Arena world;
  SimTime time{};
  double step_length_s = 0.1;
  std::vector<Vec2> positions;
  std::vector<double> headings;
  std::vector<double> max_speeds;
  // Effects: read by the test.
  std::vector<bool> off;
  RecordedMetrics recorded;  // metric -> observations
  SampledSeries sampled;     // sample() calls by series name, with the time of each
  // What show_object() last said of each object id; hide_object() removes the entry.
  struct ShownObject {
    std::string kind;
    std::string state;
    Vec2 position;
    double radius_m = 0.0;
  };
  std::map<std::uint32_t, ShownObject> shown;

  [[nodiscard]] const Arena& arena() const override { return world; }
  [[nodiscard]] std::size_t robot_count() const override { return positions.size(); }
  [[nodiscard]] SimTime now() const override { return time; }
  [[nodiscard]] double step_s() const override { return step_length_s; }
  [[nodiscard]] Vec2 position(RobotId robot) const override { return positions.at(robot); }
  [[nodiscard]] double heading_rad(RobotId robot) const override { return headings.at(robot); }
  [[nodiscard]] double max_speed_mps(RobotId robot) const override { return max_speeds.at(robot); }
  [[nodiscard]] bool switched_off(RobotId robot) const override { return off.at(robot); }
  void switch_off(RobotId robot) override { off.at(robot) = true; }
  void record(std::string_view metric, double value) override {
    log_record(recorded, metric, value);
  }
  void sample(std::string_view series, double value) override {
    log_sample(sampled, time, series, value);
  }
  void show_object(std::uint32_t id, std::string_view kind, std::string_view state, Vec2 position,
                   double radius_m) override {
    shown[id] = ShownObject{std::string(kind), std::string(state), position, radius_m};
  }
  void hide_object(std::uint32_t id) override { shown.erase(id); }

  // One step of a world plugin as the kernel runs it: pre_step at now, time advances by one
  // step (the test moves the robots before or after), post_step at the new time.
  void step(World& plugin) {
    plugin.pre_step(*this);
    time += from_seconds(step_length_s);
    plugin.post_step(*this);
  }
};

}  // namespace swarmnet::testing
