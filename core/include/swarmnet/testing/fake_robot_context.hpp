// SDK test kit: a RobotContext whose sensors the test sets and whose actuators it reads, for
// driving a controller plugin without a world.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
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
  struct RangeAndBearingData {
    std::vector<std::byte> data;  // zero-padded to range_and_bearing_data_bytes, as emitted
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
  // The range-and-bearing device (swarmnet/range_and_bearing.hpp): what range_and_bearing()
  // returns, ascending by robot id as the kernel gives it (see_by_range_and_bearing() adds one
  // with data the fake keeps; a test may also fill it with spans over bytes it keeps itself).
  // With range_and_bearing_enabled false both calls refuse as the kernel does without the key;
  // set_range_and_bearing_data() refuses more than range_and_bearing_data_bytes.
  std::vector<RangeAndBearingReading> range_and_bearing_readings;
  bool range_and_bearing_enabled = true;
  std::uint32_t range_and_bearing_data_bytes = 10;  // a foot-bot's
  // World readings by name, as a world plugin would offer them (swarmnet/world.hpp).
  std::map<std::string, std::vector<double>, std::less<>> readings;
  // Requests the world offers; when not empty, request() refuses any other name, as the kernel
  // does (a typo in a rarely taken branch shows in the test, not deep in a sweep).
  std::set<std::string, std::less<>> offered_requests;
  // Actuators: read by the test.
  double left_mps = 0.0;
  double right_mps = 0.0;
  std::vector<Sent> sent;
  std::vector<Request> requests;                            // in the order made
  std::vector<RobotId> route_asks;                          // route_to() calls
  std::vector<RangeAndBearingData> range_and_bearing_data;  // set_range_and_bearing_data() calls
  RecordedMetrics recorded;                                 // metric -> observations
  SampledSeries sampled;    // sample() calls by series name, with the time of each
  std::string shown_state;  // the last show_state()

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
  [[nodiscard]] std::span<const RangeAndBearingReading> range_and_bearing() const override {
    refuse_unless_range_and_bearing("range_and_bearing()");
    return range_and_bearing_readings;
  }
  void set_range_and_bearing_data(std::span<const std::byte> data) override {
    refuse_unless_range_and_bearing("set_range_and_bearing_data()");
    if (data.size() > range_and_bearing_data_bytes) {
      throw std::invalid_argument("set_range_and_bearing_data(): " + std::to_string(data.size()) +
                                  " bytes is more than data_bytes, " +
                                  std::to_string(range_and_bearing_data_bytes));
    }
    std::vector<std::byte> padded(range_and_bearing_data_bytes, std::byte{0});
    std::copy(data.begin(), data.end(), padded.begin());
    range_and_bearing_data.push_back({std::move(padded), time});
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

  // Adds a reading of robot `robot` where the id order puts it, carrying `data` zero-padded to
  // range_and_bearing_data_bytes (the fake keeps the bytes).
  void see_by_range_and_bearing(RobotId robot, double range_m, double bearing_rad,
                                std::span<const std::byte> data = {}) {
    std::vector<std::byte>& kept =
        kept_range_and_bearing_data_.emplace_back(range_and_bearing_data_bytes, std::byte{0});
    std::copy_n(data.begin(), std::min<std::size_t>(data.size(), kept.size()), kept.begin());
    const auto at = std::lower_bound(
        range_and_bearing_readings.begin(), range_and_bearing_readings.end(), robot,
        [](const RangeAndBearingReading& r, RobotId id) { return r.robot < id; });
    range_and_bearing_readings.insert(at,
                                      RangeAndBearingReading{robot, range_m, bearing_rad, kept});
  }

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

 private:
  void refuse_unless_range_and_bearing(const char* call) const {
    if (!range_and_bearing_enabled) {
      throw std::logic_error(std::string(call) +
                             ": the scenario has no range-and-bearing device "
                             "(set robots.range_and_bearing.enabled: true)");
    }
  }

  std::deque<std::vector<std::byte>> kept_range_and_bearing_data_;  // stays put as it grows
};

}  // namespace swarmnet::testing
