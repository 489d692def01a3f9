// What crosses between the robot half and the network half once per step (DESIGN.md section 2).
// transport/step_channel encodes these into framed records, straight into the transport's
// buffer, and decodes them from where they arrive; both halves see only these types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/radio_neighbor.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/route.hpp"
#include "swarmnet/send_report.hpp"
#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

// When, inside its step, the network half takes in message `message_id`: a deterministic offset
// in [0, step) so that one step's messages do not all contend at one instant.
inline SimTime injection_offset(std::uint64_t seed, std::uint64_t message_id, SimTime step) {
  const std::uint64_t draw = derive_seed(seed, {hash_name("inject"), message_id});
  return SimTime{static_cast<std::int64_t>(draw % static_cast<std::uint64_t>(step.count()))};
}

// A message a controller sent during a step, stamped by the robot half.
struct AppMessage {
  std::uint64_t message_id = 0;  // unique, ascending in send order
  RobotId source = kNoNode;
  RobotId destination = kBroadcast;
  std::uint16_t port = 0;  // the sending controller's, and so the receiving one's
  Payload payload;
  std::uint8_t hop_limit = 0;  // SendOptions::hop_limit
  bool report = false;         // SendOptions::report: the sender wants its SendReport
};

// A controller of robot `robot` asked what its routing protocol knows of `destination`
// (RobotContext::route_to); the network half answers at the end of the step's window.
struct RouteQuery {
  RobotId robot = kNoNode;
  RobotId destination = kNoNode;

  friend bool operator==(const RouteQuery&, const RouteQuery&) = default;
  friend bool operator<(const RouteQuery& a, const RouteQuery& b) {
    return a.robot != b.robot ? a.robot < b.robot : a.destination < b.destination;
  }
};

// Robot half -> network half: step `step` covers [start, start + step length).
struct StepBatch {
  std::uint64_t step = 0;
  SimTime start{};
  std::vector<Vec2> positions;  // robot i's position at `start`
  std::vector<AppMessage> messages;
  // Ascending by (robot, destination), unique, at most kMaxRouteQueriesPerRobot per robot;
  // empty unless a controller called route_to().
  std::vector<RouteQuery> route_queries;
};

// The answer to one RouteQuery.
struct RouteAnswer {
  RouteQuery query;
  Route route;
};

// Whether a routing protocol may give `route` in a network of `nodes` nodes: not pending (the
// robot half's own status), and a valid route names a node as next hop and at least one hop.
inline bool is_possible_answer(const Route& route, std::size_t nodes) {
  if (route.status == RouteStatus::valid) return route.next_hop < nodes && route.hops > 0;
  return route.status == RouteStatus::not_tracked || route.status == RouteStatus::none;
}

// One application-level delivery: message `message_id` reached robot `receiver`.
struct Delivery {
  std::uint64_t message_id = 0;
  RobotId source = kNoNode;
  RobotId destination = kBroadcast;  // as addressed (the receiver, or kBroadcast)
  RobotId receiver = kNoNode;
  SimTime sent_at{};  // when the network took the message in
  SimTime delivered_at{};
  std::uint32_t hops = 0;
  std::uint16_t port = 0;  // the message's (AppMessage::port)
  Payload payload;
};

// A SendReport and the controller it is for: the port of robot `source` that sent the message.
struct AddressedSendReport {
  RobotId source = kNoNode;
  std::uint16_t port = 0;
  SendReport report;
};

// Network half -> robot half, after simulating a step's window.
struct StepResult {
  std::uint64_t step = 0;
  std::vector<Delivery> deliveries;  // in delivery order
  std::uint64_t events = 0;          // discrete events processed in the window
  // network.neighbors: robot i's table is the neighbor_counts[i] entries after those of robots
  // 0..i-1, ascending by id, as at the window's end. Both empty when the scenario keeps none.
  std::vector<std::uint32_t> neighbor_counts;
  std::vector<RadioNeighbor> neighbors;
  // Reports on messages sent with SendOptions::report whose outcome fell in the window, in the
  // order the outcomes happened.
  std::vector<AddressedSendReport> send_reports;
  // One answer per route query of the step's batch, in the queries' order.
  std::vector<RouteAnswer> routes;
};

}  // namespace swarmnet
