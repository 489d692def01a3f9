// What a node's routing protocol knows of the way to another node: whether it holds a valid
// route now, its next hop and its length. A routing plugin answers Routing::route_to(); a
// controller reads the answer through RobotContext::route_to() (docs/plugins.md, "Routes").
#pragma once

#include <cstdint>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

// The most destinations one robot's controllers may ask route_to() about in one step.
inline constexpr std::uint32_t kMaxRouteQueriesPerRobot = 64;

enum class RouteStatus : std::uint8_t {
  pending,      // asked for the first time: the answer comes with the next step's deliveries
  not_tracked,  // the protocol keeps no routes (flooding, or a plugin that does not answer)
  none,         // the protocol holds no valid route to it
  valid,        // a valid route: next_hop and hops are set
};

inline const char* to_string(RouteStatus status) {
  switch (status) {
    case RouteStatus::pending:
      return "pending";
    case RouteStatus::not_tracked:
      return "not_tracked";
    case RouteStatus::none:
      return "none";
    case RouteStatus::valid:
      return "valid";
  }
  return "unknown";
}

struct Route {
  RouteStatus status = RouteStatus::not_tracked;
  NodeId next_hop = kNoNode;  // with valid: the neighbour the route goes through
  std::uint32_t hops = 0;     // with valid: its length (1: the destination is the next hop)
  SimTime as_of{};            // set by the kernel: the instant the answer describes
};

}  // namespace swarmnet
