// Identifiers shared by both halves. Robot i is network node i.
#pragma once

#include <cstdint>
#include <limits>

namespace swarmnet {

using RobotId = std::uint32_t;
using NodeId = std::uint32_t;

// Destination meaning "every robot/node that hears it".
inline constexpr NodeId kBroadcast = std::numeric_limits<NodeId>::max();
inline constexpr NodeId kNoNode = kBroadcast - 1;

// Largest application payload a controller may send in one message, in bytes. It leaves room for
// routing and MAC headers inside an 802.11 MSDU (2304 bytes).
inline constexpr std::uint32_t kMaxPayloadBytes = 2048;

// Messages the swarm may send in one step, per robot in the swarm (so 64 x robots in all): a
// bound the network half checks before it allocates anything for a step's batch.
inline constexpr std::uint32_t kMaxMessagesPerRobotStep = 64;

}  // namespace swarmnet
