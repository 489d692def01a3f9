#include "robot/robot_context.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "robot/range_and_bearing_device.hpp"
#include "robot/world_plugins.hpp"

namespace swarmnet {

namespace {

double clamp_speed(double speed_mps, double max_mps) {
  if (std::isnan(speed_mps)) return 0.0;
  return std::clamp(speed_mps, -max_mps, max_mps);
}

}  // namespace

std::span<const RadioNeighbor> WorldRobotContext::neighbors() const {
  if (!state_->neighbors_enabled) {
    throw std::logic_error(
        "neighbors(): the scenario keeps no neighbour tables (set "
        "network.neighbors.enabled: true; docs/plugins.md)");
  }
  const std::size_t first = state_->neighbor_first[id_];
  return {state_->neighbors.data() + first, state_->neighbor_first[id_ + 1] - first};
}

RangeAndBearingDevice& WorldRobotContext::range_and_bearing_device(const char* call) const {
  if (state_->range_and_bearing == nullptr) {
    throw std::logic_error("robot " + std::to_string(id_) + ": " + call +
                           ": the scenario has no range-and-bearing device (set "
                           "robots.range_and_bearing.enabled: true; docs/plugins.md)");
  }
  return *state_->range_and_bearing;
}

std::span<const RangeAndBearingReading> WorldRobotContext::range_and_bearing() const {
  return range_and_bearing_device("range_and_bearing()").readings(id_);
}

void WorldRobotContext::set_range_and_bearing_data(std::span<const std::byte> data) {
  range_and_bearing_device("set_range_and_bearing_data()").set_data(id_, data);
}

std::span<const double> WorldRobotContext::proximity() const {
  const std::size_t rays = state_->rays_per_robot;
  return {state_->proximity.data() + static_cast<std::size_t>(id_) * rays, rays};
}

void WorldRobotContext::set_wheel_speeds(double left_mps, double right_mps) {
  RobotBody& body = state_->bodies[id_];
  body.left_mps = clamp_speed(left_mps, body.max_speed_mps);
  body.right_mps = clamp_speed(right_mps, body.max_speed_mps);
}

std::span<const SendReport> WorldRobotContext::send_reports() const {
  const std::size_t slot = id_ * state_->ports.size() + state_->current_port_index;
  const auto& slots = state_->send_report_slots;
  const auto [first, last] = std::equal_range(slots.begin(), slots.end(), slot);
  return {state_->send_reports.data() + (first - slots.begin()),
          static_cast<std::size_t>(last - first)};
}

Route WorldRobotContext::route_to(RobotId destination) {
  if (destination >= state_->bodies.size() || destination == id_) {
    throw std::invalid_argument("robot " + std::to_string(id_) + ": route_to(" +
                                std::to_string(destination) + "): ask about another robot, 0 to " +
                                std::to_string(state_->bodies.size() - 1));
  }
  std::vector<RobotId>& asks = state_->route_asks[id_];
  if (std::find(asks.begin(), asks.end(), destination) == asks.end()) {
    if (asks.size() == kMaxRouteQueriesPerRobot) {
      throw std::length_error("robot " + std::to_string(id_) + ": route_to(" +
                              std::to_string(destination) + ") would ask about more than " +
                              std::to_string(kMaxRouteQueriesPerRobot) +
                              " robots in one step (kMaxRouteQueriesPerRobot)");
    }
    asks.push_back(destination);
  }
  const RouteQuery query{id_, destination};
  const auto& routes = state_->routes;
  const auto at =
      std::lower_bound(routes.begin(), routes.end(), query,
                       [](const RouteAnswer& a, const RouteQuery& q) { return a.query < q; });
  if (at == routes.end() || at->query != query) return Route{RouteStatus::pending};
  return at->route;
}

std::uint64_t WorldRobotContext::send(RobotId destination, std::span<const std::byte> payload,
                                      const SendOptions& options) {
  if (payload.size() > kMaxPayloadBytes) {
    throw std::invalid_argument("robot " + std::to_string(id_) + ": cannot send a payload of " +
                                std::to_string(payload.size()) + " bytes; the limit is " +
                                std::to_string(kMaxPayloadBytes) + " bytes (kMaxPayloadBytes)");
  }
  if (destination != kBroadcast && destination >= state_->bodies.size()) {
    throw std::invalid_argument("robot " + std::to_string(id_) + ": cannot send to " +
                                std::to_string(destination) + ": there are " +
                                std::to_string(state_->bodies.size()) +
                                " robots, and it is not kBroadcast either");
  }
  if (state_->outbox == nullptr) {
    throw std::logic_error("robot " + std::to_string(id_) +
                           ": send() called outside init() and control_step()");
  }
  if (state_->outbox->size() >= state_->bodies.size() * std::size_t{kMaxMessagesPerRobotStep}) {
    throw std::length_error(
        "robot " + std::to_string(id_) + ": the swarm already sent " +
        std::to_string(state_->outbox->size()) + " messages in this step, the most it may (" +
        std::to_string(kMaxMessagesPerRobotStep) + " per robot, kMaxMessagesPerRobotStep)");
  }
  const std::uint64_t message_id = state_->next_message_id++;
  state_->outbox->push_back(AppMessage{message_id, id_, destination, state_->current_port,
                                       Payload(payload.begin(), payload.end()), options.hop_limit,
                                       options.report});
  return message_id;
}

std::span<const double> WorldRobotContext::reading(std::string_view name) const {
  if (state_->worlds == nullptr) {
    throw std::invalid_argument("robot " + std::to_string(id_) + ": no world offers the reading '" +
                                std::string(name) + "'");
  }
  return state_->worlds->read(id_, name);
}

void WorldRobotContext::request(std::string_view name, std::span<const double> args) {
  if (state_->worlds == nullptr) {
    throw std::invalid_argument("robot " + std::to_string(id_) + ": no world offers the request '" +
                                std::string(name) + "'");
  }
  state_->worlds->request(id_, name, args);
}

void WorldRobotContext::record(std::string_view metric, double value) {
  state_->metrics.add(id_, metric, value);
}

void WorldRobotContext::sample(std::string_view series, double value) {
  state_->series.sample(state_->now, id_, series, value);
}

void WorldRobotContext::show_state(std::string_view label) {
  state_->view.robot_state(state_->now, id_, label);
}

}  // namespace swarmnet
