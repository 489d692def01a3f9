// Whether a radio link is good enough to hold a chain, judged from what this robot's own radio
// measured (RobotContext::neighbors()): the upstream robot is in the table, its smoothed RSSI is
// at least a threshold, and where the MAC ended enough unicast exchanges with it, enough of them
// were acknowledged at the first attempt.
#pragma once

#include <cstdint>
#include <span>

#include "swarmnet/radio_neighbor.hpp"

namespace swarmnet::relay_chain {

struct LinkCriteria {
  double rssi_threshold_dbm = -85.0;
  double min_first_attempt_share = 0.5;  // with at least min_exchanges exchanges
  std::uint32_t min_exchanges = 4;
};

enum class LinkState : std::uint8_t {
  unheard,  // not in the table: nothing decoded from it within the window
  weak,     // heard, below the threshold, or too few first-attempt acknowledgements
  good,
};

// The entry for `node` in `table` (ascending by id), or nullptr.
[[nodiscard]] const RadioNeighbor* find_neighbor(std::span<const RadioNeighbor> table,
                                                 RobotId node);

// `margin_db` raises the RSSI threshold (hysteresis: a link is good again only with margin).
[[nodiscard]] LinkState judge_link(std::span<const RadioNeighbor> table, RobotId node,
                                   const LinkCriteria& criteria, double margin_db = 0.0);

}  // namespace swarmnet::relay_chain
