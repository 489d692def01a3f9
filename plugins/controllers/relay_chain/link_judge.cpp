#include "link_judge.hpp"

#include <algorithm>

namespace swarmnet::relay_chain {

const RadioNeighbor* find_neighbor(std::span<const RadioNeighbor> table, RobotId node) {
  const auto it = std::lower_bound(table.begin(), table.end(), node,
                                   [](const RadioNeighbor& n, RobotId id) { return n.id < id; });
  return it != table.end() && it->id == node ? &*it : nullptr;
}

LinkState judge_link(std::span<const RadioNeighbor> table, RobotId node,
                     const LinkCriteria& criteria, double margin_db) {
  const RadioNeighbor* neighbor = find_neighbor(table, node);
  if (neighbor == nullptr) return LinkState::unheard;
  if (neighbor->rssi_smoothed_dbm < criteria.rssi_threshold_dbm + margin_db) return LinkState::weak;
  if (neighbor->unicasts >= criteria.min_exchanges &&
      neighbor->first_attempt_ack_share().value_or(1.0) < criteria.min_first_attempt_share) {
    return LinkState::weak;
  }
  return LinkState::good;
}

}  // namespace swarmnet::relay_chain
