#include "chain_role.hpp"

#include <stdexcept>
#include <string>

namespace swarmnet::relay_chain {

ChainRole chain_role(RobotId id, std::size_t robots) {
  if (robots < 2) {
    throw std::invalid_argument("relay_chain needs at least 2 robots (a base and a leader), not " +
                                std::to_string(robots));
  }
  if (id >= robots) {
    throw std::invalid_argument("relay_chain: robot " + std::to_string(id) + " is not one of " +
                                std::to_string(robots));
  }
  if (id == 0) return {Role::base, 0, kNoNode};
  const std::size_t relays = robots - 2;
  if (id == 1) {
    return {Role::leader, 0, relays == 0 ? RobotId{0} : static_cast<RobotId>(relays + 1)};
  }
  return {Role::relay, id - 1U, id == 2 ? RobotId{0} : static_cast<RobotId>(id - 1)};
}

}  // namespace swarmnet::relay_chain
