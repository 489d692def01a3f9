// The robot half: bodies, their controllers and the physics engine, advanced one step at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plugin/plugin_instance.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_data.hpp"
#include "robot/controller_metrics.hpp"
#include "robot/range_and_bearing_device.hpp"
#include "robot/robot_context.hpp"
#include "robot/robot_settings.hpp"
#include "robot/world_plugins.hpp"
#include "swarmnet/controller.hpp"
#include "swarmnet/physics.hpp"

namespace swarmnet {

class RobotWorld {
 public:
  // Places the robots (robot_placement.hpp), creates the physics engine, the world plugins and
  // one instance of each controller entry per robot, sets up the physics, senses, sets up the
  // worlds (scenario order), and calls every controller's init() (robots in ascending id, each
  // robot's controllers in scenario order) at time 0. Messages sent from init() go out with the
  // first step. Throws what placement, the loader, the physics' setup(), a world's setup() or a
  // controller's init() throws.
  //
  // Streams: placement derive_seed(seed, {hash_name("placement")}); physics seed and shared seed
  // derive_seed(seed, {hash_name("physics")}); world w derive_seed(seed, {hash_name("world"), w});
  // controller entry c on robot r derive_seed(seed, {hash_name("controller"), c, r}), shared
  // derive_seed(seed, {.., c}); the range-and-bearing reading of robot e by robot r in step k
  // derive_seed(seed, {hash_name("range_and_bearing"), r, e, k}).

  RobotWorld(const RobotSettings& settings, PluginLoader& loader);

  RobotWorld(const RobotWorld&) = delete;
  RobotWorld& operator=(const RobotWorld&) = delete;
  RobotWorld(RobotWorld&&) = delete;
  RobotWorld& operator=(RobotWorld&&) = delete;
  ~RobotWorld() = default;

  [[nodiscard]] std::size_t robot_count() const { return state_.bodies.size(); }
  // Steps completed so far; the next step covers [now(), now() + step length).
  [[nodiscard]] std::uint64_t step_index() const { return step_index_; }
  [[nodiscard]] SimTime now() const {
    return step_length_ * static_cast<std::int64_t>(step_index_);
  }
  [[nodiscard]] double step_s() const { return state_.step_s; }
  [[nodiscard]] std::span<const RobotBody> bodies() const { return state_.bodies; }
  // Poses of the arena's movable objects, as the physics engine reports them (empty when there
  // are none).
  [[nodiscard]] std::span<const ObjectPose> object_poses() const {
    return physics_->object_poses();
  }
  // The proximity readings robot `robot`'s controllers see on the next step.
  [[nodiscard]] std::span<const double> proximity(RobotId robot) const;
  // The range-and-bearing readings robot `robot`'s controllers saw in the last step; empty
  // before the first step and without robots.range_and_bearing.
  [[nodiscard]] std::span<const RangeAndBearingReading> range_and_bearing(RobotId robot) const;

  // Runs one step at now(): puts `deliveries` into the receivers' inboxes (keeping their order;
  // a receiver that is not a robot is ignored), senses the range-and-bearing devices when the
  // scenario has them (bodies where the previous step left them, the data set up to the previous
  // step or in init(), the switch-offs that take effect now), runs the worlds' pre_step(), every
  // robot's controllers (robots in ascending id, controllers in scenario order; a switched-off
  // robot's are skipped), steps the physics by step_s(), senses the proximity rings for the next
  // step, advances time and runs the worlds' post_step(). Appends the messages sent during the
  // step to `sent`, ids ascending from a world-wide counter starting at 0.
  void step(std::span<const Delivery> deliveries, std::vector<AppMessage>& sent);

  // The radio neighbour tables the next step's controllers see (StepResult's layout: `counts[r]`
  // entries for robot r, robot after robot); empty `counts`: every table empty. Only with
  // network.neighbors (RobotSettings::neighbor_tables).
  void set_neighbor_tables(std::span<const std::uint32_t> counts,
                           std::span<const RadioNeighbor> entries);

  // The send reports the next step's controllers see (StepResult::send_reports); one for a
  // robot or port no controller entry has is ignored.
  void set_send_reports(std::span<const AddressedSendReport> reports);

  // The answers the next step's controllers see through route_to() (StepResult::routes, in its
  // queries' order); an answer for a robot that is not one is ignored.
  void set_routes(std::span<const RouteAnswer> routes);
  // Moves the route_to() questions asked since the last call into `queries` (StepBatch's
  // order: ascending by robot, then destination).
  void take_route_queries(std::vector<RouteQuery>& queries);

  // True once a world plugin said its task is done: the run ends after the step that did it.
  [[nodiscard]] bool task_done() const { return worlds_->done_by().has_value(); }
  // The world plugin whose task_done() ended the run, if one did.
  [[nodiscard]] std::optional<std::string> done_by() const { return worlds_->done_by(); }
  // Calls every world's end(); once, after the last step.
  void end_worlds() { worlds_->end(); }

  // What controllers record(): pooled over robots, and per robot (robot/robot_metrics.hpp).
  [[nodiscard]] ControllerMetrics controller_metrics() const { return state_.metrics.pooled(); }
  [[nodiscard]] const RobotMetrics& robot_metrics() const { return state_.metrics; }
  [[nodiscard]] std::uint64_t series_rows() const { return state_.series.rows(); }
  // What controllers and worlds asked the viewer to show (robot/view_record.hpp).
  [[nodiscard]] const ViewRecord& view_record() const { return state_.view; }
  [[nodiscard]] const ControllerMetrics& world_metrics() const { return worlds_->metrics(); }

 private:
  // Puts each delivery into its receiver's inbox for the port the message was sent from.
  void fill_inboxes(std::span<const Delivery> deliveries);
  // The index of `port` in state_.ports.
  [[nodiscard]] std::size_t port_index(std::uint16_t port) const;
  // Makes controller entry `entry` the one the contexts speak for (its port and inbox).
  void enter(std::size_t entry);
  void sense();
  // This step's range-and-bearing readings, when the scenario has the device.
  void sense_range_and_bearing();

  RobotWorldState state_;
  SimTime step_length_{};
  std::uint64_t step_index_ = 0;
  PluginInstance<Physics> physics_;
  std::optional<WorldPlugins> worlds_;
  std::optional<RangeAndBearingDevice> range_and_bearing_;
  std::size_t controllers_per_robot_ = 0;
  std::vector<PluginInstance<Controller>> controllers_;  // robot r's entry c at r * per_robot + c
  std::vector<std::uint16_t> entry_ports_;               // controller entry c's port
  std::vector<std::size_t> entry_port_indices_;          // and its index in state_.ports
  std::vector<WorldRobotContext> contexts_;
  std::vector<AppMessage> sent_in_init_;
};

}  // namespace swarmnet
