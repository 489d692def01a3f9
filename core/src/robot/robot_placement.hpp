// Initial poses: robots scattered uniformly over a region without touching anything.
#pragma once

#include <cstdint>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/robot_body.hpp"

namespace swarmnet {

// Attempts allowed for one robot before placement gives up.
inline constexpr std::uint32_t kPlacementAttemptsPerRobot = 10000;

// `count` copies of `prototype` with centres uniform in `region` and headings uniform in
// [-pi, pi), by rejection sampling: a candidate is refused when its disc would overlap a robot
// placed before it, reach outside the arena's walls or overlap an obstacle (touching is allowed,
// as in the physics). Robots are placed in id order from RandomStream(seed), so the result is a
// function of the arguments. Placed robots are kept in a uniform grid, so the cost is
// O(count * attempts). Throws std::runtime_error when a robot cannot be placed within
// kPlacementAttemptsPerRobot attempts, saying how many were placed and what to enlarge.
std::vector<RobotBody> place_robots(const Arena& arena, const Rect& region, std::uint32_t count,
                                    const RobotBody& prototype, std::uint64_t seed);

}  // namespace swarmnet
