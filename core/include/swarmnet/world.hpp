// World plugins: the state of a task that belongs to neither the physics nor a robot's
// controller (events to service, batteries, a charging place), as ARGoS's loop functions hold it.
//
// A scenario lists any number of them under `world:`; one instance each, for the whole swarm.
// Every step, in the robot half:
//
//   1. pre_step()  for every world, in scenario order, at time t, robots at their poses at t;
//   2. every robot's controllers at t (a robot a world switched off is skipped and stands still);
//      a controller takes a world's readings and makes requests through its RobotContext;
//   3. the physics moves the bodies to t + dt;
//   4. post_step() for every world, in scenario order, at time t + dt, robots at their new poses;
//   5. when a world's task_done() says so, the run ends after this step.
//
// After the last step, however the run ended (task done or duration_s reached), end() once.
//
// A world shows itself to robots only through named readings (numbers whose layout the plugin
// documents, e.g. "battery" = [fraction]) and takes only named requests (e.g. "join" = [event]):
// a controller never reaches into the world, as an ARGoS controller sees loop functions only
// through a sensor. Reading and request names are unique across the scenario's worlds.
//
// Deterministic like every plugin: draws only from the streams of its PluginArgs, iterates
// nothing unordered, reads no clock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

// What a world plugin sees of the whole world, and what it may do to it.
class WorldContext {
 public:
  [[nodiscard]] virtual const Arena& arena() const = 0;
  [[nodiscard]] virtual std::size_t robot_count() const = 0;
  // pre_step: the step's start; post_step: its end (see the top of this file).
  [[nodiscard]] virtual SimTime now() const = 0;
  [[nodiscard]] virtual double step_s() const = 0;
  [[nodiscard]] virtual Vec2 position(RobotId robot) const = 0;
  [[nodiscard]] virtual double heading_rad(RobotId robot) const = 0;
  [[nodiscard]] virtual double max_speed_mps(RobotId robot) const = 0;
  [[nodiscard]] virtual bool switched_off(RobotId robot) const = 0;

  // From the next step on (whichever hook or request asked), `robot`'s controllers no longer run
  // and its wheels stay still (a flat battery); this step it moves as commanded. Its network
  // node is untouched: the radio keeps relaying.
  virtual void switch_off(RobotId robot) = 0;
  // Adds one observation of a named metric; summary.json reports count, sum, mean, min and max
  // under "world", beside the controllers' metrics.
  virtual void record(std::string_view metric, double value) = 0;
  // Adds the value of time series `series` at now(): a row of series.csv with no robot (see
  // RobotContext::sample). Throws std::invalid_argument for an empty name, a name with a line
  // break, or a value that is not finite.
  virtual void sample(std::string_view series, double value) = 0;

  // For the viewer (`swarmnet view`, docs/viewer.md): a thing of the task to draw, e.g. an
  // event or a charger, as a disc of `radius_m` at `position`. `id` is the world's own (unique
  // across the scenario's worlds), `kind` what it is ("event", "charger") and `state` how it is
  // now ("unserviced"); the viewer colours each state and labels the disc with kind and id. Call
  // it every step or only on a change: the run records a change only, with its time, in
  // view_states.csv. hide_object() removes it from the drawing from now on.
  virtual void show_object(std::uint32_t id, std::string_view kind, std::string_view state,
                           Vec2 position, double radius_m) = 0;
  virtual void hide_object(std::uint32_t id) = 0;

 protected:
  ~WorldContext() = default;
};

class World : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::world;

  // The readings and requests this world offers robots, by name; asked once, after creation.
  [[nodiscard]] virtual std::vector<std::string> readings() const { return {}; }
  [[nodiscard]] virtual std::vector<std::string> requests() const { return {}; }

  // Called once, after the robots are placed and before any controller's init().
  virtual void setup(WorldContext& /*world*/) {}
  virtual void pre_step(WorldContext& /*world*/) {}
  virtual void post_step(WorldContext& /*world*/) {}
  // Once, after the last step: the place to record per-run metrics.
  virtual void end(WorldContext& /*world*/) {}

  // Robot `robot`'s reading `name` (one of readings()), appended to `out`, which is empty.
  virtual void read(const WorldContext& /*world*/, RobotId /*robot*/, std::string_view /*name*/,
                    std::vector<double>& /*out*/) const {}
  // Robot `robot` asks for `name` (one of requests()) with `args`. Throws std::invalid_argument
  // for arguments the request's documentation does not allow; the run then stops with that
  // message.
  virtual void request(WorldContext& /*world*/, RobotId /*robot*/, std::string_view /*name*/,
                       std::span<const double> /*args*/) {}

  // True once the task is done: the run ends after the current step (a run's duration_s is then
  // only a cap). Read after post_step().
  [[nodiscard]] virtual bool task_done() const { return false; }
};

}  // namespace swarmnet
