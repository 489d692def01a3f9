// The scenario's world plugins (swarmnet/world.hpp) inside the robot half: their instances, the
// WorldContext they see, and which of them answers a robot's reading or request by name.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "plugin/plugin_choice.hpp"
#include "plugin/plugin_instance.hpp"
#include "plugin/plugin_loader.hpp"
#include "robot/controller_metrics.hpp"
#include "robot/robot_context.hpp"
#include "swarmnet/world.hpp"

namespace swarmnet {

// RobotWorldState::switched_off: asked for during this step, in force from the next.
inline constexpr std::uint8_t kSwitchOffPending = 2;

class WorldPlugins final : public WorldContext {
 public:
  // Creates world `choices[w]` with seed and shared seed derive_seed(seed, {hash_name("world"),
  // w}) and learns its readings and requests. Throws std::invalid_argument when two worlds offer
  // the same name, naming both.
  WorldPlugins(RobotWorldState& state, const std::vector<PluginChoice>& choices, std::uint64_t seed,
               PluginLoader& loader);

  WorldPlugins(const WorldPlugins&) = delete;
  WorldPlugins& operator=(const WorldPlugins&) = delete;
  WorldPlugins(WorldPlugins&&) = delete;
  WorldPlugins& operator=(WorldPlugins&&) = delete;
  ~WorldPlugins() = default;

  // Each calls every world in scenario order.
  void setup();
  void pre_step();
  void post_step();  // then notes the first world whose task is done
  void end();

  // The world whose task_done() ended the run, if one did.
  [[nodiscard]] std::optional<std::string> done_by() const;
  [[nodiscard]] const ControllerMetrics& metrics() const { return metrics_; }

  // Robot `robot`'s reading `name`, valid until the next read(). Throws std::invalid_argument
  // for a name no world offers.
  [[nodiscard]] std::span<const double> read(RobotId robot, std::string_view name);
  // Passes robot `robot`'s request to the world that offers it. Throws std::invalid_argument for
  // a name no world offers, and with the world's name prefixed when the world refuses it.
  void request(RobotId robot, std::string_view name, std::span<const double> args);

  // WorldContext.
  [[nodiscard]] const Arena& arena() const override { return state_.arena; }
  [[nodiscard]] std::size_t robot_count() const override { return state_.bodies.size(); }
  [[nodiscard]] SimTime now() const override { return state_.now; }
  [[nodiscard]] double step_s() const override { return state_.step_s; }
  [[nodiscard]] Vec2 position(RobotId robot) const override { return body(robot).position; }
  [[nodiscard]] double heading_rad(RobotId robot) const override { return body(robot).heading_rad; }
  [[nodiscard]] double max_speed_mps(RobotId robot) const override {
    return body(robot).max_speed_mps;
  }
  [[nodiscard]] bool switched_off(RobotId robot) const override;
  void switch_off(RobotId robot) override;
  void record(std::string_view metric, double value) override;
  void sample(std::string_view series, double value) override;
  void show_object(std::uint32_t id, std::string_view kind, std::string_view state, Vec2 position,
                   double radius_m) override;
  void hide_object(std::uint32_t id) override;

 private:
  // Runs `action` on world `w`; an exception from it is rethrown naming the world and the hook.
  template <typename Hook>
  void call(std::size_t w, const char* hook, Hook&& action);
  // Throws std::out_of_range naming the robot when `robot` is not one.
  [[nodiscard]] const RobotBody& body(RobotId robot) const;
  // The index of the world offering `name` in `owners`; throws naming `what` when none does.
  [[nodiscard]] std::size_t owner(const std::map<std::string, std::size_t, std::less<>>& owners,
                                  std::string_view name, std::string_view what,
                                  RobotId robot) const;

  RobotWorldState& state_;
  std::vector<std::string> names_;  // world w's plugin name
  std::vector<PluginInstance<World>> worlds_;
  std::map<std::string, std::size_t, std::less<>> reading_owners_;
  std::map<std::string, std::size_t, std::less<>> request_owners_;
  std::vector<double> scratch_;
  ControllerMetrics metrics_;
  std::optional<std::size_t> done_by_;
};

}  // namespace swarmnet
