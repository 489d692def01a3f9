// Which robots send constant-bit-rate traffic: the same set in every controller instance.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarmnet/ids.hpp"

namespace swarmnet::cbr {

// round(fraction * robot_count) (halves up), capped so that every sender has a destination other
// than itself: at most robot_count - 1 when one robot is the fixed destination (it does not
// send), none when there is a single robot.
std::uint32_t sender_count(double fraction, std::uint32_t robot_count, bool fixed_destination);

// The first `count` robots of a Fisher-Yates shuffle of robot ids 0..robot_count-1 (without
// `excluded`) drawn from RandomStream(shared_seed). Every instance that passes the same arguments
// gets the same senders. O(robot_count).
std::vector<RobotId> choose_senders(std::uint64_t shared_seed, std::uint32_t robot_count,
                                    std::uint32_t count, std::optional<RobotId> excluded);

}  // namespace swarmnet::cbr
