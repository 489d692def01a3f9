// Propagation plugins: received power over one radio link. Models chain like ns-3's loss models:
// the scenario lists them in order (e.g. log_distance, then nakagami) and each receives the
// previous one's output as its input power.
#pragma once

#include <cstdint>

#include "swarmnet/ids.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

struct RadioLink {
  NodeId transmitter = kNoNode;
  NodeId receiver = kNoNode;
  Vec2 tx_position = Vec2::Zero();
  Vec2 rx_position = Vec2::Zero();
  double distance_m = 0.0;
  // Unique per transmission. A random model draws from a stream derived from its seed and
  // (transmitter, receiver, frame_uid), so no draw depends on which other receivers were visited.
  std::uint64_t frame_uid = 0;
};

// Returned for a link that cannot carry any signal (beyond a hard range).
inline constexpr double kNoSignalDbm = -1.0e9;

class Propagation : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::propagation;

  // Power at the receiver, in dBm, for `input_dbm` entering this model.
  [[nodiscard]] virtual double rx_power_dbm(double input_dbm, const RadioLink& link) const = 0;

  // The largest power this model can output at `distance_m` for `input_dbm`, over all its random
  // draws (a random model bounds its strongest fading and documents the bound). Must not increase
  // with distance. The channel uses it to find the distance beyond which no receiver can hear a
  // transmission, and visits only nodes inside it.
  [[nodiscard]] virtual double max_rx_power_dbm(double input_dbm, double distance_m) const = 0;

  // Whether rx_power_dbm may give a link different powers for different frames (it reads
  // link.frame_uid, e.g. to draw fading per frame). When no model in the chain does, the channel
  // computes each transmitter's links once per step (positions do not change within a step) and
  // reuses them for every frame it sends in that step. The default is the safe answer.
  [[nodiscard]] virtual bool varies_per_frame() const { return true; }
};

}  // namespace swarmnet
