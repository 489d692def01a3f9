// What a robot's own radio knows of another node: the frames its PHY decoded from it lately.
// The network half fills one table per robot from the frames each node's PHY actually decoded
// (data frames, RTS, overheard unicasts; not ACK or CTS, which name no transmitter on the air)
// and from how its MAC's unicast exchanges with each of them ended, and returns it with the
// step's deliveries, so a controller reads it with the same delay as its inbox (docs/plugins.md,
// "Radio neighbours").
#pragma once

#include <cstdint>
#include <optional>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

// The most neighbours one robot's table may hold (network.neighbors.max_per_robot's range).
inline constexpr std::uint32_t kMaxNeighborsPerRobot = 1024;

struct RadioNeighbor {
  RobotId id = kNoNode;            // the node heard (robot i is node i)
  SimTime last_heard{};            // when its last decoded frame ended
  double rssi_dbm = 0.0;           // received power of that frame
  double rssi_smoothed_dbm = 0.0;  // exponentially smoothed over its frames (rssi_smoothing)
  // Of that frame, as the PHY judged it: the sinr model's SINR over the frame's worst stretch;
  // the threshold model computes none and reports +infinity.
  double sinr_db = 0.0;
  std::uint32_t frames = 0;  // frames decoded from it in the window
  // Unicast exchanges this robot's MAC ended with it in the window, acknowledged or given up,
  // and how many of them were acknowledged at the first attempt. Both 0 under a MAC that learns
  // nothing of its unicasts (Mac::acknowledges_unicasts() false, as ideal_mac).
  std::uint32_t unicasts = 0;
  std::uint32_t first_attempt_acks = 0;

  // The share of those exchanges acknowledged at the first attempt; none without exchanges.
  [[nodiscard]] std::optional<double> first_attempt_ack_share() const {
    if (unicasts == 0) return std::nullopt;
    return static_cast<double>(first_attempt_acks) / static_cast<double>(unicasts);
  }
};

}  // namespace swarmnet
