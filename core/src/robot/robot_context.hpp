// The robot half's state that controllers reach through RobotContext, and the context itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "protocol/step_data.hpp"
#include "robot/metric_series.hpp"
#include "robot/robot_metrics.hpp"
#include "robot/view_record.hpp"
#include "swarmnet/controller.hpp"
#include "swarmnet/robot_body.hpp"

namespace swarmnet {

class RangeAndBearingDevice;
class WorldPlugins;

// Messages delivered to one port of one robot in the current step. Slots are reused from step to
// step (payload buffers keep their capacity), so filling an inbox does not allocate once warmed up.
struct Inbox {
  std::vector<ReceivedMessage> slots;
  std::size_t size = 0;

  [[nodiscard]] std::span<const ReceivedMessage> messages() const { return {slots.data(), size}; }
};

// Everything the contexts of one RobotWorld share. Owned by the world.
struct RobotWorldState {
  Arena arena;
  std::vector<RobotBody> bodies;
  std::size_t rays_per_robot = 0;
  double proximity_range_m = 0.0;
  std::vector<double> proximity;  // rays_per_robot readings per robot, robot after robot
  // The ports the controller entries use, ascending; robot r's inbox for ports[k] is
  // inboxes[r * ports.size() + k].
  std::vector<std::uint16_t> ports;
  std::vector<Inbox> inboxes;
  // The controller entry running now: its port, and that port's index in `ports`.
  std::uint16_t current_port = 0;
  std::size_t current_port_index = 0;
  SimTime now{};
  double step_s = 0.0;
  std::uint64_t next_message_id = 0;
  std::vector<AppMessage>* outbox = nullptr;  // where send() appends
  RobotMetrics metrics;                       // what controllers record()
  MetricSeries series;                        // what controllers and worlds sample()
  // Robots a world switched off (1): their controllers no longer run (swarmnet/world.hpp). A
  // switch-off asked for during a step is pending (2) until the next step begins.
  std::vector<std::uint8_t> switched_off;
  WorldPlugins* worlds = nullptr;  // answers readings and requests; owned by RobotWorld
  // robots.range_and_bearing: every robot's device; null when the scenario has none. Owned by
  // RobotWorld.
  RangeAndBearingDevice* range_and_bearing = nullptr;
  // network.neighbors: robot r's radio neighbour table is
  // neighbors[neighbor_first[r], neighbor_first[r + 1]); filled from the step's network result.
  bool neighbors_enabled = false;
  std::vector<std::size_t> neighbor_first;  // robots + 1 offsets
  std::vector<RadioNeighbor> neighbors;
  // Send reports for the next step's controllers: send_reports[i] is for the controllers of
  // inbox slot send_report_slots[i] (robot * ports.size() + port index), slots ascending, each
  // slot's reports in the order their outcomes happened.
  std::vector<std::size_t> send_report_slots;
  std::vector<SendReport> send_reports;
  // route_to(): what each robot's controllers asked this step (route_asks[r], in asking order)
  // and the answers to the previous batch's queries, ascending by (robot, destination).
  std::vector<std::vector<RobotId>> route_asks;
  std::vector<RouteAnswer> routes;
  ViewRecord view;  // what controllers and worlds asked the viewer to show
};

// The sensors and actuators of one robot.
class WorldRobotContext final : public RobotContext {
 public:
  WorldRobotContext(RobotWorldState& state, RobotId id) : state_(&state), id_(id) {}

  [[nodiscard]] RobotId id() const override { return id_; }
  [[nodiscard]] std::size_t robot_count() const override { return state_->bodies.size(); }
  [[nodiscard]] SimTime now() const override { return state_->now; }
  [[nodiscard]] double step_s() const override { return state_->step_s; }
  [[nodiscard]] Vec2 position() const override { return body().position; }
  [[nodiscard]] double heading_rad() const override { return body().heading_rad; }
  [[nodiscard]] double max_speed_mps() const override { return body().max_speed_mps; }
  [[nodiscard]] double axle_m() const override { return body().axle_m; }
  [[nodiscard]] const Arena& arena() const override { return state_->arena; }
  [[nodiscard]] std::uint16_t port() const override { return state_->current_port; }
  [[nodiscard]] std::span<const double> proximity() const override;
  [[nodiscard]] double proximity_range_m() const override { return state_->proximity_range_m; }
  [[nodiscard]] std::span<const ReceivedMessage> inbox() const override {
    return state_->inboxes[id_ * state_->ports.size() + state_->current_port_index].messages();
  }
  // Throws std::logic_error when the scenario keeps no neighbour tables.
  [[nodiscard]] std::span<const RadioNeighbor> neighbors() const override;
  [[nodiscard]] std::span<const SendReport> send_reports() const override;
  [[nodiscard]] Route route_to(RobotId destination) override;
  [[nodiscard]] std::span<const double> reading(std::string_view name) const override;
  // Both throw std::logic_error when the scenario has no range-and-bearing device.
  [[nodiscard]] std::span<const RangeAndBearingReading> range_and_bearing() const override;
  void set_range_and_bearing_data(std::span<const std::byte> data) override;

  // Clamps each speed to +/- max_speed_mps; a NaN speed counts as 0 (stopping is the safe
  // reading of a broken command, and a NaN would poison the physics).
  void set_wheel_speeds(double left_mps, double right_mps) override;
  // Throws std::invalid_argument for a payload over kMaxPayloadBytes or a destination that is
  // neither a robot id nor kBroadcast.
  using RobotContext::send;
  std::uint64_t send(RobotId destination, std::span<const std::byte> payload,
                     const SendOptions& options) override;
  void request(std::string_view name, std::span<const double> args) override;
  void record(std::string_view metric, double value) override;
  void sample(std::string_view series, double value) override;
  void show_state(std::string_view label) override;

 private:
  [[nodiscard]] const RobotBody& body() const { return state_->bodies[id_]; }
  // The device, or std::logic_error naming `call` when the scenario has none.
  [[nodiscard]] RangeAndBearingDevice& range_and_bearing_device(const char* call) const;

  RobotWorldState* state_;
  RobotId id_;
};

}  // namespace swarmnet
