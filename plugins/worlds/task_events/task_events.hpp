// task_events: the world of the RoboNetSim study's task allocation (section VI). Events at random
// places wait to be serviced; each needs `required_robots` robots with its skill together for
// `service_time_s`. Robots have skills, a battery that driving drains, and a charger at the
// arena's centre; servicing an event recharges the robots that did it. The task is done when
// every event is serviced.
//
// The viewer (docs/viewer.md) is shown every event as a disc of service_radius_m in state
// "unserviced", "being serviced" (robots wait there) or "serviced", and the charger (object id =
// events) as a disc of charger_radius_m.
//
// Readings (per robot):
//   battery         [fraction 0..1, low]  low = 1 below low_energy_fraction: go and charge
//   skills          the robot's skill ids, ascending
//   events_in_view  per unserviced event within discover_radius_m, ascending id, 6 numbers:
//                   [id, x_m, y_m, skill, required, waiting]
//   charger         [x_m, y_m, radius_m]
//   joined          [] when the robot has joined no event, else [id, waiting, service_elapsed_s]
// Requests:
//   join  [id]  wait at / service event id (counts while inside service_radius_m); an id that is
//               no event, or a skill the robot lacks, is refused; a serviced event is ignored
//   leave []    stop waiting
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "swarmnet/world.hpp"
#include "task_event.hpp"

namespace swarmnet::task_events {

class TaskEvents final : public World {
 public:
  static PluginInfo info();
  explicit TaskEvents(const PluginArgs& args);

  [[nodiscard]] std::vector<std::string> readings() const override;
  [[nodiscard]] std::vector<std::string> requests() const override;
  void setup(WorldContext& world) override;
  void post_step(WorldContext& world) override;
  void end(WorldContext& world) override;
  void read(const WorldContext& world, RobotId robot, std::string_view name,
            std::vector<double>& out) const override;
  void request(WorldContext& world, RobotId robot, std::string_view name,
               std::span<const double> args) override;
  [[nodiscard]] bool task_done() const override { return remaining_ == 0 && !events_.empty(); }

 private:
  static constexpr std::uint32_t kNoEvent = UINT32_MAX;

  struct RobotState {
    std::vector<std::uint32_t> skills;
    double energy = 1.0;  // fraction of a full battery
    Vec2 last_position = Vec2::Zero();
    double distance_m = 0.0;
    std::uint32_t joined = kNoEvent;
    bool flat = false;  // ran out of energy
  };

  [[nodiscard]] bool has_skill(const RobotState& robot, std::uint32_t skill) const;
  [[nodiscard]] bool at_charger(const Vec2& position) const;
  // For the viewer: every event (id, "event", its state) and the charger (id = events).
  void show(WorldContext& world) const;
  // Battery and distance of every robot over the step just taken.
  void update_energy(WorldContext& world);
  // Waiting counts and service clocks; services events whose time is up.
  void update_events(WorldContext& world);

  // Parameters.
  std::uint32_t event_count_;
  std::uint32_t required_;
  double service_time_s_;
  std::uint32_t skill_types_;
  std::uint32_t skills_per_robot_;
  double discover_radius_m_;
  double service_radius_m_;
  double energy_s_;
  double low_energy_fraction_;
  double charger_radius_m_;
  double charge_time_s_;
  double event_margin_m_;
  std::uint64_t seed_;

  Vec2 charger_ = Vec2::Zero();
  std::vector<TaskEvent> events_;
  std::vector<RobotState> robots_;
  std::uint32_t remaining_ = 0;
};

}  // namespace swarmnet::task_events
