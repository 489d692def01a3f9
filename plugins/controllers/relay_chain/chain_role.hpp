// Who a robot is in a relay chain, from its id alone: robot 0 is the base, robot 1 the leader,
// robots 2.. the relays in chain order (relay 1 is robot 2). Each robot's upstream is the robot
// on its way to the base: the base for the first relay, the previous relay for the others, and
// the last relay for the leader (the base when there is none).
#pragma once

#include <cstddef>
#include <cstdint>

#include "swarmnet/ids.hpp"

namespace swarmnet::relay_chain {

enum class Role : std::uint8_t { base, leader, relay };

struct ChainRole {
  Role role = Role::base;
  std::size_t relay_index = 0;  // relays: 1 for the first relay (robot 2); 0 otherwise
  RobotId upstream = kNoNode;   // kNoNode for the base
};

// Throws std::invalid_argument when `robots` < 2 (a chain needs a base and a leader) or `id` is
// not one of them.
[[nodiscard]] ChainRole chain_role(RobotId id, std::size_t robots);

}  // namespace swarmnet::relay_chain
