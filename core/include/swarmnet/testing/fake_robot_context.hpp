// SDK test kit: a RobotContext whose sensors the test sets and whose actuators it reads, for
// driving a controller plugin without a world.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "swarmnet/controller.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/testing/metric_log.hpp"

namespace swarmnet::testing {

class FakeRobotContext final : public RobotContext {
 public:
  struct Sent {
    RobotId destination;
    std::vector<std::byte> payload;
    SimTime at;
    SendOptions options;
  };
  struct Request {
    std::string name;
    std::vector<double> args;
    SimTime at;
  };

  // Sensors: set by the test.
  RobotId robot_id = 0;
  std::size_t robots = 1;
  SimTime time{};
  double step_length_s = 0.1;
  Vec2 pose_position = Vec2::Zero();
  double pose_heading_rad = 0.0;
  double max_speed = 1.0;
  double axle = 0.14;  // a foot-bot's
  Arena world{100.0, 100.0, {}};
  std::uint16_t own_port = 0;
  double range_m = 1.0;
  std::vector<double> rays = std::vector<double>(24, 1.0);
  std::vector<ReceivedMessage> received;
  // The radio's neighbour table, as the network half would fill it (ascending ids); with
  // neighbors_enabled false, neighbors() refuses as the kernel does when the scenario has none.
  std::vector<RadioNeighbor> radio_neighbors;
  bool neighbors_enabled = true;
  // What send_reports() returns: the test writes the reports the network half would (message
  // ids as send() returned them: indices into `sent`).
  std::vector<SendReport> reports;
  // What route_to() returns, by destination, as the network half would answer; a destination
  // not in it gets RouteStatus::pending, as on the first ask. route_to() records each ask in
  // `route_asks`.
  std::map<RobotId, Route> routes;
  // World readings by name, as a world plugin would offer them (swarmnet/world.hpp).
  std::map<std::string, std::vector<double>, std::less<>> readings;
  // Requests the world offers; when not empty, request() refuses any other name, as the kernel
  // does (a typo in a rarely taken branch shows in the test, not deep in a sweep).
  std::set<std::string, std::less<>> offered_requests;
  // Actuators: read by the test.
  double left_mps = 0.0;
  double right_mps = 0.0;
  std::vector<Sent> sent;
  std::vector<Request> requests;    // in the order made
  std::vector<RobotId> route_asks;  // route_to() calls
  RecordedMetrics recorded;         // metric -> observations
  SampledSeries sampled;            // sample() calls by series name, with the time of each
  std::string shown_state;          // the last show_state()

  [[nodiscard]] RobotId id() const override { return robot_id; }
  [[nodiscard]] std::size_t robot_count() const override { return robots; }
  [[nodiscard]] SimTime now() const override { return time; }
  [[nodiscard]] double step_s() const override { return step_length_s; }
  [[nodiscard]] Vec2 position() const override { return pose_position; }
  [[nodiscard]] double heading_rad() const override { return pose_heading_rad; }
  [[nodiscard]] double max_speed_mps() const override { return max_speed; }
  [[nodiscard]] double axle_m() const override { return axle; }
  [[nodiscard]] const Arena& arena() const override { return world; }
  [[nodiscard]] std::uint16_t port() const override { return own_port; }
  [[nodiscard]] std::span<const double> proximity() const override { return rays; }
  [[nodiscard]] double proximity_range_m() const override { return range_m; }
  [[nodiscard]] std::span<const ReceivedMessage> inbox() const override { return received; }
  [[nodiscard]] std::span<const RadioNeighbor> neighbors() const override {
    if (!neighbors_enabled) {
      throw std::logic_error(
          "neighbors(): the scenario keeps no neighbour tables "
          "(set network.neighbors.enabled: true)");
    }
    return radio_neighbors;
  }
  [[nodiscard]] std::span<const double> reading(std::string_view name) const override {
    const auto it = readings.find(name);
    if (it == readings.end()) {
      throw std::invalid_argument("no world offers the reading '" + std::string(name) + "'");
    }
    return it->second;
  }
  void request(std::string_view name, std::span<const double> args) override {
    if (!offered_requests.empty() && !offered_requests.contains(name)) {
      throw std::invalid_argument("no world offers the request '" + std::string(name) + "'");
    }
    requests.push_back({std::string(name), {args.begin(), args.end()}, time});
  }
  void set_wheel_speeds(double left, double right) override {
    left_mps = std::clamp(left, -max_speed, max_speed);
    right_mps = std::clamp(right, -max_speed, max_speed);
  }
  using RobotContext::send;
  std::uint64_t send(RobotId destination, std::span<const std::byte> payload,
                     const SendOptions& options) override {
    if (payload.size() > kMaxPayloadBytes) {
      throw std::invalid_argument("payload of " + std::to_string(payload.size()) +
                                  " bytes exceeds kMaxPayloadBytes");
    }
    sent.push_back({destination, {payload.begin(), payload.end()}, time, options});
    return sent.size() - 1;
  }
  [[nodiscard]] std::span<const SendReport> send_reports() const override { return reports; }
  [[nodiscard]] Route route_to(RobotId destination) override {
    if (destination >= robots || destination == robot_id) {
      throw std::invalid_argument("route_to(" + std::to_string(destination) +
                                  "): not another robot");
    }
    route_asks.push_back(destination);
    const auto it = routes.find(destination);
    return it == routes.end() ? Route{RouteStatus::pending} : it->second;
  }
  void record(std::string_view metric, double value) override {
    log_record(recorded, metric, value);
  }
  void sample(std::string_view series, double value) override {
    log_sample(sampled, time, series, value);
  }
  void show_state(std::string_view label) override { shown_state = label; }

  // Every ray clear.
  void clear_rays() { std::fill(rays.begin(), rays.end(), range_m); }
  // One step of a differential drive with axle `axle` under the current wheel speeds: the
  // heading turns, the position moves along the mean heading, the clock advances.
  void advance() {
    const double v = 0.5 * (left_mps + right_mps);
    const double turn = (right_mps - left_mps) / axle * step_length_s;
    const double mid = pose_heading_rad + 0.5 * turn;
    pose_position += Vec2(std::cos(mid), std::sin(mid)) * v * step_length_s;
    pose_heading_rad = std::remainder(pose_heading_rad + turn, 2.0 * std::numbers::pi);
    time += from_seconds(step_length_s);
  }
};

}  // namespace swarmnet::testing
