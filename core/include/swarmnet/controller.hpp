// Controller plugins: a robot's behaviour. One instance per robot per controller entry; on each
// step a robot's controllers run in the scenario's order.
//
// A controller sees only its RobotContext: its own sensors and actuators, never the world.
//
// Ports: every controller entry of a scenario has a port (robots.controllers[i].port, by default
// its index i), as a UDP application has one. A controller's send() goes to that port on the
// destination robots, and its inbox() holds only the messages sent to its port, so controllers
// on one robot do not see each other's traffic unless the scenario gives them one port.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/radio_neighbor.hpp"
#include "swarmnet/range_and_bearing.hpp"
#include "swarmnet/route.hpp"
#include "swarmnet/send_report.hpp"
#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

// A message the network delivered to this robot.
struct ReceivedMessage {
  std::uint64_t message_id = 0;
  RobotId source = kNoNode;
  RobotId destination = kNoNode;  // this robot, or kBroadcast
  SimTime sent_at{};              // when the network took it in
  SimTime delivered_at{};
  std::uint32_t hops = 0;
  std::vector<std::byte> payload;
};

class RobotContext {
 public:
  // Sensors.
  [[nodiscard]] virtual RobotId id() const = 0;
  [[nodiscard]] virtual std::size_t robot_count() const = 0;
  [[nodiscard]] virtual SimTime now() const = 0;
  [[nodiscard]] virtual double step_s() const = 0;
  [[nodiscard]] virtual Vec2 position() const = 0;
  [[nodiscard]] virtual double heading_rad() const = 0;
  [[nodiscard]] virtual double max_speed_mps() const = 0;
  // Distance between the wheels: a turn rate w needs wheel speeds v -/+ w * axle_m() / 2.
  [[nodiscard]] virtual double axle_m() const = 0;
  // The walled arena (size and obstacles), in metres.
  [[nodiscard]] virtual const Arena& arena() const = 0;
  // Proximity ring: distances in metres, ray k at heading + 2*pi*k/size(); range when clear.
  [[nodiscard]] virtual std::span<const double> proximity() const = 0;
  [[nodiscard]] virtual double proximity_range_m() const = 0;
  // This controller's port (see the top of this file).
  [[nodiscard]] virtual std::uint16_t port() const = 0;
  // Messages delivered to this robot's port() since its previous step, in delivery order.
  [[nodiscard]] virtual std::span<const ReceivedMessage> inbox() const = 0;
  // Radio neighbours (swarmnet/radio_neighbor.hpp): the nodes this robot's radio decoded a frame
  // from within the scenario's window (network.neighbors.window_s) before the end of the network
  // window whose deliveries inbox() holds, ascending by id, at most max_per_robot of them (the
  // most recently heard). Throws std::logic_error unless the scenario sets
  // network.neighbors.enabled: true (the network half keeps no tables otherwise).
  [[nodiscard]] virtual std::span<const RadioNeighbor> neighbors() const = 0;
  // Reports on this robot's messages sent from port() with SendOptions::report, each once, when
  // its outcome happened in the network window whose deliveries inbox() holds (so with the
  // inbox's delay), in the order the outcomes happened. A message still queued at the end of
  // the run gets none.
  [[nodiscard]] virtual std::span<const SendReport> send_reports() const = 0;
  // What this robot's routing protocol knew of the way to robot `destination` at the end of the
  // network window whose deliveries inbox() holds (swarmnet/route.hpp): valid with next hop and
  // hops, none, or not_tracked (flooding keeps no routes). Asking is what makes the network half
  // answer: the first call for a destination returns pending, and a controller that asks every
  // step gets an answer from the next step on (two steps under sync: pipelined). Up to
  // kMaxRouteQueriesPerRobot destinations per robot and step (std::length_error beyond);
  // std::invalid_argument for this robot's own id or one that is not a robot.
  [[nodiscard]] virtual Route route_to(RobotId destination) = 0;
  // A reading that one of the scenario's world plugins offers this robot (swarmnet/world.hpp),
  // laid out as that plugin documents. Valid until the next call of reading() by any controller
  // (copy what you keep). Throws
  // std::invalid_argument for a name no world of the scenario offers.
  [[nodiscard]] virtual std::span<const double> reading(std::string_view name) const = 0;
  // The range-and-bearing receiver (swarmnet/range_and_bearing.hpp), a line-of-sight device of
  // the robot half, not the radio: one reading for each robot whose emitter it saw at the start
  // of this step, with the bodies where the previous step's physics left them: a robot within
  // robots.range_and_bearing.range_m, centre to centre, with no obstacle, movable object or
  // other robot's disc across the line between the two centres, and whose reading was not lost
  // (loss_probability). A robot a world switched off neither emits nor receives, but its body
  // still blocks. Ascending by robot id; each reading carries the data that robot had set by its
  // previous step (data set in step k is read by the others in step k+1; data set in init() is
  // read in the first step). Valid until this step ends. Throws std::logic_error unless the
  // scenario sets robots.range_and_bearing.enabled: true.
  [[nodiscard]] virtual std::span<const RangeAndBearingReading> range_and_bearing() const = 0;

  // Actuators. Wheel speeds are clamped to +/- max_speed_mps().
  virtual void set_wheel_speeds(double left_mps, double right_mps) = 0;
  // Sends a message to port() on one robot, or on every robot (kBroadcast). Returns its message
  // id. `options` (swarmnet/send_report.hpp) may limit its hops (1: radio neighbours only) and
  // ask for its SendReport. A payload larger than kMaxPayloadBytes is refused with
  // std::invalid_argument; a message beyond the swarm's kMaxMessagesPerRobotStep x robots in one
  // step with std::length_error.
  virtual std::uint64_t send(RobotId destination, std::span<const std::byte> payload,
                             const SendOptions& options) = 0;
  std::uint64_t send(RobotId destination, std::span<const std::byte> payload) {
    return send(destination, payload, SendOptions{});
  }

  // What this robot's range-and-bearing emitter carries from now on, until set again (zeros
  // before the first call): the others read it from the next step on. At most
  // robots.range_and_bearing.data_bytes bytes (std::invalid_argument beyond, naming both sizes);
  // shorter data is zero-padded to exactly that size. Throws std::logic_error unless the
  // scenario enables the device.
  virtual void set_range_and_bearing_data(std::span<const std::byte> data) = 0;

  // Asks the world plugin that offers request `name` for it (swarmnet/world.hpp). Throws
  // std::invalid_argument for a name no world offers, or arguments the world refuses.
  virtual void request(std::string_view name, std::span<const double> args) = 0;

  // Adds one observation of a named metric: summary.json reports its count, sum, mean, min and
  // max over all robots, robot_metrics.csv the same per robot.
  virtual void record(std::string_view metric, double value) = 0;
  // Adds the value of time series `series` for this robot at now(): one row of series.csv
  // (time, robot, series, value), which `swarmnet plot` and the viewer's chart read. Throws
  // std::invalid_argument for an empty name, a name with a line break, or a value that is
  // not finite.
  virtual void sample(std::string_view series, double value) = 0;

  // For the viewer (`swarmnet view`, docs/viewer.md): this robot's state now, as a short label
  // such as "exploring" ("" for none). Call it every step or only on a change: the run records
  // a change only, with its time, in view_states.csv. The viewer gives each label a colour of
  // its own and a legend; commas and line breaks in a label become '_'.
  virtual void show_state(std::string_view label) = 0;

 protected:
  ~RobotContext() = default;
};

class Controller : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::controller;

  // Called once before the first step.
  virtual void init(RobotContext& /*robot*/) {}
  virtual void control_step(RobotContext& robot) = 0;
  // Returns to the state right after init().
  virtual void reset() {}
};

}  // namespace swarmnet
